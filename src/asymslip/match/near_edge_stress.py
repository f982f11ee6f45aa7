"""``match --verify``: the near-edge stress amplitude of the prototype and the rig side by side.

Two edges that share mu, L_I1, L_I2, L_II1, L_II2 and a2 - a1 share the square-root loads of
the amplitude (state 2 minus state 1) near the edge -- the pressure change (4) and the shear
change (49) with its stick boundary (17) -- and so its field (:mod:`asymslip.stress.asymptote`).
What they need not share is the amplitude's uniform sxx, dsigma/2 (the stick zone's strain
compatibility, EA-3 of the stress derivation): the rig's dsigma = eta dP follows from its own
load change, which the edge signature does not fix.  The comparison therefore names it apart.

The points lie in the edge's own frame: X along the outward normal from the state-2 edge (each
contact's own a2), depth y, on a grid of ``OFFSETS`` x ``DEPTHS`` in units of the prototype's
slip zone at state 2, a2 - b, shrunk where needed so that every point lies within
``NEAR_EDGE_FRACTION`` of both contacts' edge length scales (where the asymptote's stated
accuracy holds).  Two sources, where they apply:

``asymptote`` (any law)
    The two asymptotic amplitudes and their stated accuracies (``SAFETY`` x the next-order
    field): ``within_stated_accuracy`` when at every point and component
    |rig - prototype| <= accuracy(prototype) + accuracy(rig) -- the two amplitudes cannot be
    told apart at the accuracy the stress module states.
``solver`` (with ``--verify``)
    The solvers' amplitudes (:func:`asymslip.stress.solver_source.solver_stress`) at the same
    points about each solver's own edge.  ``within_stated_accuracy`` as above, with the
    asymptotes' stated accuracies as the allowance (each exact field lies within its
    asymptote's accuracy of it, so the two exact fields of an exact match lie within their sum
    of each other); ``explained`` when the solvers' difference less the asymptotes' difference
    lies within the same allowance at every point -- the mismatch the asymptote reports is the
    one the solver finds.

Differences are stated relative to the prototype's largest |component| over the points
(``scale``).  The solver's own grid error on these points (depth >= (a2 - b)/8) is not part of
the allowance: measured in ``tests/match/test_verify_stress.py`` on a Hertz prototype (2000
against 2741 elements) it is 0.94 % of the scale, an eighth of the allowance there (7.5 %).

Examples
--------
A Hertz prototype and its exact Hertz rig of another modulus (a pad of twice the radius):
the asymptotic amplitudes are the same loads, so the same field.

>>> from asymslip import HertzLaw, LoadCycle
>>> from asymslip.match import Rig, match
>>> result = match(HertzLaw(10.0, 1.0), LoadCycle(10, 0, 10.2, 0.1), 0.3, Rig("hertz", 2.0))
>>> check = asymptote_comparison(result)
>>> check.points, check.difference < 1e-12, check.within_stated_accuracy
(24, True, True)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..stress.asymptote import EdgeLoads, edge_amplitude, edge_loads
from ..stress.field import COMPONENTS, CycleStress, StressField
from ..tractions import NEAR_EDGE_FRACTION
from .result import MatchResult, Pair

FloatArray = NDArray[np.float64]

#: Outward offsets from the state-2 edge, in units of the prototype's a2 - b (inside: < 0).
OFFSETS = (-2.0, -1.5, -1.0, -0.5, 0.0, 0.5)
#: Depths, in the same unit: below the surface, where the solver's field is resolved.
DEPTHS = (0.125, 0.25, 0.5, 1.0)
#: The grid's farthest point from the edge, in that unit: hypot(2, 1).
FARTHEST = float(np.hypot(2.0, 1.0))


@dataclass(frozen=True)
class EdgeGrid:
    """The comparison's points in the edge's outward frame: offsets X and depths y."""

    unit: float
    X: FloatArray
    depth: FloatArray

    def global_x(self, a2: float, side: str) -> FloatArray:
        """x from the contact centre of the points about an edge at outward position a2."""
        sign = 1.0 if side == "right" else -1.0
        result: FloatArray = sign * (a2 + self.X)
        return result


@dataclass(frozen=True)
class StressComparison:
    """One source's amplitudes of the two contacts compared (see the module's docstring)."""

    source: str
    points: int
    unit: float  # the grid's unit, a length
    scale: float  # the prototype's largest |component| over the points
    largest: Pair  # each contact's largest |component| over the points
    difference: float  # max |rig - prototype| / scale
    allowed: float  # max (accuracy(prototype) + accuracy(rig)) / scale
    within_stated_accuracy: bool
    explained: bool | None = None  # solver: the difference is the asymptotes' difference
    uniform_sxx: Pair | None = None  # asymptote: the amplitude's uniform sxx, dsigma/2
    near_edge: bool = True
    warnings: tuple[str, ...] = ()

    def to_dict(self) -> dict[str, object]:
        data: dict[str, object] = {
            "points": self.points,
            "grid_unit": self.unit,
            "scale": self.scale,
            "largest": {"prototype": self.largest.prototype, "rig": self.largest.rig},
            "difference": self.difference,
            "allowed": self.allowed,
            "within_stated_accuracy": self.within_stated_accuracy,
            "near_edge": self.near_edge,
        }
        if self.explained is not None:
            data["explained_by_the_asymptotes"] = self.explained
        if self.uniform_sxx is not None:
            data["uniform_sxx"] = {
                "prototype": self.uniform_sxx.prototype,
                "rig": self.uniform_sxx.rig,
            }
        data["warnings"] = list(self.warnings)
        return data


@dataclass(frozen=True)
class AsymptoticAmplitudes:
    """Both contacts' asymptotic amplitudes on the grid, with their stated accuracies."""

    grid: EdgeGrid
    prototype: CycleStress
    rig: CycleStress
    comparison: StressComparison


def _stack(field: StressField) -> FloatArray:
    result: FloatArray = np.stack([field.component(name) for name in COMPONENTS])
    return result


def _largest(values: FloatArray) -> FloatArray:
    """The largest |component| at each point."""
    result: FloatArray = np.max(np.abs(values), axis=0)
    return result


def edge_grid(result: MatchResult, loads: tuple[EdgeLoads, EdgeLoads]) -> EdgeGrid:
    """The points: ``OFFSETS`` x ``DEPTHS`` times the prototype's a2 - b, shrunk so that the
    farthest lies within 0.99 ``NEAR_EDGE_FRACTION`` of both contacts' edge length scales
    (``loads``: the prototype's and the rig's)."""
    reach = float(result.prototype.a2) - float(result.prototype.b)
    nearest = min(edge.length_scale for edge in loads)
    unit = min(reach, 0.99 * NEAR_EDGE_FRACTION * nearest / FARTHEST)  # 0.99: clear of rounding
    X, depth = np.meshgrid(np.asarray(OFFSETS), np.asarray(DEPTHS))
    return EdgeGrid(unit, unit * X.ravel(), unit * depth.ravel())


def asymptote_comparison(result: MatchResult) -> StressComparison:
    """The asymptotic amplitudes of both contacts compared (no solver)."""
    return asymptotic_amplitudes(result).comparison


def asymptotic_amplitudes(result: MatchResult) -> AsymptoticAmplitudes:
    """Both asymptotic amplitudes on :func:`edge_grid`'s points, and their comparison."""
    side = result.edge
    contacts = (
        (result.prototype_law, result.prototype_cycle, result.prototype_state.mu, result.prototype),
        (result.law, result.cycle, result.mu, result.rig_result),
    )
    mine_loads, their_loads = (edge_loads(law, cycle, mu, side) for law, cycle, mu, _ in contacts)
    grid = edge_grid(result, (mine_loads, their_loads))
    fields = [
        edge_amplitude(law, cycle, mu, grid.global_x(float(edge.a2), side), grid.depth, edge=side)
        for law, cycle, mu, edge in contacts
    ]
    prototype, rig = fields
    assert prototype.amplitude is not None and rig.amplitude is not None
    assert prototype.accuracy is not None and rig.accuracy is not None
    mine, theirs = _stack(prototype.amplitude), _stack(rig.amplitude)
    difference = _largest(theirs - mine)
    allowance = prototype.accuracy + rig.accuracy
    scale = float(np.max(np.abs(mine)))
    uniform = Pair(mine_loads.uniform, their_loads.uniform)
    near = prototype.near_edge is not None and rig.near_edge is not None
    near = near and bool(np.all(prototype.near_edge)) and bool(np.all(rig.near_edge))
    comparison = StressComparison(
        source="asymptote",
        points=int(grid.X.size),
        unit=grid.unit,
        scale=scale,
        largest=Pair(scale, float(np.max(np.abs(theirs)))),
        difference=float(np.max(difference)) / scale,
        allowed=float(np.max(allowance)) / scale,
        within_stated_accuracy=bool(np.all(difference <= allowance)),
        uniform_sxx=uniform,
        near_edge=near,
        warnings=tuple(dict.fromkeys(prototype.warnings + rig.warnings)),
    )
    return AsymptoticAmplitudes(grid, prototype, rig, comparison)


def solver_comparison(
    asymptotes: AsymptoticAmplitudes,
    prototype: StressField,
    rig: StressField,
) -> StressComparison:
    """The solvers' amplitudes at the grid's points about each solver's edge, compared with
    each other and with the asymptotes' difference."""
    assert asymptotes.prototype.amplitude is not None and asymptotes.rig.amplitude is not None
    assert asymptotes.prototype.accuracy is not None and asymptotes.rig.accuracy is not None
    allowance = asymptotes.prototype.accuracy + asymptotes.rig.accuracy
    mine, theirs = _stack(prototype), _stack(rig)
    difference = theirs - mine
    predicted = _stack(asymptotes.rig.amplitude) - _stack(asymptotes.prototype.amplitude)
    scale = float(np.max(np.abs(mine)))
    return StressComparison(
        source="solver",
        points=int(asymptotes.grid.X.size),
        unit=asymptotes.grid.unit,
        scale=scale,
        largest=Pair(scale, float(np.max(np.abs(theirs)))),
        difference=float(np.max(_largest(difference))) / scale,
        allowed=float(np.max(allowance)) / scale,
        within_stated_accuracy=bool(np.all(_largest(difference) <= allowance)),
        explained=bool(np.all(_largest(difference - predicted) <= allowance)),
        near_edge=asymptotes.comparison.near_edge,
    )


__all__ = [
    "DEPTHS",
    "FARTHEST",
    "OFFSETS",
    "AsymptoticAmplitudes",
    "EdgeGrid",
    "StressComparison",
    "asymptote_comparison",
    "asymptotic_amplitudes",
    "edge_grid",
    "solver_comparison",
]
