"""How far a fitted edge can be trusted: each window's fit with its scatter and truncation errors.

:mod:`.edge_fit` fits the edge expansion (:mod:`.edge_model`) to windows of K = 4, 5, 6, 7, 8,
10, 12, ... nodes ending at the edge and keeps the window whose L_I has the least relative
error.  The error of a window's a (and likewise of its L_I) has two parts, added:

* **scatter** -- q sd, with sd the standard deviation the pressures' scatter gives the fit
  (the fit linearised about its solution, J its Jacobian in (a, L_I, c), each node's
  variance sigma_i^2 from the noise model of :mod:`.noise`:
  Cov = (J^T J)^-1 J^T diag(sigma^2) J (J^T J)^-1), and q the two-sided 95 % quantile
  (Student's t on the noise model's degrees of freedom).  For noisy data this is a 95 %
  bound; exact data have only rounding scatter.
* **truncation** -- what the neglected terms (a - x)^(5/2), ... do to the two-term fit, which
  for exact data is the whole error: F times the larger of two estimates from the data,

    - the *next term*: the change of a and L_I when e (a - x)^(5/2) is fitted too (the
      three-term fit's own truncation is of higher order, so this is the two-term fit's
      error to leading order), and
    - *Richardson*: the change Delta_1 to the first window at least twice as wide, divided
      by r^p - 1 (r the ratio of their widths): the neglected term shifts a by O(w^3) and
      L_I by O(w^2) over a window of width w, so p = 3 and 2 -- but p is the order the data
      show, log(Delta_2 / Delta_1) / log r from a third window twice as wide again (or, on a
      trace too coarse for one, from a window between the two: e(w) = C w^p through the
      three), kept in [1, 3] (resp. [1, 2]), and 1 where the changes are within twice their
      scatter or disagree in sign (taking the expansion's order there instead lets the
      estimate miss: 88 % coverage of a's error with 1 % absolute scatter, not 95 %).  A window
      reaching towards the end of the expansion's validity (the corner of a flat punch) has
      changes that shrink slower than w^3, a low observed order and a large estimate: the
      next term alone misses such cases by up to 2.3 times.

  Each change is freed of its own scatter, so that on noisy data it measures the truncation,
  not the noise (sd the linearised standard deviation of the change): the next term's change
  is shrunk to change^2 / sqrt(change^2 + sd^2), and the change between windows counts only
  beyond its 95 % range of pure scatter, sqrt(max(change^2 - (1.96 sd)^2, 0))
  (:data:`NOISE_MARGIN`).  Freed by one sd only, a change of pure scatter still gave a
  truncation of up to twice its sd in a third of the fits, counted again beside the scatter
  part that already states it: on 1 % relative scatter the RMS true error of a was then a
  median 0.32 of the reported one (the 95 % bound of Gaussian scatter alone is 0.51),
  within [1/3, 1] for 45 % of the census's meshes.  The next term keeps the gentler
  shrinkage: on coarse exact traces of the rounded flat punch the noise model reads the
  corner as scatter, and a margin there dropped a real truncation error (true/reported up
  to 2.3).  F = :data:`TRUNCATION_SAFETY`.
* the minimisation's own resolution (:func:`.edge_model.resolution`) is added to a's error.

Where Richardson's estimate is the larger and the truncation part outweighs the scatter part
(:attr:`WindowErrors.richardson_dominates`), the error is a bound, not an estimate: on the
census's exact traces the true error was then 0.23-1.5 times Richardson's estimate and
0.62-3.9 times the next term's, too wide a spread for any one factor (the geometric mean of
the two, tried, missed held-out fits of the rounded flat punch by up to 4.5 times); elsewhere
the next term's estimate is the true error within 0.56-1.75 times.  :mod:`.edge_fit` says so
with the fit (``EdgeFit.error_kind``).

Measured on the census of :mod:`tests.calibration.census` (every built-in law; uniform and
graded meshes of 20 to 200 nodes; exact and with 1 % scatter): see the calibration guide
(docs/guide/calibration.md) for the distribution of true over reported errors.

Runtime needs NumPy only.

Examples
--------
The windows tried, and the order of an error e(w) = w^3 recovered from three windows of widths
1, 1.5 and 2 (the changes 1.5^3 - 1 and 2^3 - 1.5^3):

>>> window_sizes(4, 12, 1.2)
[4, 5, 6, 7, 8, 10, 12]
>>> quotient = np.array([(2.0**3 - 1.5**3) / (1.5**3 - 1.0)])
>>> round(float(_three_window_order(quotient, 1.5, 2.0)[0]), 9)
3.0
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .edge_model import minimise, padded, profile, resolution
from .noise import NoiseModel

FloatArray = NDArray[np.float64]

#: The truncation part of the error is this many times the larger of its two estimates.  On
#: exact traces of the built-in laws (240 fits, tests/calibration/census.py) the estimate alone
#: is the true error to within a few per cent in most fits (true/reported 0.45-0.50 at factor 2
#: for 35 nodes or more; lower near the corner of the rounded flat punch and on some 20-node
#: meshes), and 2 covers every fit (largest true/reported 0.57 for a, 0.70 for L_I).
TRUNCATION_SAFETY = 2.0
#: The orders of the two-term fit's truncation error in the window width: a, L_I.
ORDERS = (3.0, 2.0)
#: A change between windows counts towards the observed order only if it exceeds this many of
#: its standard deviations.
SIGNIFICANT = 2.0
#: The change between windows counts towards the Richardson estimate only beyond this many of
#: its standard deviations (the two-sided 95 % range of a change of pure scatter).
NOISE_MARGIN = 1.96


@dataclass(frozen=True)
class WindowFits:
    """Fits of every window ending at one node (arrays over windows, index k).

    ``nodes`` is the largest window's node set (the others are its last ``sizes[k]`` nodes in
    contact, and the same nodes beyond); ``influence[k]`` the linearised map from the
    pressures at ``nodes`` to (a, L_I) of window k's two-term fit, ``sigma`` their scatter.
    """

    sizes: NDArray[np.intp]
    reach: FloatArray  # distance from the window's edge node to its innermost node
    rows: list[NDArray[np.intp]]
    a: FloatArray
    L: FloatArray
    c: FloatArray
    a_next: FloatArray  # the three-term fit's a and L_I
    L_next: FloatArray
    sd: FloatArray  # (k, 2): standard deviations of a and L_I
    sd_next: FloatArray  # (k, 2): ... of the change to the three-term fit
    influence: FloatArray  # (k, 2, n)
    sigma: FloatArray  # (n,)
    resolution: float  # of the minimisation, in a


@dataclass(frozen=True)
class WindowErrors:
    """Each window's error of a and L_I, and their parts (arrays over windows)."""

    a: FloatArray
    L: FloatArray
    scatter_a: FloatArray
    scatter_L: FloatArray
    truncation_a: FloatArray
    truncation_L: FloatArray
    #: Where Richardson's estimate exceeds the next term's and the truncation part outweighs
    #: the scatter part, for a or L_I: the window is not in the expansion's asymptotic range,
    #: and the error is a bound, not an estimate.
    richardson_dominates: NDArray[np.bool_]


def window_sizes(smallest: int, available: int, growth: float) -> list[int]:
    """K = smallest, then growing by ``growth`` (at least one node), up to ``available``."""
    sizes, size = [], smallest
    while size <= available:
        sizes.append(size)
        size = max(size + 1, int(round(size * growth)))
    return sizes


def fit_windows(
    x: FloatArray,
    p: FloatArray,
    end: int,
    beyond: NDArray[np.intp],
    sizes: list[int],
    low: float,
    high: float,
    noise: NoiseModel,
) -> WindowFits:
    """Two- and three-term fits of every window, and their linearised scatter."""
    rows = [np.concatenate([np.arange(end - size + 1, end + 1), beyond]) for size in sizes]
    X, Pv = padded(x, p, rows)
    a = minimise(X, Pv, low, high)
    L, c = (value[:, 0] for value in profile(X, Pv, a[:, None])[:2])
    a_next = minimise(X, Pv, low, high, next_term=True)
    L_next, c_next, e_next = (value[:, 0] for value in profile(X, Pv, a_next[:, None], True)[:3])
    nodes = rows[-1]
    largest = sizes[-1]
    sigma = noise.sigma(p[nodes])
    # Window k holds the last sizes[k] nodes in contact of the largest window and its nodes
    # beyond the contact.
    position = np.arange(nodes.size)
    member = (position[None, :] >= largest - np.asarray(sizes)[:, None]).astype(np.float64)
    xs = x[nodes][None, :]
    two = _influence(_jacobian(a, (L, c), xs) * member[:, :, None])
    three = _influence(_jacobian(a_next, (L_next, c_next, e_next), xs) * member[:, :, None])
    influence = two[:, :2, :]
    change = three[:, :2, :] - influence
    return WindowFits(
        sizes=np.asarray(sizes),
        reach=x[end] - x[end - np.asarray(sizes) + 1],
        rows=rows,
        a=a,
        L=L,
        c=c,
        a_next=a_next,
        L_next=L_next,
        sd=np.sqrt(np.einsum("kin,n->ki", influence**2, sigma**2)),
        sd_next=np.sqrt(np.einsum("kin,n->ki", change**2, sigma**2)),
        influence=influence,
        sigma=sigma,
        resolution=resolution(low, high),
    )


def _jacobian(a: FloatArray, coefficients: tuple[FloatArray, ...], x: FloatArray) -> FloatArray:
    """d model / d (a, L_I, c[, e]) at the nodes x, (k, n, 1 + terms); 0 beyond the edge."""
    d = np.maximum(a[:, None] - x, 0.0)
    inside = d > 0
    root = np.sqrt(np.where(inside, d, 1.0))
    basis = [np.where(inside, root * d**j, 0.0) for j in range(len(coefficients))]
    # d/da of sum_j C_j d^(j + 1/2) = sum_j (j + 1/2) C_j d^(j - 1/2)
    slope = sum(
        (j + 0.5) * C[:, None] * np.where(inside, d**j / root, 0.0)
        for j, C in enumerate(coefficients)
    )
    return np.stack([slope, *basis], axis=-1)


def _influence(J: FloatArray) -> FloatArray:
    """(J^T J)^-1 J^T for each window, (k, parameters, n), with the columns scaled first.

    The pseudo-inverse: a window whose edge falls before its last node (that node's row is 0)
    may have fewer nodes inside than parameters.
    """
    norm = np.sqrt(np.einsum("kni,kni->ki", J, J))
    norm = np.where(norm > 0, norm, 1.0)
    return np.linalg.pinv(J / norm[:, None, :], rcond=1e-12) / norm[:, :, None]


def window_errors(
    fits: WindowFits, quantile: float, safety: float = TRUNCATION_SAFETY
) -> WindowErrors:
    """The error of a and L_I of each window (inf where no wider window checks it)."""
    count = fits.sizes.size
    truncation = np.full((count, 2), np.inf)
    richardson_larger = np.zeros((count, 2), dtype=bool)
    values = np.stack([fits.a, fits.L], axis=1)
    nexts = np.stack([fits.a_next, fits.L_next], axis=1)
    for k in range(count):
        wider = np.flatnonzero(fits.reach >= 2 * fits.reach[k])
        if not wider.size:
            continue
        m = int(wider[0])
        widest = np.flatnonzero(fits.reach >= 2 * fits.reach[m])
        ratio = fits.reach[m] / fits.reach[k]
        next_term = _shrunk(nexts[k] - values[k], fits.sd_next[k])
        first, sd_first = _change(fits, values, m, k)
        order = np.ones(2)
        if widest.size:
            n = int(widest[0])
            second, sd_second = _change(fits, values, n, m)
            significant = (np.abs(first) > SIGNIFICANT * sd_first) & (
                np.abs(second) > SIGNIFICANT * sd_second
            )
            mean_ratio = np.sqrt(ratio * fits.reach[n] / fits.reach[m])
            growth = np.where(significant, np.abs(second), 1.0) / np.where(
                significant, np.abs(first), 1.0
            )
            observed = np.log(growth) / np.log(mean_ratio)
            order = np.where(significant, np.clip(observed, 1.0, ORDERS), 1.0)
        elif m - k >= 2:
            # No window twice as wide again (a coarse trace): the order from a window j
            # between k and m instead, e(w) = C w^p through the three.
            j = int(
                k
                + np.argmin(np.abs(np.log(fits.reach[k:m] ** 2 / (fits.reach[k] * fits.reach[m]))))
            )
            j = min(max(j, k + 1), m - 1)
            inner, sd_inner = _change(fits, values, j, k)
            outer, sd_outer = _change(fits, values, m, j)
            significant = (
                (np.abs(inner) > SIGNIFICANT * sd_inner)
                & (np.abs(outer) > SIGNIFICANT * sd_outer)
                & (inner * outer > 0)
            )
            observed = _three_window_order(
                np.abs(outer) / np.where(significant, np.abs(inner), 1.0),
                fits.reach[j] / fits.reach[k],
                ratio,
            )
            order = np.where(significant, np.clip(observed, 1.0, ORDERS), 1.0)
        richardson = _beyond_scatter(first, sd_first) / (ratio**order - 1.0)
        truncation[k] = safety * np.maximum(next_term, richardson)
        richardson_larger[k] = richardson > next_term
    scatter = quantile * fits.sd
    # A bound where the truncation part rests on Richardson's estimate and outweighs the scatter.
    dominates = np.any(richardson_larger & (truncation > scatter), axis=1)
    total = np.hypot(scatter, truncation)
    total[:, 0] += fits.resolution
    return WindowErrors(
        a=total[:, 0],
        L=total[:, 1],
        scatter_a=scatter[:, 0],
        scatter_L=scatter[:, 1],
        truncation_a=truncation[:, 0],
        truncation_L=truncation[:, 1],
        richardson_dominates=dominates,
    )


def bootstrap_scatter(
    x: FloatArray,
    p: FloatArray,
    row: NDArray[np.intp],
    size: int,
    a: float,
    L: float,
    c: float,
    low: float,
    high: float,
    noise: NoiseModel,
    coverage: float,
    draws: int = 200,
) -> tuple[float, float]:
    """The scatter part of a's and L_I's error of one window by a parametric bootstrap.

    ``draws`` sets of pressures -- the fitted model at the window's nodes in contact plus
    Gaussian scatter of the noise model (the nodes beyond the contact as they are) -- are fitted
    again; the ``coverage`` quantile of |a* - a| and |L_I* - L_I|, times the ratio of the noise
    model's quantile to the normal one (Student's t for an estimated model).  Unlike the
    linearised standard deviation, this sees that the nodes beyond the contact hold the edge
    back (they enter the fit through the clamp max(a - x, 0), which linearisation drops).
    The draws are seeded: the same trace gives the same error.
    """
    contact = row[:size]
    d = np.maximum(a - x[contact], 0.0)
    model = np.sqrt(d) * (L + c * d)
    rng = np.random.default_rng(BOOTSTRAP_SEED)
    scatter = noise.sigma(model)[None, :] * rng.standard_normal((draws, contact.size))
    X = np.broadcast_to(x[row], (draws, row.size))
    Pv = np.concatenate(
        [model[None, :] + scatter, np.broadcast_to(p[row[size:]], (draws, row.size - size))],
        axis=1,
    )
    a_star = minimise(np.ascontiguousarray(X), Pv, low, high)
    L_star = profile(np.ascontiguousarray(X), Pv, a_star[:, None])[0][:, 0]
    widen = noise.quantile(coverage) / noise.quantile_normal(coverage)
    return (
        widen * float(np.quantile(np.abs(a_star - a), coverage)),
        widen * float(np.quantile(np.abs(L_star - L), coverage)),
    )


#: The bootstrap's random numbers (fixed: the error of a trace must not change between runs).
BOOTSTRAP_SEED = 20230619


def _change(
    fits: WindowFits, values: FloatArray, wide: int, narrow: int
) -> tuple[FloatArray, FloatArray]:
    """(a, L_I) of window ``wide`` minus window ``narrow``, and the change's standard deviation."""
    difference = fits.influence[wide] - fits.influence[narrow]
    return values[wide] - values[narrow], np.sqrt(difference**2 @ fits.sigma**2)


def _three_window_order(quotient: FloatArray, r_inner: float, r_outer: float) -> FloatArray:
    """p with (r_outer^p - r_inner^p) / (r_inner^p - 1) = quotient, by bisection in [0.25, 6].

    The changes between windows of widths w_k < w_j < w_m (r = w / w_k) of a value whose error
    is C w^p; the quotient rises with p, so the root is unique (clipped to the interval).
    """
    low = np.full(quotient.shape, 0.25)
    high = np.full(quotient.shape, 6.0)
    for _ in range(60):
        middle = 0.5 * (low + high)
        value = (r_outer**middle - r_inner**middle) / (r_inner**middle - 1.0)
        above = value > quotient
        high = np.where(above, middle, high)
        low = np.where(above, low, middle)
    root: FloatArray = 0.5 * (low + high)
    return root


def _shrunk(change: FloatArray, sd: FloatArray) -> FloatArray:
    """|change| shrunk by its scatter: change^2 / sqrt(change^2 + sd^2) (0 for no change)."""
    size = np.sqrt(change**2 + sd**2)
    return np.where(size > 0, change**2 / np.where(size > 0, size, 1.0), 0.0)


def _beyond_scatter(change: FloatArray, sd: FloatArray) -> FloatArray:
    """|change| beyond what its scatter alone makes likely: sqrt(max(change^2 - (m sd)^2, 0)).

    m = :data:`NOISE_MARGIN`.  A change of pure scatter exceeds m sd in only 5 % of draws, so
    on noisy data the truncation estimate is mostly 0 where the windows differ by scatter (the
    scatter part states it already); on exact data sd is rounding and the change stands.
    """
    return np.sqrt(np.maximum(change**2 - (NOISE_MARGIN * sd) ** 2, 0.0))
