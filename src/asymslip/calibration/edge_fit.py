"""The contact edge from nodal pressures: its position a and the multiplier L_I of (4).

Near a contact edge the pressure of an incomplete contact has the expansion

    p(x) = L_I sqrt(a - x) + c (a - x)^(3/2) + O((a - x)^(5/2)),

whose first term is the paper's (4).  Given the nodal pressures of one load (a finite-element
trace), :func:`fit_edge` fits the first two terms to the nodes next to the edge.

How
---
* **a is the only nonlinear parameter** (:mod:`.edge_model`).  At a fixed trial edge a the
  model is linear in (L_I, c), so the residual sum of squares RSS(a) is a least-squares problem
  in two unknowns, solved in closed form for many trial values at once, and minimised over a
  bracket of a few nodes around the last node in contact by a grid refined four times.  Nodes
  beyond a trial edge are kept with the model value 0, so the first node out of contact
  bounds a, as it should.
* **the window is chosen by the data.**  Windows of K = 4, 5, 6, 7, 8, 10, 12, ... nodes ending
  at the edge are fitted, each with its error (:mod:`.edge_errors`): a 95 % bound on what the
  pressures' scatter does (the scatter's model estimated from the trace, :mod:`.noise`) plus
  what the neglected terms of the expansion do, estimated from the next term and from nested
  windows (Richardson, at the order the data show).  The window with the smallest relative
  error of L_I is kept: small windows have little truncation error and much scatter, large
  ones the reverse.
* **what the reported error means.**  For exact data (no scatter) it bounds the truncation and
  discretisation error: on the census of every built-in law (tests/calibration/census.py:
  uniform and graded meshes of 20 to 200 nodes, 240 fits) it covers every true error, and the
  true error is typically half of it (median true/reported 0.49).  For data with scatter it
  is a 95 % bound: on the census with 1 % scatter (40 draws per mesh) it covers 94-98 % of
  the true errors, and per mesh the RMS true error is a median 0.42-0.52 of the reported one
  (docs/guide/calibration.md for the distribution).
* **estimate or bound.**  Each fit says which its errors are (:attr:`EdgeFit.error_kind`,
  with a note): a *bound* where the edge can only be placed at the last node in contact or in
  the gap after it, or where the truncation part outweighs the scatter part and rests on
  Richardson's estimate at an order the windows do not show (the nodes next to the edge are
  short of the expansion's asymptotic range: mostly 20- and 35-node meshes of the rounded flat
  punch and the power laws); an *estimate* otherwise.  On the census's exact traces the 200
  estimates of 240 fits lie within a factor of three of the true error (0.36-0.55 for a, all;
  0.33-0.54 for L_I, 99 %), on 400 more 99.1 % and 98.5 %; the bounds cover it but may exceed
  it many times (true/reported down to 0.011).
* **the last node in contact is often wrong** in a finite-element result (its element is only
  partly in contact).  The fit is done with and without it; it is kept only when its pressure
  agrees with the fit of the other nodes within that fit's uncertainty, and that uncertainty
  is small beside the node's own pressure (otherwise agreement proves nothing).  Left out, it
  is named in a note.
* **the first node out of contact bounds a.**  If the chosen window, freed of the nodes beyond
  the contact, would put the edge past the first of them, the edge is only known to lie
  between the last node in contact and that node, and the error says so.
* **points interpolated by a path report** (lying on the straight line between their
  neighbours) are recognised and left out: the fit uses the nodes.

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
from .edge_errors import TRUNCATION_SAFETY, bootstrap_scatter, fit_windows, window_errors
from .edge_errors import window_sizes as _window_sizes
from .edge_model import minimise, padded
from .noise import COVERAGE, NOISE_FLOOR, NoiseModel, estimate_noise

FloatArray = NDArray[np.float64]
Side = Literal["right", "left"]
#: Whether a fit's errors estimate the true ones or only bound them (:attr:`EdgeFit.error_kind`).
ErrorKind = Literal["estimate", "bound"]

#: The smallest window: three parameters and one degree of freedom to spare.
MIN_WINDOW = 4
#: Windows reach at most this fraction of the contact width from the edge (the comparison
#: windows included): beyond it the edge expansion is not what the fit is about.
MAX_WINDOW_FRACTION = 0.5
#: Windows (the comparison windows included) hold at most this many nodes: a trace finer than
#: that near the edge (a solver's) has more than the fit needs, and the cost grows with it.
MAX_WINDOW_NODES = 240
#: A node is in contact when its pressure exceeds this many standard deviations of the
#: scatter at zero pressure.
CONTACT_THRESHOLD = 3.0
#: The last node in contact is checked against the fit of the others only when that fit's
#: uncertainty at the node is below this fraction of the node's pressure.
LAST_NODE_RESOLUTION = 0.25
#: Points whose slope changes by less than this fraction of the peak pressure over the spacing
#: are taken as linearly interpolated between nodes (see :func:`nodal_points`).
COLLINEAR = 1e-6
#: ... and whose bend is below this fraction of the trace's kinks (see :func:`nodal_points`).
FLAT_BEND = 1e-3
#: An FE solution's nodal pressures differ from the continuum's by the FE's discretisation
#: error, which the fit cannot see in one mesh (it is smooth, neither scatter nor truncation).
#: The errors of a get an allowance in element sizes h at the edge that depends on where the
#: fit put the edge -- the rule printed with the result:
#:
#: * between the last node in contact and the first node out (the fit stands): FE_ALLOWANCE_A
#:   element, in quadrature with the fit's own error.  There the FE's pressures put the fitted
#:   edge inside the FE's own edge, by 0.055-0.165 element (every such fit measured): by
#:   0.074-0.165 where the edge falls a quarter to a half of the way to the next node, by
#:   0.055-0.064 beyond half of it (a trend, too loose for a rule of its own);
#: * moved to the last node in contact (the fit put it before that node, which carries
#:   pressure): the larger of the fit's own error -- which then holds the distance it was
#:   moved -- and FE_ALLOWANCE_A_AT_NODE element.  The FE's edge lies within 0.04-0.19 element
#:   of that node, on either side, and the distance moved is a measure of it (0.02-0.24).
#:
#: L_I gets :func:`fe_allowance_L` times h/a of L_I (a half the contact width), in
#: quadrature: FE_ALLOWANCE_L less FE_ALLOWANCE_L_SLOPE times the fraction f (0 to 1) of the
#: last gap at which the fit put the edge (f = 0 for a fit moved to the last node).  L_I's FE
#: error follows a's: a fit whose edge lies inside the FE's edge makes up for it with a larger
#: L_I (over the 75 fits that stand on the twelve runs below, the errors correlate at -0.90,
#: 2.6 h/a per element), and the edge lies further inside where f is small -- L_I's error in
#: h/a falls from 0.39-0.54 at f = 0.2-0.3 to 0.13-0.24 at f = 0.5-0.6 (0.41 - 0.30 f by least
#: squares, scatter 0.07).  Set on the twelve runs below (96 fits): every error covered (at
#: most 0.91), 91 within a factor of three (84 with a fixed 0.6 h/a, which 12 runs before
#: were set with); on three runs not used to set it (21 elements; 26 with tension; 19 with the
#: cycle P 1000 -> 1180, Q -120 -> 260; 24 fits): every error covered (at most 0.98, thinly),
#: 21 within a factor of three (19 with 0.6 h/a; the others an FE L_I error of 0.073 h/a, a
#: quarter of the usual, at f = 0.67 on both edges, and 0.33 at f = 0.52).
#: Measured on the project's CalculiX model (asymslip.fe) against the FE model's own contact:
#: Hertz's a (29) about the FE contact's resultant (under Q the FE cylinder bends and its
#: contact moves sideways by up to 0.1 element, a tilted Hertz contact;
#: tests/fe/test_fe_model.py), and Hertz's L_I (31).  Set on seven runs (15, 20, 25, 30
#: elements per a(P2), with and without tension; the tutorial's 16 elements, another cycle),
#: 56 fits: every error covered (true/reported at most 0.96), 53 within a factor of three
#: (0.31, 0.31, 0.32 the others); the fixed 0.2 element before covered them too, but only 44
#: of the 56 within a factor of three.  Checked on three runs not used to set it (22 elements;
#: 27 with tension; 24 with the tutorial's cycle P 1000 -> 1200, Q -150 -> 350), 24 fits:
#: every error covered (at most 0.97: thinly) and all 24 within a factor of three; and on two
#: more run after (18 elements with the cycle P 1000 -> 1150, Q -100 -> 200; 33 elements), 16
#: fits: every error covered (at most 0.85), 15 within a factor of three (the other 0.31: an
#: FE edge 0.03 element from the node the fit was moved to, below a third of 0.1); on three
#: more (those of the L_I rule below), 20 of 24 (the others an FE edge 0.01 element from the
#: node the fit was moved to, and an FE error of 0.03 element at f = 0.67: 0.10 and 0.19).
#: L_I is above Hertz's by 0.07-0.62 h/a over fifteen runs, on every mesh alike (O(h)).
#: Estimates from the data were measured against the same reference and rejected: the misfit
#: of the last node in contact (the change of a when it is fitted too: 0.01-0.24 h,
#: uncorrelated with the error); Richardson between meshes of 30 and 15 elements (twice the
#: change of a: covers 15 of 16 fits, misses one by 1.5 times -- the error depends on where
#: the edge falls between nodes, which differs between the meshes); and the FE's nodal
#: pressures read as averages of the continuum's over each node's share of the surface (the
#: edge's error of such averages is 0.03 element inwards or 0.2-0.5 outwards, unlike the
#: FE's).  A user's model may differ: the note printed with the result says so.
FE_ALLOWANCE_A = 0.17
FE_ALLOWANCE_A_AT_NODE = 0.1
FE_ALLOWANCE_L = 0.62
#: How fast the FE allowance of L_I falls (in h/a of L_I) as the fitted edge moves through
#: the last gap (see FE_ALLOWANCE_A and :func:`fe_allowance_L`).
FE_ALLOWANCE_L_SLOPE = 0.25
#: Why a fit's errors are bounds, not estimates (the note printed with it): its truncation
#: part rests on Richardson's estimate at an order the windows do not show (larger than the
#: next term's: on the census's exact traces the true error was then 0.23-1.5 times
#: Richardson's estimate and 0.62-3.9 times the next term's, so that no one factor brings it
#: within three times), or the edge could only be placed in the last gap or at the last node.
BOUND_RICHARDSON = (
    "the nested windows do not show the edge expansion's order (the nodes next to the edge "
    "are not in its asymptotic range)"
)
BOUND_GAP = "the edge can only be placed within the gap after the last node in contact"
BOUND_MOVED = "the edge can only be placed at the last node in contact"
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
        Estimated error of ``x_edge`` (and of any distance a measured from a fixed point): a
        bound on the truncation error plus a 95 % bound on the scatter's (see the module).
    L_I, L_I_error
        The multiplier of (4), p ~ L_I sqrt(a - x) at the edge, and its estimated error.
    c
        The coefficient of the next term, (a - x)^(3/2), of the chosen fit.
    window
        The x range (trace coordinates) of the nodes in contact that the chosen fit used.
    nodes
        How many nodes in contact it used.
    noise
        The absolute part of the pressure scatter (its standard deviation where p = 0),
        estimated or given.
    last_node_used
        Whether the last node in contact was kept (see the module notes).
    notes
        What the fit had to do or doubt, in words.
    noise_relative
        The relative part of the scatter: its standard deviation at pressure p is
        sqrt(noise^2 + (noise_relative p)^2).
    error_kind
        ``"estimate"``: ``a_error`` and ``L_I_error`` estimate the errors (on the census of
        the built-in laws' exact traces, within three times the true error in 99 % of such
        fits); ``"bound"``: the data support only a bound -- it covers the true error but may
        exceed it many times (a note says why: the nodes next to the edge are not in the edge
        expansion's asymptotic range, or the edge could only be placed at a node or in a gap).
        A finer mesh at the edge gives an estimate.
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
    noise_relative: float = 0.0
    error_kind: ErrorKind = "estimate"

    def position(self, origin: float) -> float:
        """The edge's distance from ``origin`` along its outward direction."""
        return self.x_edge - origin if self.side == "right" else origin - self.x_edge


class EdgeFitError(InputError):
    """The trace cannot give this edge; ``node`` is the offending node's index, if any."""

    def __init__(self, rule: str, node: int | None = None) -> None:
        super().__init__("trace", rule)
        self.node = node


def fe_allowance_L(fraction: float) -> float:
    """The FE allowance of L_I in units of h/a L_I, for a fitted edge ``fraction`` (0 to 1) of
    the way from the last node in contact to the first node out (0 for a fit moved to the last
    node): FE_ALLOWANCE_L - FE_ALLOWANCE_L_SLOPE fraction (see FE_ALLOWANCE_L).

    >>> fe_allowance_L(0.0), fe_allowance_L(1.0)
    (0.62, 0.37)
    """
    return FE_ALLOWANCE_L - FE_ALLOWANCE_L_SLOPE * fraction


# --- nodes -------------------------------------------------------------------------------------
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


# --- the chosen window ----------------------------------------------------------------------
@dataclass(frozen=True)
class _Choice:
    a: float
    L: float
    c: float
    a_error: float
    L_error: float
    row: NDArray[np.intp]
    size: int
    # Why the errors are bounds rather than estimates (see EdgeFit.error_kind); None if not.
    bound: str | None = None


def _choose(
    x: FloatArray,
    p: FloatArray,
    end: int,
    beyond: NDArray[np.intp],
    sizes: list[int],
    low: float,
    high: float,
    noise: NoiseModel,
    safety: float,
) -> _Choice | None:
    """The window ending at ``end`` whose L_I has the least relative error (None if no window
    has a wider one to check its truncation against)."""
    fits = fit_windows(x, p, end, beyond, sizes, low, high, noise)
    errors = window_errors(fits, noise.quantile(), safety)
    if not np.isfinite(errors.L).any():
        return None
    relative = errors.L / np.maximum(np.abs(fits.L), 1e-300)
    k = int(np.argmin(np.where(np.isfinite(relative), relative, np.inf)))
    # The chosen window's scatter part again, by a bootstrap (the linearised one, used to
    # choose, does not see the nodes beyond the contact holding the edge back).
    scatter_a, scatter_L = bootstrap_scatter(
        x,
        p,
        fits.rows[k],
        int(fits.sizes[k]),
        float(fits.a[k]),
        float(fits.L[k]),
        float(fits.c[k]),
        low,
        high,
        noise,
        COVERAGE,
    )
    return _Choice(
        a=float(fits.a[k]),
        L=float(fits.L[k]),
        c=float(fits.c[k]),
        a_error=float(np.hypot(errors.truncation_a[k], scatter_a) + fits.resolution),
        L_error=float(np.hypot(errors.truncation_L[k], scatter_L)),
        row=fits.rows[k][: fits.sizes[k]],
        size=int(fits.sizes[k]),
        bound=(BOUND_RICHARDSON if bool(errors.richardson_dominates[k]) else None),
    )


# --- the edge ----------------------------------------------------------------------------
def _right_edge(
    x: FloatArray, p: FloatArray, noise: NoiseModel, fe_nodes: bool = False
) -> tuple[_Choice, bool, list[str]]:
    """The right-hand edge of a trace with increasing x (the left edge is mirrored first)."""
    peak = float(np.max(p))
    if not peak > 0:
        raise EdgeFitError("no node is in contact (no positive pressure)")
    zero_scatter = max(noise.absolute, NOISE_FLOOR * peak)
    in_contact = np.flatnonzero(p > CONTACT_THRESHOLD * zero_scatter)
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
        sizes = _window_sizes(MIN_WINDOW, available, _WINDOW_GROWTH)
        if not sizes:
            return None
        return _choose(x, p, end, beyond, sizes, low, high, noise, TRUNCATION_SAFETY)

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
        # by dp/da * a_error and sqrt(a - x) * L_error within that fit's uncertainty, and the
        # node's own pressure by its scatter.
        distance = max(without.a - x[last], 0.0)
        predicted = without.L * np.sqrt(distance) + without.c * distance**1.5
        band = np.hypot(
            without.L / (2 * np.sqrt(max(distance, 1e-300))) * without.a_error,
            np.sqrt(distance) * without.L_error,
        )
        tolerance = np.hypot(noise.quantile() * float(noise.sigma(p[last])), band)
        agrees = abs(p[last] - predicted) <= tolerance
        # Agreement means something only when that uncertainty is small beside the node's
        # own pressure; otherwise a wrong last node would pass and pin the edge wrongly.
        decisive = tolerance <= LAST_NODE_RESOLUTION * p[last]
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
    # Kept, the last node's fit stands with its own errors: the node agrees with the others
    # within their uncertainty, and the fit without it is the less accurate one (its window
    # lies a node further from the edge), so their difference measures that fit's error.
    chosen = with_last if keep and with_last is not None else without
    # Would the chosen window, without the nodes beyond the contact, put the edge past the
    # first of them?  Then those zeros hold the edge back and the fit cannot place it within
    # the last gap: the edge is only known to lie in it, and the error says so.
    free_high = x[last + 1] + 2 * (x[last + 1] - x[last])
    X, Pv = padded(x, p, [chosen.row])
    free = float(minimise(X, Pv, low, free_high)[0])
    if free > x[last + 1]:
        gap = max(chosen.a - x[last], x[last + 1] - chosen.a)
        chosen = replace(chosen, a_error=max(chosen.a_error, gap), bound=BOUND_GAP)
        notes.append(
            f"the fit alone would put the edge beyond the first node out of contact (x = "
            f"{x[last + 1]:.6g}); it is placed between the last node in contact and that node"
        )
    # A node with pressure is in contact: the edge is not before it.  A fit that puts it
    # there (an FE trace whose pressure falls short of the square root in the last element)
    # is moved to that node, and keeps its distance from it as error.
    moved = bool(chosen.a < x[last])
    if moved:
        shortfall = x[last] - chosen.a
        chosen = replace(
            chosen, a=float(x[last]), a_error=max(chosen.a_error, shortfall), bound=BOUND_MOVED
        )
        notes.append(
            f"the fit put the edge {shortfall:.3g} before the last node in contact (x = "
            f"{x[last]:.6g}); it is placed at that node"
        )
    if fe_nodes:
        # The FE solution's own discretisation error, which one mesh cannot show: of order the
        # element at the edge, by the rule of FE_ALLOWANCE_A.  A fit that stands is
        # independent of it (the FE's pressures as data): in quadrature.  A fit moved to the
        # last node carries the distance moved, itself a measure of the FE's error there: the
        # larger of the two.
        spacing = x[last + 1] - x[last]
        # Where the fit stands, how far (0 to 1) it put the edge into the last gap.
        fraction = 0.0 if moved else float(np.clip((chosen.a - x[last]) / spacing, 0.0, 1.0))
        allowance_a = (FE_ALLOWANCE_A_AT_NODE if moved else FE_ALLOWANCE_A) * spacing
        allowance_L = fe_allowance_L(fraction) * spacing / (0.5 * width) * abs(chosen.L)
        a_error = (
            max(chosen.a_error, allowance_a)
            if moved
            else float(np.hypot(chosen.a_error, allowance_a))
        )
        # The errors stay bounds only where the fit's own bound outweighs the FE's allowance,
        # itself an estimate (measured on the project's FE model): otherwise they are estimates.
        outweighed = chosen.a_error <= allowance_a and chosen.L_error <= allowance_L
        chosen = replace(
            chosen,
            a_error=float(a_error),
            L_error=float(np.hypot(chosen.L_error, allowance_L)),
            bound=None if outweighed else chosen.bound,
        )
    if chosen.bound is not None:
        notes.append(
            f"the errors of a and L_I are bounds, not estimates: {chosen.bound}; they cover the "
            "true errors but may exceed them many times (a finer mesh at the edge gives an "
            "estimate)"
        )
    return chosen, keep, notes


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
        The pressure scatter (a standard deviation, the same at every node) if known; by
        default its model is estimated from the trace (:func:`.noise.estimate_noise`).
    fe_nodes
        The pressures are an FE solution's nodal values (read from FE results): the errors
        get the FE's discretisation allowance (:data:`FE_ALLOWANCE_A`,
        :data:`FE_ALLOWANCE_A_AT_NODE`, :data:`FE_ALLOWANCE_L`).

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
    # The scatter's model from the nodes in increasing x, as either edge sees it.
    ordered = np.flatnonzero(nodes)
    model = estimate_noise(x[ordered], p[ordered]) if noise is None else NoiseModel(float(noise))
    try:
        chosen, keep, notes = _right_edge(xs, ps, model, fe_nodes)
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
        noise=max(model.absolute, NOISE_FLOOR * float(np.max(p))),
        last_node_used=bool(keep),
        notes=tuple(notes),
        noise_relative=model.relative,
        error_kind="bound" if chosen.bound is not None else "estimate",
    )
