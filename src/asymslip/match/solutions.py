"""The rig's pad and cycle that reproduce an edge state: exactly where the rig allows, else the
closest by the edge-state mismatch (:mod:`.signature`).

Exact answers come from the derived solutions of ``derivations/lab_transfer.py``: for a Hertz
pad the one (R, a1, a2) of LT3; for a rounded flat with both dimensions free the pad at the
prototype's own half-widths (LT5, the second-order match), or, where that needs a c out of
reach, a pad of the nearest c whose a1 is found from its L_I2/L_I1; then the path slopes of LT4.
Anything the rig's limits rule out (a radius from a list, a load limit, no bulk tension, an L_I
that falls along the prototype's path) is minimised: the loads and free dimensions by bounded
least squares (SciPy, the ``special`` extra) over the mismatch, the path slopes, for each pad and
loads, by linear least squares within the shear-force and tension limits.

Examples
--------
The one cylinder (LT3) and path slopes (LT4) of an edge state:

>>> from asymslip.match import EdgeSignature, Rig
>>> from asymslip.match.solutions import exact_hertz
>>> pad = exact_hertz(Rig("hertz", 1.0), EdgeSignature(0.3, 2.0, 2.1, 0.7, 0.9, 0.05))
>>> round(pad.geometry.R, 6), round(pad.a1, 6), round(pad.lam, 6), round(pad.eta, 6)
(0.246932, 0.487805, -0.416551, 2.000805)
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from typing import Literal

import numpy as np

from asymslip_gen.edge_multipliers import shear_edge_multiplier_proportional
from asymslip_gen.lab_transfer import (
    flat_rounded_matched_radius,
    flat_rounded_multiplier_ratio,
    hertz_matched_half_width,
    hertz_matched_radius,
    matched_shear_slope,
    matched_tension_slope,
)

from ..errors import InputError
from ..laws.base import ContactLaw
from .rig import Geometry, Rig
from .signature import EdgeSignature

Order = Literal["second", "leading", "approximate"]


@dataclass(frozen=True)
class RigSolution:
    """A pad, its two loads and the path slopes in the edge's own frame, with its edge state."""

    geometry: Geometry
    P1: float
    P2: float
    lam: float
    eta: float
    a1: float
    a2: float
    state: EdgeSignature
    order: Order


@dataclass(frozen=True)
class LawPoint:
    """The rig law's quantities at a pair of loads (one call of ``cycle_state``)."""

    law: ContactLaw
    P1: float
    P2: float
    a1: float
    a2: float
    da: float
    L_I1: float
    L_I2: float


def law_point(law: ContactLaw, P1: float, dP: float) -> LawPoint | None:
    """a1, a2, a2 - a1 and L_I at both loads, or None where the law cannot carry them."""
    with np.errstate(all="ignore"):
        state = law.cycle_state(P1, dP)
    values = [float(state.a1), float(state.a2), float(state.da)]
    values += [float(state.L_I1), float(state.L_I2)]
    if not all(math.isfinite(value) and value > 0 for value in values):
        return None
    return LawPoint(law, P1, P1 + dP, *values)


def _columns(point: LawPoint) -> tuple[tuple[float, float], tuple[float, float]]:
    """L_II at states 1, 2 for unit lambda and for unit eta, by (21): L_II is linear in both."""
    lam_column = (
        float(shear_edge_multiplier_proportional(1.0, 0.0, point.a1, point.L_I1)),
        float(shear_edge_multiplier_proportional(1.0, 0.0, point.a2, point.L_I2)),
    )
    eta_column = (
        float(shear_edge_multiplier_proportional(0.0, 1.0, point.a1, point.L_I1)),
        float(shear_edge_multiplier_proportional(0.0, 1.0, point.a2, point.L_I2)),
    )
    return lam_column, eta_column


def exact_slopes(point: LawPoint, target: EdgeSignature) -> tuple[float, float]:
    """lambda, eta that give the rig's edge the target's L_II1 and L_II2 (LT4)."""
    args = (point.da, point.L_I1, point.L_I2, target.L_II1, target.L_II2)
    eta = float(matched_tension_slope(*args))
    lam = float(matched_shear_slope(point.a1, *args))
    return lam, eta


def edge_signature(point: LawPoint, mu: float, lam: float, eta: float) -> EdgeSignature:
    """The rig edge's state for path slopes lambda, eta, by (21)."""
    L_II1 = float(shear_edge_multiplier_proportional(lam, eta, point.a1, point.L_I1))
    L_II2 = float(shear_edge_multiplier_proportional(lam, eta, point.a2, point.L_I2))
    return EdgeSignature(mu, point.L_I1, point.L_I2, L_II1, L_II2, point.da)


def best_slopes(point: LawPoint, target: EdgeSignature, rig: Rig) -> tuple[float, float]:
    """The slopes (lambda, eta) nearest the target's L_II within the rig's limits.

    Least squares on the two L_II mismatches of the measure (each in units of mu L_I of the
    target), with |dQ| <= 2 max_Q and |dsigma| <= 2 max_sigma (the mean of each is free), and
    eta = 0 without bulk tension.
    """
    dP = point.P2 - point.P1
    lam_max = 2 * rig.max_Q / dP
    eta_max = 2 * rig.max_sigma / dP if rig.tension else 0.0
    scale = (target.mu * target.L_I1, target.mu * target.L_I2)
    lam_column, eta_column = _columns(point)
    A = np.array([[lam_column[k] / scale[k], eta_column[k] / scale[k]] for k in range(2)])
    y = np.array([target.L_II1 / scale[0], target.L_II2 / scale[1]])

    def cost(lam: float, eta: float) -> float:
        return float(np.sum((A @ np.array([lam, eta]) - y) ** 2))

    def fit_one(column: int, fixed: float) -> float:
        """The best value of one slope with the other fixed, clipped to its limit."""
        other = 1 - column
        rest = y - A[:, other] * fixed
        value = float(A[:, column] @ rest / (A[:, column] @ A[:, column]))
        bound = lam_max if column == 0 else eta_max
        return min(max(value, -bound), bound)

    candidates: list[tuple[float, float]] = []
    if eta_max > 0:
        lam, eta = exact_slopes(point, target)
        if abs(lam) <= lam_max and abs(eta) <= eta_max:
            return lam, eta
        for eta_fixed in (-eta_max, eta_max):
            candidates.append((fit_one(0, eta_fixed), eta_fixed))
        for lam_fixed in (-lam_max, lam_max):
            candidates.append((lam_fixed, fit_one(1, lam_fixed)))
    candidates.append((fit_one(0, 0.0), 0.0))
    return min(candidates, key=lambda pair: cost(*pair))


def _bisect(function: Callable[[float], float], low: float, high: float) -> float:
    """The root of an increasing ``function`` on [low, high] (a sign change), to rounding."""
    for _ in range(200):
        middle = 0.5 * (low + high)
        if middle in (low, high):
            break
        if function(middle) > 0:
            high = middle
        else:
            low = middle
    return 0.5 * (low + high)


def _solution(
    rig: Rig, geometry: Geometry, a1: float, da: float, target: EdgeSignature, order: Order
) -> RigSolution | None:
    """The pad at half-widths a1, a1 + da with the exact slopes of LT4."""
    law = rig.law(geometry)
    P1 = float(law.load(a1))
    dP = float(law.load_difference(a1, da))
    point = law_point(law, P1, dP)
    if point is None:
        return None
    lam, eta = exact_slopes(point, target)
    state = edge_signature(point, target.mu, lam, eta)
    return RigSolution(geometry, P1, point.P2, lam, eta, point.a1, point.a2, state, order)


def exact_hertz(rig: Rig, target: EdgeSignature) -> RigSolution | str:
    """The one cylinder of LT3, or why there is none."""
    if not target.L_I2 > target.L_I1:
        return (
            "the prototype's L_I does not rise along the path (L_I2 <= L_I1), and a "
            "cylinder's always does (LT3)"
        )
    a1 = float(hertz_matched_half_width(target.L_I1, target.L_I2, target.da))
    R = float(hertz_matched_radius(rig.E_star, target.L_I1, a1))
    solution = _solution(rig, Geometry(R), a1, target.da, target, "leading")
    return solution if solution is not None else "the matching cylinder is out of range"


def _flat_for_ratio(a1: float, a2: float, ratio: float) -> float | None:
    """c in [0, a1) whose rounded flat has L_I2/L_I1 = ratio between a1 and a2 (LT5)."""
    if not float(flat_rounded_multiplier_ratio(a1, a2, 0.0)) <= ratio:
        return None
    return _bisect(lambda c: float(flat_rounded_multiplier_ratio(a1, a2, c)) - ratio, 0.0, a1)


def _half_width_for_ratio(c: float, da: float, ratio: float) -> float | None:
    """a1 > c at which a rounded flat of flat half-width c has L_I2/L_I1 = ratio over da."""
    if not ratio > 1:
        return None

    def excess(a1: float) -> float:  # decreasing in a1: negate for the increasing bisection
        return ratio - float(flat_rounded_multiplier_ratio(a1, a1 + da, c))

    low = c * (1 + 1e-12) if c > 0 else da * 1e-9
    high = max(2 * c, da)
    for _ in range(200):
        if excess(high) > 0:
            break
        high *= 2
    else:
        return None
    return _bisect(excess, low, high)


def exact_flat_rounded(rig: Rig, target: EdgeSignature, a1: float) -> RigSolution | str:
    """The rounded flat at the prototype's own half-widths (LT5), else the nearest c's pad."""
    ratio = target.L_I2 / target.L_I1
    flat = _flat_for_ratio(a1, a1 + target.da, ratio)
    if flat is not None and rig.flat_half_width.contains(flat):
        R = float(flat_rounded_matched_radius(a1, flat, rig.E_star, target.L_I1))
        solution = _solution(rig, Geometry(R, flat), a1, target.da, target, "second")
        if solution is not None:
            return solution
    # The second-order pad is out of reach: the c's within reach, each with its own a1.
    available = rig.flat_half_width
    flats = (
        list(available.values)
        if available.values is not None
        else sorted({available.clip(flat if flat is not None else 0.0), available.low})
    )
    found = []
    for c in flats:
        half_width = _half_width_for_ratio(c, target.da, ratio)
        if half_width is None:
            continue
        R = float(flat_rounded_matched_radius(half_width, c, rig.E_star, target.L_I1))
        solution = _solution(rig, Geometry(R, c), half_width, target.da, target, "leading")
        if solution is not None:
            found.append(solution)
    if not found:
        return (
            "no rounded flat within reach has the prototype's rise of L_I along the path "
            f"(L_I2/L_I1 = {ratio:.6g})"
        )
    return min(found, key=lambda solution: abs(math.log(solution.a1 / a1)))


# --- the closest rig cycle ---------------------------------------------------------------------


def _geometries(rig: Rig) -> Iterator[tuple[Geometry, list[int]]]:
    """Each fixed combination of listed dimensions, and which of (R, c) stay free (0, 1)."""
    radii = rig.radius.values or (None,)
    flats = (0.0,) if rig.family == "hertz" else (rig.flat_half_width.values or (None,))
    for R in radii:
        for c in flats:
            free = [k for k, value in ((0, R), (1, c)) if value is None]
            yield Geometry(R if R is not None else math.nan, c if c is not None else math.nan), free


def closest(
    rig: Rig, target: EdgeSignature, start: RigSolution | None, a1_target: float
) -> RigSolution:
    """The pad, loads and slopes within the rig's limits nearest the target edge state."""
    try:
        from scipy.optimize import least_squares
    except ImportError:
        raise InputError(
            "rig",
            "this prototype is out of the rig's exact reach, and the closest match needs "
            "SciPy's least squares: install the 'special' extra (pip install "
            "'asymslip[special]')",
        ) from None
    best: RigSolution | None = None
    best_distance = math.inf
    for fixed, free in _geometries(rig):

        def unpack(
            x: np.ndarray, fixed: Geometry = fixed, free: list[int] = free
        ) -> tuple[Geometry, float, float]:
            values = [fixed.R, fixed.c]
            for k, index in zip(free, range(len(free)), strict=True):
                values[k] = math.exp(x[index]) if k == 0 else float(x[index])
            P2 = math.exp(x[len(free)])
            growth = math.exp(x[len(free) + 1])  # dP/P1
            P1 = P2 / (1 + growth)
            return Geometry(values[0], values[1]), P1, P2 - P1

        def evaluate(x: np.ndarray) -> tuple[RigSolution | None, np.ndarray]:
            geometry, P1, dP = unpack(x)
            point = law_point(rig.law(geometry), P1, dP)
            if point is None:
                return None, np.full(5, 1e3)
            lam, eta = best_slopes(point, target, rig)
            state = edge_signature(point, target.mu, lam, eta)
            solution = RigSolution(
                geometry, P1, point.P2, lam, eta, point.a1, point.a2, state, "approximate"
            )
            return solution, np.array(state.mismatch(target))

        lower, upper, x0 = _bounds_and_start(rig, fixed, free, target, start, a1_target)
        for x_start in _starts(x0, lower, upper, len(free)):
            fit = least_squares(
                lambda x: evaluate(x)[1],
                x_start,
                bounds=(lower, upper),
                x_scale="jac",
                ftol=1e-15,
                xtol=1e-15,
                gtol=1e-15,
                max_nfev=400,
            )
            solution, residual = evaluate(fit.x)
            distance = float(np.sqrt(np.sum(residual**2)))
            if solution is not None and distance < best_distance:
                best, best_distance = solution, distance
    if best is None:
        raise InputError("rig", "no pad and loads within the rig's limits carry a contact")
    return best


def _bounds_and_start(
    rig: Rig,
    fixed: Geometry,
    free: list[int],
    target: EdgeSignature,
    start: RigSolution | None,
    a1_target: float,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Bounds on (ln R, c, ln P2, ln(dP/P1)) (the free ones) and a start inside them."""
    lower: list[float] = []
    upper: list[float] = []
    x0: list[float] = []
    if start is not None:
        geometry, P2, growth = start.geometry, start.P2, (start.P2 - start.P1) / start.P1
    else:  # a cylinder with the prototype's a1 and L_I1, its load grown to advance the edge da
        R = float(hertz_matched_radius(rig.E_star, target.L_I1, a1_target))
        R = fixed.R if not math.isnan(fixed.R) else rig.radius.clip(R)
        c = 0.0 if rig.family == "hertz" else fixed.c
        c = rig.flat_half_width.clip(0.0) if math.isnan(c) else c
        geometry = Geometry(R, c)
        a1 = max(a1_target, 1.2 * c)
        law = rig.law(geometry)
        P1 = float(law.load(a1))
        dP = float(law.load_difference(a1, target.da))
        P2, growth = P1 + dP, dP / P1
    if 0 in free:
        lower.append(math.log(rig.radius.low) if rig.radius.low > 0 else -np.inf)
        upper.append(math.log(rig.radius.high) if math.isfinite(rig.radius.high) else np.inf)
        x0.append(math.log(geometry.R))
    if 1 in free:
        lower.append(rig.flat_half_width.low)
        upper.append(rig.flat_half_width.high)
        x0.append(geometry.c)
    lower += [-np.inf, -np.inf]
    upper += [math.log(rig.max_P) if math.isfinite(rig.max_P) else np.inf, np.inf]
    x0 += [math.log(P2), math.log(growth)]
    low, high = np.array(lower), np.array(upper)
    inside = np.clip(np.array(x0), low, high)
    # least_squares wants a strictly interior start.
    span = np.where(np.isfinite(high - low), high - low, 1.0)
    inside = np.clip(inside, low + 1e-9 * span, high - 1e-9 * span)
    return low, high, inside


def _starts(
    x0: np.ndarray, lower: np.ndarray, upper: np.ndarray, free: int
) -> Iterator[np.ndarray]:
    """The start and two with the load change halved and doubled (the mismatch is not convex)."""
    yield x0
    for change in (-math.log(2), math.log(2)):
        x = x0.copy()
        x[free + 1] += change
        yield np.clip(x, lower, upper)
