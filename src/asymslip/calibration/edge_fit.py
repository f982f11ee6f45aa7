"""The contact edge from nodal pressures: its position a and the multiplier L_I of (4).

Near a contact edge the pressure of an incomplete contact has the expansion

    p(x) = L_I sqrt(a - x) + c (a - x)^(3/2) + O((a - x)^(5/2)),

whose first term is the paper's (4).  Given the nodal pressures of one load (a finite-element
trace), :func:`fit_edge` fits the first two terms to the nodes next to the edge.

How
---
* **a is the only nonlinear parameter.**  At a fixed trial edge a the model is linear in
  (L_I, c), so the residual sum of squares RSS(a) is a least-squares problem in two unknowns,
  solved in closed form for many trial values at once.  RSS(a) is minimised over a bracket of
  a few nodes around the last node in contact by a grid, refined four times (each round
  narrows the bracket to two grid steps around the best point).  Nodes beyond a trial edge are
  kept in the fit with the model value 0 (the clamped model ``sqrt(max(a - x, 0))``), so the
  first node out of contact penalises an edge placed beyond it: it bounds a, as it should.
* **the window is chosen by the data.**  Windows of K = 4, 5, 6, 7, 8, 10, 12, ... nodes ending
  at the edge are fitted.  For each window the error is estimated (below) and the window with
  the smallest relative error of L_I is kept.  Small windows have little truncation error
  and much noise; large ones the reverse.
* **the error** of each window is the sum of
    - the *noise* part: the profile-likelihood interval of a, {a : RSS(a) <= RSS_min +
      kappa^2 s^2}, with s the scatter of the pressures (estimated from the trace, below), and
      the range of L_I over that interval plus kappa times its conditional standard error;
      this is right for the nonlinear parameter a, where a linearised covariance is not (the
      node next to the edge makes dp/da ~ 1/sqrt(a - x) large); or twice the jackknife
      (leave one node out) standard deviation, if larger -- a check on single bad nodes;
    - the *truncation* part: the larger of two estimates of what the neglected terms do: the
      change of a and L_I when the next term, (a - x)^(5/2), is fitted as well, and their
      change to the first window at least twice as wide (the neglected term shifts L_I by
      O(delta^2) and a by O(delta^3) over a window of width delta).  On exact traces the first
      is the true error to a median factor 0.98 (but misses it by 5-30 times in one case of
      twenty); the second is about 2.5 times it and sees the end of the expansion's validity
      (the rounded flat's corner) that the first may not.

  kappa = 4.  Measured on traces of every built-in law (960 fits, three seeds: 20 to 200 nodes
  across the contact, uniform and graded meshes, exact or with 1 % noise -- relative or of the
  peak pressure): the true error never exceeded the reported one (largest ratio 0.77 for a,
  0.84 for L_I); the median ratio is 0.15 (a) and 0.28 (L_I) on exact traces and 0.12-0.15
  with noise: the reported errors are typically 3.5-7 times the true ones on exact traces
  and 7-8 times with noise (before: twice the truncation estimate and four jackknife standard
  deviations, 7-13 times).  With noise most of that is kappa = 4: a true error is a draw, and a
  bound that covers every one of a thousand draws is several times the typical one.
* **the last node in contact is often wrong** in a finite-element result (its element is only
  partly in contact).  The fit is done with and without it; it is kept only when its pressure
  agrees with the fit of the other nodes within that fit's uncertainty, and that uncertainty
  is small beside the node's own pressure (otherwise agreement proves nothing); then the error
  keeps at least the change the node makes.  Left out, it is named in a note.
* **the first node out of contact bounds a.**  If the chosen window, freed of the nodes beyond
  the contact, would put the edge past the first of them, the edge is only known to lie
  between the last node in contact and that node, and the error says so.
* **points interpolated by a path report** (lying on the straight line between their
  neighbours) are recognised and left out: the fit uses the nodes.
* **noise.**  The scatter s of the pressures is estimated from the trace itself: the median
  absolute residual of local quadratics through five consecutive nodes inside the contact
  (away from the edges, where the pressure is not smooth), scaled to a standard deviation.
  For an exact trace it is the local truncation error of those quadratics, so it is never
  zero.  It may also be given.

The trace is taken as the whole contact or the part of it next to the edge: what is needed is
the last node in contact, at least one node beyond it, and enough nodes within half the
contact width of the edge (at least 8: 4 to fit the three parameters with one degree of
freedom to spare, and a window twice as wide to estimate the truncation error).

Runtime needs NumPy only.

Examples
--------
The Hertzian pressure (48) at P = 100, R = E* = 1 on nodes 0.1 apart: by (29) and (31) the
edge is at a = sqrt(400/pi) = 11.2838 with L_I = sqrt(a/2) = 2.3753.

>>> import numpy as np
>>> from asymslip.calibration.edge_fit import fit_edge
>>> a = np.sqrt(400 / np.pi)
>>> x = np.arange(-120, 121) * 0.1
>>> p = 200 / (np.pi * a**2) * np.sqrt(np.maximum(a**2 - x**2, 0))
>>> fit = fit_edge(x, p, "right", P=100.0)
>>> round(fit.x_edge, 3), round(fit.L_I, 3)
(11.284, 2.375)
>>> bool(abs(fit.x_edge - a) <= fit.a_error and abs(fit.L_I - np.sqrt(a / 2)) <= fit.L_I_error)
True
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Literal

import numpy as np
from numpy.typing import NDArray

from ..errors import InputError

FloatArray = NDArray[np.float64]
Side = Literal["right", "left"]

#: Width of the reported error, in standard deviations of the pressure noise.
KAPPA = 4.0
#: The jackknife's standard deviation is widened by this factor (a check on single bad nodes;
#: 4 before, which on exact traces counted the truncation error a second time).
JACKKNIFE_KAPPA = 2.0
#: The truncation error is taken as this many times the larger of the two estimates (the next
#: term, and a window twice as wide).  On exact traces of the built-in laws the next term alone
#: is the true error to a median factor 0.98, the wider window about 2.5 times it; their larger
#: is enough (factor 2 before: the errors were 7-13 times the true ones).
TRUNCATION_SAFETY = 1.0
#: ... and this many times for an FE solution's nodal pressures, which are not samples of the
#: edge expansion: their shortfall in the last element or two (linear elements) biases every
#: window alike, so the comparisons of windows see it only in part (measured: the fitted L_I of
#: the CalculiX model 1-2 % from Hertz's, the windows' spread about 1 %).
TRUNCATION_SAFETY_FE = 2.0
#: The smallest window: three parameters and one degree of freedom to spare.
MIN_WINDOW = 4
#: Windows reach at most this fraction of the contact width from the edge (the comparison
#: windows included): beyond it the edge expansion is not what the fit is about.
MAX_WINDOW_FRACTION = 0.5
#: Windows (the comparison windows included) hold at most this many nodes: a trace finer than
#: that near the edge (a solver's) has more than the fit needs, and the cost grows with it.
MAX_WINDOW_NODES = 240
#: A node is in contact when its pressure exceeds this many noise standard deviations.
CONTACT_THRESHOLD = 3.0
#: Pressure noise is never taken below this fraction of the peak pressure (rounding).
NOISE_FLOOR = 1e-12
#: The last node in contact is checked against the fit of the others only when that fit's
#: uncertainty at the node is below this fraction of the node's pressure.
LAST_NODE_RESOLUTION = 0.25
#: Points whose slope changes by less than this fraction of the peak pressure over the spacing
#: are taken as linearly interpolated between nodes (see :func:`nodal_points`).
COLLINEAR = 1e-6
#: ... and whose bend is below this fraction of the trace's kinks (see :func:`nodal_points`).
FLAT_BEND = 1e-3
_GRID = 48
_ROUNDS = 4
_PROFILE_GRID = 120
_BISECTIONS = 30
# Successive window sizes grow by this factor (at least one node).
_WINDOW_GROWTH = 1.2


@dataclass(frozen=True)
class EdgeFit:
    """One contact edge at one load, fitted to a pressure trace.

    Attributes
    ----------
    side
        ``"right"`` or ``"left"``.
    P
        The normal load of the trace.
    x_edge
        The edge position in the trace's own x coordinate.
    a_error
        Estimated error of ``x_edge`` (and of any distance a measured from a fixed point).
    L_I, L_I_error
        The multiplier of (4), p ~ L_I sqrt(a - x) at the edge, and its estimated error.
    c
        The coefficient of the next term, (a - x)^(3/2), of the chosen fit.
    window
        The x range (trace coordinates) of the nodes in contact that the chosen fit used.
    nodes
        How many nodes in contact it used.
    noise
        The pressure scatter s used for the error (estimated or given).
    last_node_used
        Whether the last node in contact was kept (see the module notes).
    notes
        What the fit had to do or doubt, in words.
    """

    side: Side
    P: float
    x_edge: float
    a_error: float
    L_I: float
    L_I_error: float
    c: float
    window: tuple[float, float]
    nodes: int
    noise: float
    last_node_used: bool
    notes: tuple[str, ...] = field(default=())

    def position(self, origin: float) -> float:
        """The edge's distance from ``origin`` along its outward direction."""
        return self.x_edge - origin if self.side == "right" else origin - self.x_edge


class EdgeFitError(InputError):
    """The trace cannot give this edge; ``node`` is the offending node's index, if any."""

    def __init__(self, rule: str, node: int | None = None) -> None:
        super().__init__("trace", rule)
        self.node = node


# --- the linear part: L_I and c at fixed trial edges -----------------------------------------
def _least_squares(
    D: FloatArray, p: FloatArray
) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray]:
    """(L_I, c, RSS, var factor of L_I) for clamped distances D = max(a - x, 0), last axis nodes.

    Nodes padded with D = 0 and p = 0 add nothing.  Where the 2x2 normal matrix is singular
    (fewer than two nodes inside the trial edge) RSS is +inf.
    """
    b1 = np.sqrt(D)
    b2 = D * b1
    g11 = np.einsum("...i,...i->...", b1, b1)
    g12 = np.einsum("...i,...i->...", b1, b2)
    g22 = np.einsum("...i,...i->...", b2, b2)
    r1 = np.einsum("...i,...i->...", b1, p)
    r2 = np.einsum("...i,...i->...", b2, p)
    det = g11 * g22 - g12 * g12
    regular = det > 1e-12 * g11 * g22
    safe = np.where(regular, det, 1.0)
    L = np.where(regular, (g22 * r1 - g12 * r2) / safe, 0.0)
    c = np.where(regular, (g11 * r2 - g12 * r1) / safe, 0.0)
    rss = np.einsum("...i,...i->...", p, p) - L * r1 - c * r2
    # A pressure: the model sqrt(d) (L + c d) must stay >= 0 over the nodes it fits, else a
    # trial edge far beyond the contact can pass through the zero nodes (a spurious minimum).
    positive = (L > 0) & (L + c * D.max(axis=-1) >= 0)
    rss = np.where(regular & positive, np.maximum(rss, 0.0), np.inf)
    var_L = np.where(regular, g22 / safe, np.inf)
    return L, c, rss, var_L


def _least_squares_next(D: FloatArray, p: FloatArray) -> tuple[FloatArray, FloatArray]:
    """(L_I, RSS) of the fit that carries one more term, (a - x)^(5/2) (truncation check).

    The symmetric 3x3 normal equations are solved by cofactors, elementwise, after scaling
    each basis function to unit norm; RSS is +inf where they are singular (fewer than three
    nodes inside the trial edge).
    """
    root = np.sqrt(D)
    basis = (root, D * root, D * D * root)
    norm = [np.sqrt(np.einsum("...i,...i->...", f, f)) for f in basis]
    norm = [np.where(n > 0, n, 1.0) for n in norm]
    g = [
        [np.einsum("...i,...i->...", basis[i], basis[j]) / (norm[i] * norm[j]) for j in range(3)]
        for i in range(3)
    ]
    r = [np.einsum("...i,...i->...", basis[i], p) / norm[i] for i in range(3)]
    c00 = g[1][1] * g[2][2] - g[1][2] * g[1][2]
    c01 = g[0][2] * g[1][2] - g[0][1] * g[2][2]
    c02 = g[0][1] * g[1][2] - g[0][2] * g[1][1]
    c11 = g[0][0] * g[2][2] - g[0][2] * g[0][2]
    c12 = g[0][2] * g[0][1] - g[0][0] * g[1][2]
    c22 = g[0][0] * g[1][1] - g[0][1] * g[0][1]
    det = g[0][0] * c00 + g[0][1] * c01 + g[0][2] * c02
    regular = det > 1e-13
    safe = np.where(regular, det, 1.0)
    x0 = (c00 * r[0] + c01 * r[1] + c02 * r[2]) / safe
    x1 = (c01 * r[0] + c11 * r[1] + c12 * r[2]) / safe
    x2 = (c02 * r[0] + c12 * r[1] + c22 * r[2]) / safe
    rss = np.einsum("...i,...i->...", p, p) - (x0 * r[0] + x1 * r[1] + x2 * r[2])
    # As for the two-term fit: a pressure, >= 0 at the far end of the window.
    far = D.max(axis=-1)
    L, c, e = x0 / norm[0], x1 / norm[1], x2 / norm[2]
    positive = (L > 0) & (L + c * far + e * far**2 >= 0)
    return np.where(regular, L, 0.0), np.where(regular & positive, np.maximum(rss, 0.0), np.inf)


def _profile(
    x: FloatArray, p: FloatArray, trial: FloatArray, next_term: bool = False
) -> tuple[FloatArray, ...]:
    """L_I, c, RSS and var factor of L_I at each trial edge (trial: (..., m); x, p: (..., n)).

    With ``next_term``, (L_I, RSS) of the fit with the (a - x)^(5/2) term as well.
    """
    D = np.maximum(trial[..., :, None] - x[..., None, :], 0.0)
    if next_term:
        return _least_squares_next(D, p[..., None, :])
    return _least_squares(D, p[..., None, :])


def _minimise(
    x: FloatArray, p: FloatArray, low: float, high: float, next_term: bool = False
) -> FloatArray:
    """The trial edge of least RSS for each row of x, p (padded rows), by refined grids."""
    rows = x.shape[0]
    lo = np.full(rows, low)
    hi = np.full(rows, high)
    fractions = np.linspace(0.0, 1.0, _GRID)
    for _ in range(_ROUNDS):
        trial = lo[:, None] + (hi - lo)[:, None] * fractions
        rss = _profile(x, p, trial, next_term)[-1 if next_term else 2]
        best = trial[np.arange(rows), np.argmin(rss, axis=1)]
        step = (hi - lo) / (_GRID - 1)
        lo, hi = np.maximum(best - step, low), np.minimum(best + step, high)
    return 0.5 * (lo + hi)


def _padded(
    x: FloatArray, p: FloatArray, rows: list[NDArray[np.intp]]
) -> tuple[FloatArray, FloatArray]:
    """Stack ragged node sets; padding nodes sit at +inf with p = 0 (D = 0: no weight)."""
    width = max(index.size for index in rows)
    X = np.full((len(rows), width), np.inf)
    Pv = np.zeros((len(rows), width))
    for row, index in enumerate(rows):
        X[row, : index.size] = x[index]
        Pv[row, : index.size] = p[index]
    return X, Pv


# --- nodes and noise ---------------------------------------------------------------------------
def nodal_points(x: FloatArray, p: FloatArray) -> NDArray[np.bool_]:
    """False at points that lie on the straight line through their two neighbours.

    A finite-element path report may add points between the nodes, interpolated linearly
    (Abaqus: "include intersections"); they are collinear with their neighbours to the
    printed digits, while the nodes are kinks of the piecewise-linear trace.  A point is taken
    as interpolated when its bend (the change of slope across it) is both below
    :data:`COLLINEAR` times the peak pressure over the spacing (6 printed digits give about
    1e-6) and below :data:`FLAT_BEND` times the bends of the trace's kinks (their 90th
    percentile).  The second condition keeps a smooth trace sampled finely: there every point
    bends about as much as its neighbours (by p'' h), however small h makes that, while in a
    path report the interpolated points bend by rounding only, far less than the nodes.  The
    ends are always kept.
    """
    keep = np.ones(x.size, dtype=bool)
    if x.size < 3:
        return keep
    h_left, h_right = x[1:-1] - x[:-2], x[2:] - x[1:-1]
    bend = np.abs((p[2:] - p[1:-1]) / h_right - (p[1:-1] - p[:-2]) / h_left)
    scale = COLLINEAR * max(float(np.max(np.abs(p))), 1e-300) / np.minimum(h_left, h_right)
    kinks = float(np.percentile(bend, 90))
    keep[1:-1] = (bend > scale) | (bend > FLAT_BEND * kinks)
    return keep


def pressure_noise(x: FloatArray, p: FloatArray) -> float:
    """Scatter of p about local quadratics through 5 consecutive nodes inside the contact.

    1.4826 times the median absolute standardised residual at the middle node (a robust
    standard deviation), over the nodes in contact at least two nodes from either end of the
    region where p > 0.  0 when there are fewer than 9 such nodes.
    """
    inside = np.flatnonzero(p > 0)
    if inside.size < 9:
        return 0.0
    centre = inside[2:-2]
    offsets = np.arange(-2, 3)
    index = centre[:, None] + offsets
    index = np.clip(index, 0, x.size - 1)
    dx = x[index] - x[centre][:, None]
    scale = np.max(np.abs(dx), axis=1, keepdims=True)
    V = np.stack([np.ones_like(dx), dx / scale, (dx / scale) ** 2], axis=-1)  # (m, 5, 3)
    gram = np.einsum("mki,mkj->mij", V, V)
    hat_row = np.einsum("mi,mij,mkj->mk", V[:, 2, :], np.linalg.inv(gram), V)  # row of the middle
    residual = p[centre] - np.einsum("mk,mk->m", hat_row, p[index])
    leverage = hat_row[:, 2]
    standardised = residual / np.sqrt(np.maximum(1.0 - leverage, 1e-12))
    return float(1.4826 * np.median(np.abs(standardised)))


# --- windows ---------------------------------------------------------------------------------
@dataclass(frozen=True)
class _WindowFits:
    """Fits of every window ending at one node (arrays over windows)."""

    sizes: NDArray[np.intp]
    reach: FloatArray  # distance from the window's edge node to its innermost node
    rows: list[NDArray[np.intp]]
    a: FloatArray
    L: FloatArray
    c: FloatArray
    noise_a: FloatArray
    noise_L: FloatArray
    next_a: FloatArray  # change of a and L_I when the next term is fitted too
    next_L: FloatArray


def _window_sizes(available: int) -> list[int]:
    sizes, size = [], MIN_WINDOW
    while size <= available:
        sizes.append(size)
        size = max(size + 1, int(round(size * _WINDOW_GROWTH)))
    return sizes


def _fit_windows(
    x: FloatArray,
    p: FloatArray,
    end: int,
    beyond: NDArray[np.intp],
    sizes: list[int],
    low: float,
    high: float,
    noise: float,
) -> _WindowFits:
    rows = [np.concatenate([np.arange(end - size + 1, end + 1), beyond]) for size in sizes]
    X, Pv = _padded(x, p, rows)
    a = _minimise(X, Pv, low, high)
    L, c, _, _ = _profile(X, Pv, a[:, None])
    L, c = L[:, 0], c[:, 0]
    # The same windows with the next term of the expansion: the change estimates the
    # truncation error of the two-term fit directly (with K = 4 the four parameters pass
    # through the four nodes: still an estimate of what the next term does).
    a_next = _minimise(X, Pv, low, high, next_term=True)
    L_next = _profile(X, Pv, a_next[:, None], next_term=True)[0][:, 0]
    noise_a, noise_L = _profile_interval(X, Pv, a, L, low, high, noise)
    reach = x[end] - x[end - np.asarray(sizes) + 1]
    return _WindowFits(
        np.asarray(sizes),
        reach,
        rows,
        a,
        L,
        c,
        noise_a,
        noise_L,
        np.abs(a_next - a),
        np.abs(L_next - L),
    )


def _profile_interval(
    X: FloatArray,
    Pv: FloatArray,
    a: FloatArray,
    L: FloatArray,
    low: float,
    high: float,
    noise: float,
) -> tuple[FloatArray, FloatArray]:
    """Half-width of {t : RSS(t) <= RSS(a) + (kappa s)^2} and the error of L_I over it.

    The interval's ends are found on a grid over the bracket (which sees every dip of RSS),
    then by bisection between the outermost grid point inside and the next one outside.  The
    error of L_I is the largest change of L_I(t) over the interval plus kappa times its
    conditional standard error s sqrt((G^-1)_11).
    """
    rows = a.size
    L_a, _, rss_a, var_a = (v[:, 0] for v in _profile(X, Pv, a[:, None]))
    threshold = rss_a + (KAPPA * noise) ** 2
    trial = np.broadcast_to(np.linspace(low, high, _PROFILE_GRID), (rows, _PROFILE_GRID))
    L_t, _, rss_t, var_t = _profile(X, Pv, trial)
    inside = rss_t <= threshold[:, None]
    step = (high - low) / (_PROFILE_GRID - 1)
    # Outermost grid point inside on each side (a itself if none), and the grid point beyond.
    lower_in = np.where(inside, trial, np.inf).min(axis=1)
    upper_in = np.where(inside, trial, -np.inf).max(axis=1)
    inner = np.stack([np.minimum(lower_in, a), np.maximum(upper_in, a)], axis=1)
    outer = np.clip(inner + np.array([-step, step]), low, high)
    for _ in range(_BISECTIONS):  # both ends at once: inner stays inside, outer outside
        middle = 0.5 * (inner + outer)
        below = _profile(X, Pv, middle)[2] <= threshold[:, None]
        inner, outer = np.where(below, middle, inner), np.where(below, outer, middle)
    ends = [inner[:, 0], inner[:, 1]]
    lower, upper = ends
    noise_a = np.maximum(a - lower, upper - a)
    L_ends = [_profile(X, Pv, end[:, None]) for end in (lower, upper)]
    spread_L = np.maximum.reduce(
        [
            np.where(inside, np.abs(L_t - L[:, None]), 0.0).max(axis=1),
            np.abs(L_ends[0][0][:, 0] - L),
            np.abs(L_ends[1][0][:, 0] - L),
        ]
    )
    var_L = np.maximum.reduce(
        [
            np.where(inside, var_t, 0.0).max(axis=1),
            var_a,
            L_ends[0][3][:, 0],
            L_ends[1][3][:, 0],
        ]
    )
    del L_a
    return noise_a, spread_L + KAPPA * noise * np.sqrt(var_L)


@dataclass(frozen=True)
class _Choice:
    a: float
    L: float
    c: float
    a_error: float
    L_error: float
    row: NDArray[np.intp]
    size: int


def _choose(
    fits: _WindowFits,
    x: FloatArray,
    p: FloatArray,
    low: float,
    high: float,
    safety: float = TRUNCATION_SAFETY,
) -> _Choice:
    """The window of least relative error of L_I; errors = noise + truncation + jackknife."""
    count = fits.sizes.size
    truncation_a = np.full(count, np.inf)
    truncation_L = np.full(count, np.inf)
    for k in range(count):
        wider = np.flatnonzero(fits.reach >= 2 * fits.reach[k])
        if wider.size:
            m = wider[0]
            truncation_a[k] = safety * max(abs(fits.a[m] - fits.a[k]), fits.next_a[k])
            truncation_L[k] = safety * max(abs(fits.L[m] - fits.L[k]), fits.next_L[k])
    error_L = fits.noise_L + truncation_L
    relative = np.where(np.isfinite(error_L), error_L / np.maximum(np.abs(fits.L), 1e-300), np.inf)
    k = int(np.argmin(relative))
    row = fits.rows[k]
    # Jackknife over the nodes in contact of the chosen window.
    contact = row[: fits.sizes[k]]
    left_out = [row[row != node] for node in contact]
    X, Pv = _padded(x, p, left_out)
    a_j = _minimise(X, Pv, low, high)
    L_j = _profile(X, Pv, a_j[:, None])[0][:, 0]
    n = contact.size
    jack_a = np.sqrt((n - 1) / n * np.sum((a_j - a_j.mean()) ** 2))
    jack_L = np.sqrt((n - 1) / n * np.sum((L_j - L_j.mean()) ** 2))
    return _Choice(
        a=float(fits.a[k]),
        L=float(fits.L[k]),
        c=float(fits.c[k]),
        a_error=float(max(fits.noise_a[k], JACKKNIFE_KAPPA * jack_a) + truncation_a[k]),
        L_error=float(max(fits.noise_L[k], JACKKNIFE_KAPPA * jack_L) + truncation_L[k]),
        row=contact,
        size=int(fits.sizes[k]),
    )


# --- the edge ----------------------------------------------------------------------------
def _right_edge(
    x: FloatArray, p: FloatArray, noise: float | None, fe_nodes: bool = False
) -> tuple[_Choice, float, bool, list[str]]:
    """The right-hand edge of a trace with increasing x (the left edge is mirrored first)."""
    peak = float(np.max(p))
    if not peak > 0:
        raise EdgeFitError("no node is in contact (no positive pressure)")
    scatter = pressure_noise(x, p) if noise is None else float(noise)
    scatter = max(scatter, NOISE_FLOOR * peak)
    in_contact = np.flatnonzero(p > CONTACT_THRESHOLD * scatter)
    if in_contact.size == 0:
        raise EdgeFitError("no node is in contact: every pressure is within the noise")
    if in_contact.size == 1:
        raise EdgeFitError(
            "a single node is in contact: an edge needs several nodes in contact next to it",
            int(in_contact[0]),
        )
    first, last = int(in_contact[0]), int(in_contact[-1])
    if last == x.size - 1:
        raise EdgeFitError(
            "the contact reaches the end of the trace: the edge is not in the "
            "data (no node beyond it is out of contact)",
            last,
        )
    width = x[last] - x[first]
    beyond = np.arange(last + 1, min(last + 3, x.size))
    low = x[max(last - 1, first)]
    # The edge lies before the first node out of contact -- or, if noise hid a last node in
    # contact, before the one after it; never more than one spacing beyond the first.
    high = x[last + 1] + (x[last + 1] - x[last])
    if last + 2 < x.size:
        high = min(high, x[last + 2])
    notes: list[str] = []

    def variant(end: int) -> _Choice | None:
        reach = x[end] - x[first : end + 1]
        available = min(int(np.sum(reach <= MAX_WINDOW_FRACTION * width)), MAX_WINDOW_NODES)
        sizes = _window_sizes(available)
        if not sizes:
            return None
        fits = _fit_windows(x, p, end, beyond, sizes, low, high, scatter)
        if not np.any(fits.reach >= 2 * fits.reach[0]):
            return None
        safety = TRUNCATION_SAFETY_FE if fe_nodes else TRUNCATION_SAFETY
        return _choose(fits, x, p, low, high, safety)

    without = variant(last - 1)
    if without is None:
        near = int(np.sum(x[last] - x[first : last + 1] <= MAX_WINDOW_FRACTION * width))
        raise EdgeFitError(
            f"too few nodes near the edge to fit it: {near} nodes in contact lie within half "
            f"the contact width of the edge; at least {2 * MIN_WINDOW} are needed (refine the "
            "mesh there)",
            last,
        )
    with_last = variant(last)
    keep = False
    if with_last is not None:
        # Does the last node agree with the fit of the others?  Its predicted pressure moves
        # by dp/da * a_error and sqrt(a - x) * L_error within that fit's uncertainty.
        distance = max(without.a - x[last], 0.0)
        predicted = without.L * np.sqrt(distance) + without.c * distance**1.5
        band = np.hypot(
            without.L / (2 * np.sqrt(max(distance, 1e-300))) * without.a_error,
            np.sqrt(distance) * without.L_error,
        )
        agrees = abs(p[last] - predicted) <= np.hypot(KAPPA * scatter, band)
        # Agreement means something only when that uncertainty is small beside the node's
        # own pressure; otherwise a wrong last node would pass and pin the edge wrongly.
        decisive = np.hypot(KAPPA * scatter, band) <= LAST_NODE_RESOLUTION * p[last]
        keep = bool(agrees and decisive)
        if agrees and not decisive:
            notes.append(
                f"the last node in contact (x = {x[last]:.6g}) cannot be checked against its "
                "neighbours (their fit is too uncertain there): left out"
            )
        if not agrees:
            notes.append(
                f"the last node in contact (x = {x[last]:.6g}, p = {p[last]:.6g}) disagrees "
                f"with the fit of its neighbours (p = {predicted:.6g} +- {band:.2g}): left out"
            )
    if keep and with_last is not None:
        # The two fits differ by what the last node adds; the error keeps at least that.
        chosen = replace(
            with_last,
            a_error=max(with_last.a_error, abs(with_last.a - without.a)),
            L_error=max(with_last.L_error, abs(with_last.L - without.L)),
        )
    else:
        chosen = without
    # Would the chosen window, without the nodes beyond the contact, put the edge past the
    # first of them?  Then those zeros hold the edge back and the fit cannot place it within
    # the last gap: the error becomes that gap.
    free_high = x[last + 1] + 2 * (x[last + 1] - x[last])
    X, Pv = _padded(x, p, [chosen.row])
    free = float(_minimise(X, Pv, low, free_high)[0])
    if free > x[last + 1]:
        gap = chosen.a - x[last]
        chosen = replace(chosen, a_error=max(chosen.a_error, gap, abs(free - chosen.a)))
        notes.append(
            f"the fit alone would put the edge beyond the first node out of contact (x = "
            f"{x[last + 1]:.6g}); it is placed between the last node in contact and that node"
        )
    # A node with pressure is in contact: the edge is not before it.  A fit that puts it
    # there (an FE trace whose pressure falls short of the square root in the last element)
    # is moved to that node, and keeps its distance from it as error.
    if chosen.a < x[last]:
        shortfall = x[last] - chosen.a
        chosen = replace(chosen, a=float(x[last]), a_error=max(chosen.a_error, shortfall))
        notes.append(
            f"the fit put the edge {shortfall:.3g} before the last node in contact (x = "
            f"{x[last]:.6g}); it is placed at that node"
        )
    if fe_nodes:
        # The FE's resolution: its edge is known to half the node spacing there.
        chosen = replace(chosen, a_error=max(chosen.a_error, 0.5 * (x[last + 1] - x[last])))
    return chosen, scatter, keep, notes


def fit_edge(
    x: FloatArray,
    p: FloatArray,
    side: Side,
    P: float,
    noise: float | None = None,
    *,
    fe_nodes: bool = False,
) -> EdgeFit:
    """Fit one edge of one load's pressure trace.

    Parameters
    ----------
    x, p
        Node positions (strictly increasing) and nodal pressures of one load, as checked by
        :mod:`asymslip.calibration.traces`.
    side
        ``"right"`` (the edge at the largest x) or ``"left"``.
    P
        The load, recorded in the result.
    noise
        The pressure scatter (standard deviation) if known; estimated from the trace if None.
    fe_nodes
        The pressures are an FE solution's nodal values (read from FE results): its contact
        edge is resolved only to the element that holds it, so the error of a is at least half
        the spacing between the last node in contact and the next (linear elements cannot
        follow the square root there; the FE's pressure falls short of it in the last element
        or two); the truncation part of the error is doubled (``TRUNCATION_SAFETY_FE``).

    Raises
    ------
    EdgeFitError
        When the trace cannot give the edge (no contact, one node in contact, the edge outside
        the trace, too few nodes near it); ``node`` names the offending node where there is one.
    """
    x = np.asarray(x, dtype=np.float64)
    p = np.asarray(p, dtype=np.float64)
    # Points a path report interpolated linearly between nodes carry nothing the nodes do not,
    # and next to the edge they follow a straight line, not the square root: fit the nodes.
    nodes = nodal_points(x, p)
    index = np.flatnonzero(nodes)
    if side == "left":
        index = index[::-1]
        xs, ps = -x[index], p[index]
    else:
        xs, ps = x[index], p[index]
    try:
        chosen, scatter, keep, notes = _right_edge(xs, ps, noise, fe_nodes)
    except EdgeFitError as error:
        if error.node is not None:
            error.node = int(index[error.node])
        raise
    dropped = int(np.sum(~nodes & (p != 0)))  # zeros beyond the contact are collinear anyway
    if dropped:
        notes.insert(
            0,
            f"{dropped} points lying on straight lines between their neighbours "
            "(a path report interpolating between nodes) were left out",
        )
    window = (float(xs[chosen.row].min()), float(xs[chosen.row].max()))
    x_edge = chosen.a
    if side == "left":
        window = (-window[1], -window[0])
        x_edge = -x_edge
    return EdgeFit(
        side=side,
        P=float(P),
        x_edge=float(x_edge),
        a_error=chosen.a_error,
        L_I=chosen.L,
        L_I_error=chosen.L_error,
        c=chosen.c,
        window=window,
        nodes=chosen.size,
        noise=scatter,
        last_node_used=bool(keep),
        notes=tuple(notes),
    )
