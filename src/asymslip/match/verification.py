"""``match --verify``: both contacts solved by the reference solver, compared at the edge.

The prototype and the rig are solved to their steady states (:func:`asymslip.solver.solve`),
the rig on elements of the prototype's size.  In the edge's own coordinate s (distance from the
state-2 edge, each solver's own) the shear-traction change q2 - q1 and the slip on loading of
the rig are interpolated (linearly) onto the prototype's element centres in its slip zone (less
one element at each end, where an edge or a stick boundary falls inside an element) and the
largest differences reported, relative to the prototype's largest |q2 - q1| and |slip|
there; the solvers' slip-zone widths a1 - b are compared against the match's stated accuracy
plus two elements of each solve (plus, for an approximate match, the asymptotic difference of
the two widths that the mismatch causes).  Where the asymptotic match is exact the two
solutions still differ by the next terms of the edge expansions (4), (5), of relative size up to
(a2 - b)/a1 at the far end of the slip zone: the ``expansion_allowance``, the larger of the two
contacts'.  The near-edge stress amplitude (state 2 minus state 1) is compared from both
sources of :mod:`asymslip.stress`, the edge asymptotes and the solvers' fields, at points about
each contact's own edge (:mod:`.near_edge_stress`).

Examples
--------
>>> from asymslip import FlatRoundedLaw, LoadCycle
>>> from asymslip.match import Rig, match, verify
>>> blade = FlatRoundedLaw(c=1.0, R=10.0, E_star=1.0)
>>> result = match(blade, LoadCycle(0.5, 0.0, 0.52, 0.04, 0.0, 0.002), 0.3, Rig("hertz", 1.0))
>>> check = verify(result, elements=300)
>>> check.widths_agree, check.prototype.elements, check.rig.elements
(True, 300, 193)
>>> [(item.source, item.within_stated_accuracy) for item in check.stress]
[('asymptote', True), ('solver', True)]
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from ..errors import InputError
from ..solver.result import Edge
from .near_edge_stress import StressComparison, asymptotic_amplitudes, solver_comparison
from .result import MatchResult, Pair

if TYPE_CHECKING:
    from ..stress.field import StressField

FloatArray = NDArray[np.float64]

#: Margin of the rig's computational domain beyond its largest contact, as the solver's own.
DOMAIN_MARGIN = 0.03


@dataclass(frozen=True)
class SolverProblem:
    """The prototype as the reference solver sees it, where its law has no profile.

    ``contact``: a built-in law or a :class:`asymslip.solver.Profile`; ``loading``: a
    :class:`~asymslip.LoadCycle` or a :class:`asymslip.solver.LoadPath` whose first two points
    are states 1 and 2 of the matched cycle (a moment may vary along it); ``E_star`` for a
    profile; ``domain`` the solver's (left, right), or None for its own choice.
    """

    contact: Any
    loading: Any
    E_star: float | None = None
    domain: tuple[float, float] | None = None


@dataclass(frozen=True)
class SolvedEdge:
    """One contact's edge as the solver found it, in the edge's own coordinate."""

    width: float  # a1 - b
    width_error: float
    reach: float  # a2 - b: the slip zone at state 2, from the edge
    element: float
    elements: int
    seconds: float
    s: FloatArray  # distance from the state-2 edge of each element centre
    q_diff: FloatArray  # q2 - q1 at the centres
    slip: FloatArray  # slip on loading (state 1 to 2) at the centres
    a2: float = math.nan  # the state-2 edge, outward from the centre
    solution: Any = field(default=None, repr=False, compare=False)  # the SolverResult

    def to_dict(self) -> dict[str, float | int]:
        return {
            "slip_zone_width": self.width,
            "slip_zone_width_error": self.width_error,
            "element_size": self.element,
            "elements": self.elements,
            "seconds": self.seconds,
        }


@dataclass(frozen=True)
class Verification:
    """The two solves side by side (see the module's docstring)."""

    prototype: SolvedEdge
    rig: SolvedEdge
    width_difference: float
    width_allowed: float
    shear_change_difference: float
    slip_difference: float
    compared_points: int
    expansion_allowance: float
    stress: tuple[StressComparison, ...] = ()

    @property
    def shear_change_peak(self) -> Pair:
        """The largest |q2 - q1| of each solve over its own slip zone."""
        return Pair(_peak(self.prototype, "q_diff"), _peak(self.rig, "q_diff"))

    @property
    def slip_peak(self) -> Pair:
        """The largest |slip| on loading of each solve over its own slip zone."""
        return Pair(_peak(self.prototype, "slip"), _peak(self.rig, "slip"))

    @property
    def widths_agree(self) -> bool:
        return abs(self.width_difference) <= self.width_allowed

    def to_dict(self) -> dict[str, object]:
        return {
            "prototype": self.prototype.to_dict(),
            "rig": self.rig.to_dict(),
            "slip_zone_width_difference": self.width_difference,
            "slip_zone_width_allowed": self.width_allowed,
            "widths_agree": self.widths_agree,
            "shear_change_difference": self.shear_change_difference,
            "slip_difference": self.slip_difference,
            "shear_change_peak": {
                "prototype": self.shear_change_peak.prototype,
                "rig": self.shear_change_peak.rig,
            },
            "slip_peak": {"prototype": self.slip_peak.prototype, "rig": self.slip_peak.rig},
            "compared_points": self.compared_points,
            "expansion_allowance": self.expansion_allowance,
            "stress_amplitude": {item.source: item.to_dict() for item in self.stress},
        }


def solve_edge(
    contact: Any,
    loading: Any,
    mu: float,
    side: Edge,
    elements: int,
    E_star: float | None,
    domain: tuple[float, float] | None,
) -> SolvedEdge:
    from ..solver import solve

    result = solve(contact, loading, mu, elements=elements, E_star=E_star, domain=domain)
    if not result.steady:
        raise InputError("verify", "the reference solver did not reach the steady state")
    first, second = result.states[0], result.states[1]
    edge = result.edge(side)
    if edge.b is None or edge.b_error is None:
        raise InputError("verify", f"the solver finds no stick zone at the {side} edge")
    a1, a2 = first.edge(side).a, second.edge(side).a
    orientation = 1.0 if side == "right" else -1.0
    return SolvedEdge(
        width=a1 - edge.b,
        width_error=edge.b_error + first.edge(side).a_error,
        reach=a2 - edge.b,
        element=result.element_size,
        elements=result.elements,
        seconds=result.seconds,
        s=a2 - orientation * result.x,
        q_diff=second.shear - first.shear,
        slip=second.slip - first.slip,
        a2=a2,
        solution=result,
    )


def _peak(solved: SolvedEdge, values: str) -> float:
    """max |values| over the element centres of the solve's slip zone, 0 < s < a2 - b."""
    inside = (solved.s > 0) & (solved.s < solved.reach)
    chosen: FloatArray = getattr(solved, values)[inside]
    return float(np.max(np.abs(chosen))) if chosen.size else math.nan


def compared(prototype: SolvedEdge, rig: SolvedEdge) -> NDArray[np.bool_]:
    """The prototype's element centres compared: its slip zone less one element (the larger of
    the two solves') at each end, where the contact edge and the stick boundary each fall
    somewhere inside an element and the element values there are not comparable."""
    trim = max(prototype.element, rig.element)
    return (prototype.s > trim) & (prototype.s < prototype.reach - trim)


def largest_difference(prototype: SolvedEdge, rig: SolvedEdge, values: str) -> float:
    """max |rig - prototype| over the compared centres (``compared``) / max |prototype|
    there, the rig's ``values`` ("q_diff" or "slip") interpolated linearly in s onto the
    prototype's centres."""
    inside = compared(prototype, rig)
    order = np.argsort(rig.s)
    mine = getattr(prototype, values)[inside]
    theirs = np.interp(prototype.s[inside], rig.s[order], getattr(rig, values)[order])
    scale = float(np.max(np.abs(mine)))
    return float(np.max(np.abs(theirs - mine)) / scale) if scale > 0 else math.inf


def verify(
    result: MatchResult,
    prototype: SolverProblem | None = None,
    *,
    elements: int = 2000,
) -> Verification:
    """Solve the prototype and the rig with the reference solver and compare their edges.

    Parameters
    ----------
    result
        What :func:`~asymslip.match.match` answered.
    prototype
        The prototype for the solver; None for a built-in law, whose profile the solver takes,
        under the matched cycle.
    elements
        Elements of the prototype's solve; the rig's are sized to the same element length.

    Returns
    -------
    Verification
    """
    if prototype is None:
        law = result.prototype_law
        if not hasattr(law, "profile"):
            raise InputError(
                "verify",
                f"the {getattr(law, 'name', 'prototype')} law has no profile for the solver: "
                "give the prototype's profile (and its load path)",
            )
        prototype = SolverProblem(law, result.prototype_cycle)
    side = result.edge
    solved = solve_edge(
        prototype.contact,
        prototype.loading,
        result.prototype_state.mu,
        side,
        elements,
        prototype.E_star,
        prototype.domain,
    )
    a2 = float(result.rig_result.a2)
    reach = (1 + DOMAIN_MARGIN) * a2
    # Elements of the prototype's size, but at least the solver's minimum.
    rig_elements = max(64, math.ceil(2 * reach / solved.element))
    solved_rig = solve_edge(
        result.law, result.cycle, result.mu, side, rig_elements, None, (-reach, reach)
    )
    expected = abs(result.rig_state.width - result.prototype_state.width)
    asymptotes = asymptotic_amplitudes(result)
    amplitudes = [
        _solver_amplitude(solved, asymptotes.grid.global_x(solved.a2, side), asymptotes.grid.depth)
        for solved in (solved, solved_rig)
    ]
    return Verification(
        prototype=solved,
        rig=solved_rig,
        width_difference=solved_rig.width - solved.width,
        width_allowed=result.accuracy + expected + 2 * solved.element + 2 * solved_rig.element,
        shear_change_difference=largest_difference(solved, solved_rig, "q_diff"),
        slip_difference=largest_difference(solved, solved_rig, "slip"),
        compared_points=int(np.count_nonzero(compared(solved, solved_rig))),
        expansion_allowance=max(
            _slip_zone_reach(result.prototype), _slip_zone_reach(result.rig_result)
        ),
        stress=(asymptotes.comparison, solver_comparison(asymptotes, *amplitudes)),
    )


def _solver_amplitude(solved: SolvedEdge, x: FloatArray, depth: FloatArray) -> StressField:
    """The solver's amplitude, state 2 minus state 1, at the points: for a load path (a
    prototype under a moment) its first two points, the matched cycle's states 1 and 2."""
    from ..stress.solver_source import solver_stress

    field = solver_stress(solved.solution, x, depth)
    if field.amplitude is not None:
        return field.amplitude
    return field.states[1] - field.states[0]


def _slip_zone_reach(edge: Any) -> float:
    """(a2 - b)/a1: the relative size of the first neglected terms of the edge expansions (4),
    (5) at the far end of the slip zone (for Hertz, (a - x)/(4a) of it)."""
    return (float(edge.a2) - float(edge.b)) / float(edge.a1)


__all__ = [
    "SolvedEdge",
    "SolverProblem",
    "Verification",
    "largest_difference",
    "solve_edge",
    "verify",
]
