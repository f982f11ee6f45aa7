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

Examples
--------
>>> import numpy as np
>>> from asymslip.laws.roots import invert_increasing
>>> invert_increasing(lambda a: a**3, np.array([8.0, 27.0]), lambda a: 3 * a**2)
array([2., 3.])
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
    root, found = invert_increasing_where_possible(
        function, target, slope, lower=lower, upper=upper
    )
    if not np.all(found):
        goal = np.asarray(target, dtype=np.float64)
        index = int(np.flatnonzero(~np.asarray(found).ravel())[0])
        raise ValueError(
            f"target: {float(goal.ravel()[index])!r} (at index {index}) is outside the range of "
            "the function over positive arguments; no root was bracketed"
        )
    return root


def invert_increasing_where_possible(
    function: Callable[[FloatArray], FloatArray],
    target: ArrayLike,
    slope: Callable[[FloatArray], FloatArray] | None = None,
    *,
    lower: ArrayLike | None = None,
    upper: ArrayLike | None = None,
) -> tuple[FloatArray, NDArray[np.bool_]]:
    """:func:`invert_increasing` that marks, instead of raising for, targets it cannot reach.

    Returns the roots (NaN where none was bracketed or the target is not finite) and a mask of
    the elements where a root was found, both shaped like ``target``.
    """
    goal = np.asarray(target, dtype=np.float64)
    finite = np.isfinite(goal)
    safe = np.where(finite, goal, 1.0)
    lo = _start(lower, safe)
    hi = _start(upper, safe)
    if np.any(lo > hi):
        raise ValueError("lower: must not exceed upper")
    lo, hi, r_lo, r_hi = _bracket(function, safe, lo, hi)
    found = finite & (r_lo <= 0) & (r_hi >= 0)
    # Unbracketed elements get a harmless bracket; their result is discarded.
    lo, hi = np.where(found, lo, 1.0), np.where(found, hi, 2.0)
    r_lo, r_hi = np.where(found, r_lo, -1.0), np.where(found, r_hi, 1.0)
    root = np.where(found, _refine(function, slope, safe, lo, hi, r_lo, r_hi), np.nan)
    if root.ndim == 0:
        return root[()], found[()]
    return root, found


def newton_from(
    function: Callable[[FloatArray], FloatArray],
    slope: Callable[[FloatArray], FloatArray],
    target: ArrayLike,
    guess: ArrayLike,
    *,
    iterations: int = 12,
    both: Callable[[FloatArray], tuple[FloatArray, FloatArray]] | None = None,
) -> tuple[FloatArray, NDArray[np.bool_]]:
    """Plain Newton steps from a good first guess.

    For inverting an increasing law near a known point (a1 from a tight upper bound, a2 and
    a(P_K) from the tangent at a1), where two or three steps reach full precision.  An element
    is converged when its last step is within four units in the last place, or when quadratic
    convergence predicts the next one will be: steps shrink as s_(k+1) = C s_k^2, and with C
    estimated from the last two steps the step after |s_k| is |s_k|^3 / |s_(k-1)|^2 -- below
    two units in the last place, one more function evaluation would not change the double.
    The others (a step leaving the positive reals, no convergence) come back unconverged, for
    the caller to hand to the bracketing :func:`invert_increasing_where_possible`.

    ``both``, if given, returns the function and its slope from one evaluation (laws whose
    two share their costly parts).  While most elements still move, every element is stepped
    (a converged one stays put to rounding); the stragglers are then stepped on their own.
    """
    goal = np.asarray(target, dtype=np.float64)
    x = np.array(np.broadcast_to(np.asarray(guess, dtype=np.float64), goal.shape), dtype=float)
    goal = np.broadcast_to(goal, x.shape)
    shape = x.shape
    x, goal = x.reshape(-1), np.ascontiguousarray(goal).reshape(-1)
    if both is None:

        def both(points: FloatArray) -> tuple[FloatArray, FloatArray]:
            return function(points), slope(points)

    usable = np.isfinite(x) & (x > 0) & np.isfinite(goal)
    converged = np.zeros(x.shape, dtype=bool)
    moving = usable.copy()
    previous = np.zeros(x.shape)  # no step yet: the prediction needs two
    index: NDArray[np.intp] | None = None  # None: step the whole array
    with np.errstate(all="ignore"):  # a step may leave the domain: it is then not converged
        for _ in range(iterations):
            if index is None and moving.sum() < x.size // 4:
                index = np.flatnonzero(moving)  # few left: step only those
            if index is not None and index.size == 0:
                break
            current = x if index is None else x[index]
            value, gradient = both(current)
            step = (value - (goal if index is None else goal[index])) / gradient
            new = current - step
            # An overflowing slope gives a zero step far from the root: not a converged one.
            ok = np.isfinite(new) & (new > 0) & np.isfinite(gradient)
            size = np.abs(step)
            ulp = np.spacing(new)
            last = previous if index is None else previous[index]
            done = ok & ((size <= 4 * ulp) | (size**3 <= 2 * ulp * last**2))
            if index is None:
                active = moving
                x = np.where(active & ok, new, x)
                converged |= active & done
                moving = active & ok & ~done
                previous = size
            else:
                x[index] = np.where(ok, new, current)
                converged[index[done]] = True
                keep = ok & ~done
                moving[index] = keep
                index, previous_kept = index[keep], size[keep]
                previous[index] = previous_kept
            if index is None and not moving.any():
                break
    result, flags = x.reshape(shape), converged.reshape(shape)
    if result.ndim == 0:
        return result[()], flags[()]
    return result, flags


def _start(value: ArrayLike | None, goal: FloatArray) -> FloatArray:
    start = np.ones_like(goal) if value is None else np.asarray(value, dtype=np.float64)
    start = np.array(np.broadcast_to(start, goal.shape), dtype=np.float64)
    if not np.all((start > 0) & np.isfinite(start)):
        raise ValueError("lower, upper: bracket guesses must be finite and > 0")
    return start


def _residual(
    function: Callable[[FloatArray], FloatArray], x: FloatArray, goal: FloatArray
) -> FloatArray:
    return np.asarray(function(x), dtype=np.float64) - goal


def _bracket(
    function: Callable[[FloatArray], FloatArray], goal: FloatArray, lo: FloatArray, hi: FloatArray
) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray]:
    """Expand [lo, hi] until residual(lo) <= 0 <= residual(hi); return it and its residuals.

    Elements whose root lies outside the double range come back unbracketed (the residuals do
    not change sign); the caller decides what to do with them.

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
            # An overflowing slope (inf) makes the step 0 without x being near the root: only
            # a finite slope may end the iteration or take a Newton step.
            finite_slope = np.isfinite(gradient)
            converged = (
                np.isfinite(newton)
                & finite_slope
                & (np.abs(newton - x) <= 2 * np.spacing(np.abs(x)))
            )
            if slope is None:
                converged &= np.abs(x - x_previous) <= 1e-6 * np.abs(x)
            # Otherwise Newton only if it lands strictly inside the bracket and at most halves the
            # step before last; else bisect, geometrically while the bracket is wide (rtsafe).
            trusted = (
                np.isfinite(newton)
                & finite_slope
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


#: Up to this relative length the difference is integrated; beyond it the plain difference
#: loses at most a few units in the last place (P(a + d) - P(a) >= P(a) d/a for a convex law
#: through 0).
QUADRATURE_LIMIT = 0.25
#: Gauss-Legendre rules on [0, 1] by the interval's length relative to its distance from the
#: law's nearest singularity (r = d/a in the half-width): the n-point rule's error is about
#: (r/4)^(2n), so 3 points are exact to rounding up to r = 1e-3, 5 up to 0.03, 7 up to 0.25.
GAUSS_RULES = tuple(
    (limit, 0.5 * (nodes + 1), 0.5 * weights)
    for limit, (nodes, weights) in (
        (1e-3, np.polynomial.legendre.leggauss(3)),
        (3e-2, np.polynomial.legendre.leggauss(5)),
        (QUADRATURE_LIMIT, np.polynomial.legendre.leggauss(7)),
    )
)


def gauss_integral(
    integrand: Callable[[FloatArray], FloatArray],
    start: FloatArray,
    length: FloatArray,
    ratio: FloatArray,
) -> FloatArray:
    """int_start^(start + length) integrand, elementwise, each with the smallest rule of
    :data:`GAUSS_RULES` whose limit covers its ``ratio``.

    An element whose ratio no rule covers (above :data:`QUADRATURE_LIMIT`, or NaN) is NaN: the
    caller must take the plain difference there, and a NaN cannot pass for an integral.
    """
    out = np.full(start.shape, np.nan)
    lower = -np.inf
    for limit, nodes, weights in GAUSS_RULES:
        chosen = (ratio > lower) & (ratio <= limit)
        lower = limit
        if chosen.any():
            points = start[chosen, None] + length[chosen, None] * nodes
            out[chosen] = length[chosen] * (integrand(points) @ weights)
    return out


def load_difference(
    slope: Callable[[FloatArray], FloatArray],
    load: Callable[[FloatArray], FloatArray],
    a: ArrayLike,
    d: ArrayLike,
) -> FloatArray:
    """P(a + d) - P(a) without cancellation: int_a^{a+d} P'(s) ds by Gauss-Legendre.

    For d <= :data:`QUADRATURE_LIMIT` a the rule of :data:`GAUSS_RULES` chosen by d/a is exact
    to rounding for a law analytic on the disc around the interval that reaches to s = 0 (the
    nearest singularity of every law here).  Larger d: the plain difference, then accurate.
    """
    a, d = np.broadcast_arrays(np.asarray(a, dtype=np.float64), np.asarray(d, dtype=np.float64))
    near = d <= QUADRATURE_LIMIT * a
    out = np.empty(a.shape)
    if near.any():
        out[near] = gauss_integral(slope, a[near], d[near], d[near] / a[near])
    if (~near).any():
        out[~near] = load(a[~near] + d[~near]) - load(a[~near])
    return out[()] if out.ndim == 0 else out


def growth_from(
    load: Callable[[FloatArray], FloatArray],
    slope: Callable[[FloatArray], FloatArray],
    difference: Callable[[FloatArray, FloatArray], FloatArray],
    a1: ArrayLike,
    P2: ArrayLike,
    dP: ArrayLike,
    *,
    both: Callable[[FloatArray], tuple[FloatArray, FloatArray]] | None = None,
) -> tuple[FloatArray, NDArray[np.bool_]]:
    """a(P1 + dP) - a(P1) from a1 = a(P1): a1 + the result is a(P2) to a few units in the last
    place for any load change, and the result keeps full relative precision however small
    dP/P1 is.

    a2 is a root solve of P(a) = P2 (Newton from the tangent at a1, the bracketing inverse
    where Newton does not settle), accurate to a few units in the last place of a2; so is
    d0 = a2 - a1, which is all the precision d needs where d is not small against a1.  Where it
    is (d0 <= :data:`QUADRATURE_LIMIT` a1), one Newton step on the cancellation-free residual
    difference(a1, d) - dP takes d to full relative precision: its error after the step is of
    order (eps a2)^2, far below eps d.  That step is kept only if it moves d0 by no more than
    a2's own rounding can explain (8 units in the last place of a1 and of a2): a larger move
    means the difference was not accurate there (an interval beyond its quadrature rule), and
    d0 stands.  No quadrature of root solves.  Elements with no root (P2 outside the law's
    range) are returned with ``found`` False.
    """
    a1 = np.asarray(a1, dtype=np.float64)
    P2, dP = np.asarray(P2, dtype=np.float64), np.asarray(dP, dtype=np.float64)
    a1, P2, dP = np.broadcast_arrays(a1, P2, dP)
    with np.errstate(all="ignore"):
        guess = a1 + dP / slope(a1)
    a2, found = newton_from(load, slope, P2, guess, both=both)
    if not np.all(found):
        retry = ~found
        a2 = np.array(a2, dtype=float)
        solved, solved_found = invert_increasing_where_possible(
            load,
            P2[retry],
            slope,
            lower=a1[retry],
            upper=np.where(
                np.isfinite(guess[retry]) & (guess[retry] > a1[retry]), guess[retry], 2 * a1[retry]
            ),
        )
        a2[retry], found = solved, np.array(found, dtype=bool)
        found[retry] = solved_found
    with np.errstate(all="ignore"):
        d0 = np.where(found, np.maximum(a2 - a1, 0.0), np.nan)
        near = found & (d0 <= QUADRATURE_LIMIT * a1)
        step = np.where(near, d0, 0.0)
        corrected = step - (difference(a1, step) - dP) / slope(a1 + step)
        rounding = 8 * (np.spacing(np.abs(a1)) + np.spacing(np.abs(a2)))
        trusted = near & np.isfinite(corrected) & (np.abs(corrected - d0) <= rounding)
    d = np.where(trusted, corrected, d0)
    if d.ndim == 0:
        return d[()], found[()]
    return d, found
