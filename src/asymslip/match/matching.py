"""``match``: the laboratory rig cycle whose contact edge reproduces a prototype's."""

from __future__ import annotations

import math
from typing import Literal

from numpy.typing import ArrayLike

from asymslip_gen.edge_stress import edge_uniform_sxx

from ..cycle import LoadCycle
from ..errors import InputError, as_float_array
from ..laws.base import ContactLaw
from ..slip_zones import SlipZoneResult, slip_zone
from .result import MatchResult, Mismatch, Pair
from .rig import Rig
from .signature import QUANTITIES, EdgeSignature
from .solutions import RigSolution, closest, exact_flat_rounded, exact_hertz

#: Largest mismatch (each component of the measure) of an exact match: the round trip through
#: ``slip_zone`` reproduces every quantity to this relative accuracy.
EXACT = 1e-9

#: Largest edge-state mismatch of an answer: beyond it (an order-one change of a multiplier)
#: no rig within the limits reproduces the edge, and the closest is refused, not offered.
FARTHEST = 0.5

Edge = Literal["right", "left"]


def _scalar(name: str, value: ArrayLike) -> float:
    array = as_float_array(name, value)
    if array.ndim:
        raise InputError(name, "match takes one cycle (a number, not an array)")
    return float(array)


def _prototype_state(
    law: ContactLaw, cycle: LoadCycle, mu: float, edge: Edge
) -> tuple[SlipZoneResult, EdgeSignature]:
    if cycle.shape != ():
        raise InputError("cycle", "match takes one cycle (numbers, not arrays)")
    result = slip_zone(law, cycle, mu, edge=edge)
    if result.slip_direction == 0:
        raise InputError(
            "edge",
            f"the prototype's {edge} edge does not slip in this cycle (|L_II2| <= mu L_I2): "
            "there is no slip zone to reproduce",
            edge,
        )
    P1 = float(cycle.P1)
    dP = float(cycle.P2) - P1
    # a2 - a1 from the law's cancellation-free growth, not the difference of two half-widths.
    da = float(law.for_edge(edge).cycle_state(P1, dP).da)
    state = EdgeSignature(
        mu,
        float(result.L_I1),
        float(result.L_I2),
        float(result.L_II1),
        float(result.L_II2),
        da,
    )
    return result, state


def _limits_broken(rig: Rig, solution: RigSolution) -> list[str]:
    """Why an exact solution is out of the rig's reach (nothing if it is within)."""
    reasons = []
    geometry = solution.geometry
    if not rig.admits(geometry):
        pad = f"R = {geometry.R:.6g}" + (
            f", c = {geometry.c:.6g}" if rig.family == "flat-rounded" else ""
        )
        reasons.append(f"the matching pad ({pad}) is not available ({rig.limits_text()})")
    if solution.P2 > rig.max_P:
        reasons.append(
            f"the matching load P2 = {solution.P2:.6g} exceeds the rig's largest {rig.max_P:g}"
        )
    dP = solution.P2 - solution.P1
    if solution.eta != 0 and not rig.tension:
        reasons.append(
            f"the match needs bulk tension (eta = {solution.eta:.6g}), which the rig cannot apply"
        )
    elif abs(solution.eta) * dP > 2 * rig.max_sigma:
        reasons.append(
            f"the match needs a tension change of {abs(solution.eta) * dP:.6g}, more than "
            f"twice the rig's largest |sigma| {rig.max_sigma:g}"
        )
    if abs(solution.lam) * dP > 2 * rig.max_Q:
        reasons.append(
            f"the match needs a shear-force change of {abs(solution.lam) * dP:.6g}, more than "
            f"twice the rig's largest |Q| {rig.max_Q:g}"
        )
    return reasons


def _without_vanishing_tension(solution: RigSolution, target: EdgeSignature) -> RigSolution:
    """eta of rounding size (a prototype without tension) set to zero."""
    ratio = max(abs(target.L_II1 / target.L_I1), abs(target.L_II2 / target.L_I2), target.mu)
    if abs(math.pi * solution.eta * solution.a2 / 4) <= 1e-12 * ratio:
        from dataclasses import replace

        return replace(solution, eta=0.0)
    return solution


def rig_cycle(solution: RigSolution, mu: float, rig: Rig, edge: Edge) -> tuple[LoadCycle, float]:
    """The rig's cycle and its margin against gross sliding.

    The slopes fix the changes of Q and sigma; their means are free.  The mean tension is zero
    (the smallest |sigma|); the mean shear force makes the two states equally far from gross
    sliding, Q1 = -dQ P1/(P1 + P2), which maximises min_i (1 - |Q_i|/(mu P_i)) (the two are
    equal there, 1 - |dQ|/(mu (P1 + P2))), shifted where the rig's |Q| limit requires.  Seen
    from the left edge Q changes sign (derivations/edge_symmetry.py).
    """
    P1, P2 = solution.P1, solution.P2
    dP = P2 - P1
    dQ = (1.0 if edge == "right" else -1.0) * solution.lam * dP
    dsigma = solution.eta * dP
    Q1 = -dQ * P1 / (P1 + P2)
    Q2 = Q1 + dQ
    if abs(Q2) > rig.max_Q:
        Q2 = math.copysign(rig.max_Q, dQ)
        Q1 = Q2 - dQ
    margin = min(1 - abs(Q1) / (mu * P1), 1 - abs(Q2) / (mu * P2))
    if not margin > 0:
        raise InputError(
            "rig",
            f"every rig cycle with these loads slides grossly: the shear-force change "
            f"|Q2 - Q1| = {abs(dQ):.6g} is at least mu (P1 + P2) = {mu * (P1 + P2):.6g} "
            "(or the rig's |Q| limit leaves no room)",
        )
    # + 0.0: no tension is 0, not -0.
    return LoadCycle(P1, Q1, P2, Q2, -dsigma / 2 + 0.0, dsigma / 2 + 0.0), margin


def _unbounded(rig: Rig) -> bool:
    """True when the rig's pads and loads may grow without bound."""
    radius = rig.radius.values is None and math.isinf(rig.radius.high)
    flat = rig.family == "hertz" or (
        rig.flat_half_width.values is None and math.isinf(rig.flat_half_width.high)
    )
    return radius and flat and math.isinf(rig.max_P)


def _first_order_accuracy(result: SlipZoneResult) -> float:
    """2 (da/a1) |a1 - b| of one contact: the accuracy of a first-order width."""
    a1 = float(result.a1)
    return 2 * (float(result.a2) - a1) / a1 * abs(float(result.slip_zone_width))


def _uniform_sxx(cycle: LoadCycle) -> float:
    """The near-edge amplitude's uniform sxx of a cycle (EA-3)."""
    return float(edge_uniform_sxx(float(cycle.sigma2) - float(cycle.sigma1)))


def match(
    law: ContactLaw,
    cycle: LoadCycle,
    mu: float,
    rig: Rig,
    *,
    edge: Edge = "right",
) -> MatchResult:
    """Design the laboratory test whose contact edge reproduces the prototype's.

    Parameters
    ----------
    law
        The prototype's contact law, any that ``slip_zone`` takes (built-in, table, module,
        calibrated -- an asymmetric contact's edges each with their own law).
    cycle
        The prototype's load cycle (one, not arrays).
    mu
        The prototype's coefficient of friction.
    rig
        The rig: pad family, material and limits (:class:`~asymslip.match.Rig`).
    edge
        The prototype's edge to reproduce, ``"right"`` or ``"left"``; the rig's same edge
        reproduces it.

    Returns
    -------
    MatchResult
        The rig's pad and cycle, the quantities side by side, the validity measures (24)-(27)
        and slip-zone widths of both contacts with their accuracies, the match's order and
        stated accuracy, each quantity's mismatch and its effect.

    Raises
    ------
    InputError
        The prototype's cycle is invalid or its edge does not slip; the rig's limits are
        invalid; every rig cycle slides grossly; the rig's cycle is not a steady partial-slip
        state.

    Examples
    --------
    >>> from asymslip import FlatRoundedLaw, LoadCycle
    >>> from asymslip.match import Rig, match
    >>> blade = FlatRoundedLaw(c=1.0, R=10.0, E_star=1.0)
    >>> result = match(blade, LoadCycle(0.5, 0.0, 0.52, 0.04, 0.0, 0.002), 0.3, Rig("hertz", 1.0))
    >>> result.exact, result.order, round(result.geometry.R, 3)
    (True, 'leading', 10.147)
    >>> round(float(result.cycle.P1), 4), round(float(result.cycle.P2), 4)
    (0.3487, 0.3649)
    """
    if edge not in ("right", "left"):
        raise InputError("edge", "must be 'right' or 'left'", edge)
    mu = _scalar("mu", mu)
    prototype, prototype_state = _prototype_state(law, cycle, mu, edge)
    mu_rig = rig.mu if rig.mu is not None else mu
    target = prototype_state.for_friction(mu_rig)
    a1 = float(prototype.a1)
    if not target.L_I2 > target.L_I1 and _unbounded(rig):
        raise InputError(
            "law",
            f"the prototype's L_I does not rise along the path at its {edge} edge (L_I2/L_I1 = "
            f"{target.L_I2 / target.L_I1:.6g}), and every rig pad's does: no rig reproduces "
            "this edge, and the nearest pad would be infinitely large (bound the rig's radius "
            "or load for the closest within them)",
        )
    exact = (
        exact_hertz(rig, target) if rig.family == "hertz" else exact_flat_rounded(rig, target, a1)
    )
    reasons: list[str] = []
    start: RigSolution | None = None
    solution: RigSolution | None = None
    if isinstance(exact, str):
        reasons.append(exact)
    else:
        exact = _without_vanishing_tension(exact, target)
        reasons = _limits_broken(rig, exact)
        start, solution = exact, (None if reasons else exact)
    if solution is None:
        solution = closest(rig, target, start, a1)
        distance = solution.state.distance(target)
        if not distance <= FARTHEST:
            raise InputError(
                "rig",
                f"no rig within its limits ({rig.limits_text()}) comes near this edge: the "
                f"closest differs by an edge-state mismatch of {distance:.3g} (more than "
                f"{FARTHEST:g}); " + "; ".join(reasons),
            )
    rig_law = rig.law(solution.geometry)
    cycle_rig, margin = rig_cycle(solution, mu_rig, rig, edge)
    try:
        rig_result = slip_zone(rig_law, cycle_rig, mu_rig, edge=edge)
    except InputError as error:
        raise InputError(
            "rig", f"the closest rig cycle is not a steady partial-slip state: {error}"
        ) from None
    return _assemble(
        rig,
        solution,
        rig_law,
        mu_rig,
        cycle_rig,
        edge,
        prototype,
        prototype_state,
        rig_result,
        target,
        margin,
        reasons,
        law,
        cycle,
    )


def _assemble(
    rig: Rig,
    solution: RigSolution,
    rig_law: ContactLaw,
    mu_rig: float,
    cycle_rig: LoadCycle,
    edge: Edge,
    prototype: SlipZoneResult,
    prototype_state: EdgeSignature,
    rig_result: SlipZoneResult,
    target: EdgeSignature,
    margin: float,
    reasons: list[str],
    prototype_law: ContactLaw,
    prototype_cycle: LoadCycle,
) -> MatchResult:
    da_rig = float(rig_law.cycle_state(solution.P1, solution.P2 - solution.P1).da)
    rig_state = EdgeSignature(
        mu_rig,
        float(rig_result.L_I1),
        float(rig_result.L_I2),
        float(rig_result.L_II1),
        float(rig_result.L_II2),
        da_rig,
    )
    components = rig_state.mismatch(target)
    matches = all(abs(value) <= EXACT for value in components)
    same_friction = mu_rig == prototype_state.mu
    mismatches = []
    for quantity, value in zip(QUANTITIES, components, strict=True):
        alone = target.with_value(quantity, rig_state.value(quantity))
        mismatches.append(
            Mismatch(
                quantity,
                value,
                alone.width / target.width - 1,
                alone.peak_shear_change / target.peak_shear_change - 1,
            )
        )
    unmatched = [
        f"{item.quantity}: mismatch {item.mismatch:+.3g} (slip-zone width "
        f"{item.width_change:+.3g}, peak shear change {item.peak_change:+.3g}, relative)"
        for item in mismatches
        if abs(item.mismatch) > EXACT
    ]
    unmatched += reasons if not matches else []
    if not same_friction:
        unmatched.append(
            f"L_I1, L_I2: the rig's mu = {mu_rig:g} differs from the prototype's "
            f"{prototype_state.mu:g}; mu L_I, the shear change and the slip zone are matched, "
            "the pressure is not"
        )
    order = solution.order if matches else "approximate"
    first_order = Pair(_first_order_accuracy(prototype), _first_order_accuracy(rig_result))
    if order == "second":
        accuracy = float(prototype.b_accuracy) + float(rig_result.b_accuracy)
        width_accuracy = Pair(float(prototype.b_accuracy), float(rig_result.b_accuracy))
    else:
        accuracy = first_order.prototype + first_order.rig
        width_accuracy = first_order
    warnings = [f"prototype: {text}" for text in prototype.warnings]
    warnings += [f"rig: {text}" for text in rig_result.warnings]
    width = Pair(float(prototype.slip_zone_width), float(rig_result.slip_zone_width))
    if matches and abs(width.rig - width.prototype) > accuracy:
        warnings.append(
            f"the headline slip-zone widths differ by {abs(width.rig - width.prototype):.3g}, "
            f"more than the match's stated accuracy {accuracy:.3g}"
        )
    uniform = Pair(_uniform_sxx(prototype_cycle), _uniform_sxx(cycle_rig))
    if abs(uniform.rig - uniform.prototype) > EXACT * max(abs(uniform.prototype), abs(uniform.rig)):
        # The edge signature fixes eta, not the load change: dsigma = eta dP is the rig's own.
        warnings.append(
            "the near-edge stress amplitude's uniform sxx, dsigma/2 (EA-3: the stick zone's "
            f"strain compatibility), is not part of the edge match: prototype "
            f"{uniform.prototype:.4g}, rig {uniform.rig:.4g}"
        )
    if not hasattr(prototype.law, "E_star") or getattr(prototype.law, "E_star", None) != rig.E_star:
        warnings.append(
            "the slip scales as 1/E*: the rig's slip equals the prototype's only where their "
            "E* are equal (the shear change and slip zone do not depend on E*)"
        )
    matched = {
        "L_I1": Pair(prototype_state.L_I1, rig_state.L_I1),
        "L_I2": Pair(prototype_state.L_I2, rig_state.L_I2),
        "L_II1": Pair(prototype_state.L_II1, rig_state.L_II1),
        "L_II2": Pair(prototype_state.L_II2, rig_state.L_II2),
        "a2_minus_a1": Pair(prototype_state.da, rig_state.da),
        "slip_zone_width": width,
    }
    return MatchResult(
        rig=rig,
        geometry=solution.geometry,
        law=rig_law,
        mu=mu_rig,
        cycle=cycle_rig,
        edge=edge,
        prototype=prototype,
        rig_result=rig_result,
        matched=matched,
        width_accuracy=width_accuracy,
        peak_shear_change=Pair(prototype_state.peak_shear_change, rig_state.peak_shear_change),
        exact=matches and same_friction,
        order=order,
        measure=rig_state.distance(target),
        mismatches=tuple(mismatches),
        accuracy=accuracy,
        margin=margin,
        unmatched=tuple(unmatched),
        warnings=tuple(warnings),
        prototype_law=prototype_law,
        prototype_cycle=prototype_cycle,
        prototype_state=prototype_state,
        rig_state=rig_state,
    )
