"""Vectorised inverse of an increasing function: bracket, then safeguarded Newton (NumPy only).

Contact laws give P(a) and dP/da in closed form but not always a(P); :func:`invert_increasing`
solves P(a) = target elementwise for a > 0.  It first brackets each root (expanding
geometrically, with a factor that squares at every step, so that any double is reached in a
dozen evaluations), then iterates Newton's method (with the slope if given, else the secant
through the last two iterates) inside the bracket.  A step that leaves the bracket, or does not
at least halve the step before last, is replaced by a bisection (geometric while the bracket
spans more than a factor of two), as in Numerical Recipes' ``rtsafe``: convergence is
guaranteed like bisection's and is quadratic near a simple root.  The final iterate is then
compared by residual with its neighbours within two units in the last place: the result is the
double closest to a root of the function as computed.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from numpy.typing import ArrayLike, NDArray

FloatArray = NDArray[np.float64]

#: Growth factors 2, 4, 16, 256, ... reach the ends of the double range in this many steps.
_BRACKET_STEPS = 12
#: Bisection alone needs ~11 geometric plus ~53 arithmetic halvings; rtsafe at most doubles it.
_MAX_ITERATIONS = 200
_LARGEST = np.finfo(np.float64).max
_SMALLEST = np.finfo(np.float64).smallest_normal


def invert_increasing(
    function: Callable[[FloatArray], FloatArray],
    target: ArrayLike,
    slope: Callable[[FloatArray], FloatArray] | None = None,
    *,
    lower: ArrayLike | None = None,
    upper: ArrayLike | None = None,
) -> FloatArray:
    """Solve ``function(a) = target`` for a > 0, elementwise, for an increasing ``function``.

    Parameters
    ----------
    function
        Increasing (non-decreasing is enough where it is flat away from the root) and
        vectorised over arrays of positive half-widths.
    target
        Values to invert; every one must lie strictly inside the range of ``function`` on
        (0, inf).
    slope
        The derivative of ``function``, for Newton steps; without it the secant is used.
    lower, upper
        Optional first guesses for a bracket (broadcast against ``target``); they need not be
        valid, the bracket is expanded from them.  By default both are 1.

    Returns
    -------
    ndarray or float64
        The roots, shaped like ``target``.

    Raises
    ------
    ValueError
        If a target is not finite, or no bracket is found within the double range (the target
        is outside the range of ``function``).
    """
    goal = np.asarray(target, dtype=np.float64)
    if not np.all(np.isfinite(goal)):
        raise ValueError("target: every value to invert must be finite")
    lo = _start(lower, goal)
    hi = _start(upper, goal)
    if np.any(lo > hi):
        raise ValueError("lower: must not exceed upper")
    lo, hi, r_lo, r_hi = _bracket(function, goal, lo, hi)
    root = _refine(function, slope, goal, lo, hi, r_lo, r_hi)
    return root[()] if root.ndim == 0 else root


def _start(value: ArrayLike | None, goal: FloatArray) -> FloatArray:
    start = np.ones_like(goal) if value is None else np.asarray(value, dtype=np.float64)
    start = np.array(np.broadcast_to(start, goal.shape), dtype=np.float64)
    if not np.all((start > 0) & np.isfinite(start)):
        raise ValueError("lower, upper: bracket guesses must be finite and > 0")
    return start


def _residual(function: Callable[[FloatArray], FloatArray], x: FloatArray,
              goal: FloatArray) -> FloatArray:  # fmt: skip
    return np.asarray(function(x), dtype=np.float64) - goal


def _bracket(
    function: Callable[[FloatArray], FloatArray], goal: FloatArray, lo: FloatArray, hi: FloatArray
) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray]:
    """Expand [lo, hi] until residual(lo) <= 0 <= residual(hi); return it and its residuals.

    Each step moves an end past the other (which then tightens the bracket) by a factor that
    squares every time: 2, 4, 16, 256, ...; twelve steps span the whole double range.
    """
    # While expanding, a function that overflows to +inf far above the root is simply large.
    with np.errstate(over="ignore"):
        r_lo = _residual(function, lo, goal)
        r_hi = _residual(function, hi, goal)
        factor = np.full_like(goal, 2.0)
        for _ in range(_BRACKET_STEPS):
            low_side = r_lo > 0  # the root lies below lo
            if low_side.any():
                trial = np.where(low_side, np.maximum(lo / factor, _SMALLEST), lo)
                r_trial = _residual(function, trial, goal)
                hi = np.where(low_side, lo, hi)
                r_hi = np.where(low_side, r_lo, r_hi)
                lo = np.where(low_side, trial, lo)
                r_lo = np.where(low_side, r_trial, r_lo)
            high_side = r_hi < 0  # the root lies above hi
            if high_side.any():
                trial = np.where(high_side, np.minimum(hi * factor, _LARGEST), hi)
                r_trial = _residual(function, trial, goal)
                lo = np.where(high_side, hi, lo)
                r_lo = np.where(high_side, r_hi, r_lo)
                hi = np.where(high_side, trial, hi)
                r_hi = np.where(high_side, r_trial, r_hi)
            if not (low_side.any() or high_side.any()):
                break
            factor = np.where(low_side | high_side, np.minimum(factor * factor, _LARGEST), factor)
    unbracketed = ~((r_lo <= 0) & (r_hi >= 0))
    if unbracketed.any():
        index = int(np.flatnonzero(unbracketed.ravel())[0])
        raise ValueError(
            f"target: {float(goal.ravel()[index])!r} (at index {index}) is outside the range of "
            "the function over positive arguments; no root was bracketed"
        )
    return lo, hi, r_lo, r_hi


def _refine(
    function: Callable[[FloatArray], FloatArray],
    slope: Callable[[FloatArray], FloatArray] | None,
    goal: FloatArray,
    lo: FloatArray,
    hi: FloatArray,
    r_lo: FloatArray,
    r_hi: FloatArray,
) -> FloatArray:
    """Safeguarded Newton (or secant) inside a valid bracket, elementwise."""
    # Start from the end with the smaller residual; the other end seeds the secant.
    from_low = np.abs(r_lo) <= np.abs(r_hi)
    x, r = np.where(from_low, lo, hi), np.where(from_low, r_lo, r_hi)
    x_previous, r_previous = np.where(from_low, hi, lo), np.where(from_low, r_hi, r_lo)
    step_before_last = hi - lo
    last_step = hi - lo
    active = (r != 0) & (np.nextafter(lo, np.inf) < hi)
    # Far from the root an increasing function may overflow: +inf simply means "above".
    with np.errstate(over="ignore"):
        for _ in range(_MAX_ITERATIONS):
            if not active.any():
                break
            if slope is not None:
                gradient = np.asarray(slope(x), dtype=np.float64)
            # A zero or undefined gradient (also inf - inf from an overflowed residual) gives a
            # non-finite step, which bisection replaces.
            with np.errstate(divide="ignore", invalid="ignore"):
                if slope is None:
                    gradient = (r - r_previous) / (x - x_previous)
                newton = x - r / gradient
            # A step below two units in the last place ends the iteration if the slope is f'(x):
            # then |x - root| ~ |r / f'(x)| is that small.  A secant through a far point can be
            # much too steep, so it counts only once its two points are close.
            converged = np.isfinite(newton) & (np.abs(newton - x) <= 2 * np.spacing(np.abs(x)))
            if slope is None:
                converged &= np.abs(x - x_previous) <= 1e-6 * np.abs(x)
            # Otherwise Newton only if it lands strictly inside the bracket and at most halves the
            # step before last; else bisect, geometrically while the bracket is wide (rtsafe).
            trusted = (
                np.isfinite(newton)
                & (newton > lo)
                & (newton < hi)
                & (np.abs(newton - x) <= 0.5 * np.abs(step_before_last))
            )
            bisection = np.where(hi > 2 * lo, np.sqrt(lo) * np.sqrt(hi), lo + 0.5 * (hi - lo))
            candidate = np.where(
                converged, np.clip(newton, lo, hi), np.where(trusted, newton, bisection)
            )
            step_before_last = np.where(active, last_step, step_before_last)
            last_step = np.where(active, candidate - x, last_step)
            x_previous = np.where(active, x, x_previous)
            r_previous = np.where(active, r, r_previous)
            x = np.where(active, candidate, x)
            r = np.where(active, _residual(function, x, goal), r)
            below, above = active & (r < 0), active & (r > 0)
            lo, r_lo = np.where(below, x, lo), np.where(below, r, r_lo)
            hi, r_hi = np.where(above, x, hi), np.where(above, r, r_hi)
            adjacent = np.nextafter(lo, np.inf) >= hi
            active &= ~converged & (r != 0) & ~adjacent
    # Polish: of the iterate, its neighbours within two units in the last place (where a tiny
    # Newton step may have stopped) and the bracket ends, return the smallest residual.
    best, r_best = x, np.abs(r)
    for candidate, residual in [(lo, r_lo), (hi, r_hi)]:
        better = np.abs(residual) < r_best
        best, r_best = np.where(better, candidate, best), np.where(better, np.abs(residual), r_best)
    with np.errstate(over="ignore"):
        for shift in (-2, -1, 1, 2):
            candidate = np.clip(x + shift * np.spacing(np.abs(x)), lo, hi)
            residual = np.abs(_residual(function, candidate, goal))
            better = residual < r_best
            best, r_best = np.where(better, candidate, best), np.where(better, residual, r_best)
    return best


#: Gauss-Legendre rule used by :func:`inverse_growth` on each panel.
_NODES, _WEIGHTS = np.polynomial.legendre.leggauss(16)


def inverse_growth(
    inverse: Callable[[FloatArray], FloatArray],
    slope: Callable[[FloatArray], FloatArray],
    start: ArrayLike,
    change: ArrayLike,
) -> FloatArray:
    """a(P1 + dP) - a(P1) = int_{P1}^{P1 + dP} dP / P'(a(P)), as a sum of positive terms.

    The difference of two inverses loses relative precision as dP/P1 -> 0; the integral of the
    inverse's slope does not.  Gauss-Legendre (16 nodes) on panels whose ends are in ratio at
    most 2: the integrand is analytic on each, its nearest singularity (P = 0) at least a panel
    width away, so the rule's error is below 1e-20 relative.

    Parameters
    ----------
    inverse
        a(P), vectorised, for P > 0.
    slope
        dP/da of the law, vectorised (> 0 where used).
    start, change
        P1 > 0 and dP >= 0, broadcast together.

    Returns
    -------
    ndarray or float64
        a(P1 + dP) - a(P1), shaped like the broadcast of ``start`` and ``change``.
    """
    P1, dP = np.broadcast_arrays(np.asarray(start, dtype=np.float64),
                                 np.asarray(change, dtype=np.float64))  # fmt: skip
    ratio = dP / P1
    panels = int(np.ceil(np.log2(1 + np.max(ratio, initial=0.0)))) or 1
    # Panel ends P1 (1 + dP/P1)^(k/panels): geometric, each panel's ends in ratio <= 2.
    fractions = np.expm1(np.log1p(ratio)[..., None] * np.arange(panels + 1) / panels)
    ends = P1[..., None] * (1 + fractions)
    widths = P1[..., None] * (fractions[..., 1:] - fractions[..., :-1])
    # Panel widths from the fractions keep full precision for tiny dP/P1.
    middles = ends[..., :-1] + 0.5 * widths
    loads = middles[..., None] + 0.5 * widths[..., None] * _NODES
    integrand = 1.0 / slope(inverse(loads))
    total = np.sum(0.5 * widths * np.sum(_WEIGHTS * integrand, axis=-1), axis=-1)
    return total[()] if total.ndim == 0 else total
