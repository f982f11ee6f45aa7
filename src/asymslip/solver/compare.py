"""The asymptotes beside the solver: every ``slip-zone`` estimate and its error in elements.

The only module of :mod:`asymslip.solver` that imports the asymptotic formulas: the solver
computes without them, and this module puts them side by side.  For each edge, every estimate
of ``asymslip.slip_zone`` -- ``b`` (the headline: the second-order boundary of
``derivations/second_order_slip_zone.py``), ``b_paper`` (22), ``b_first_order`` (28),
``b_corrective_stick`` (40)
and ``b_exact`` (a(P_K), which exists only without bulk tension) -- is reported with its
difference from the solver's stick boundary, in length and in elements, and whether it lies
within the solver's error bound.
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Any, overload

import numpy as np

from ..cycle import LoadCycle
from ..errors import InputError
from ..slip_zones import slip_zone
from .path import LoadPath
from .refine import RefinementResult
from .result import SolverResult

#: The estimates of ``slip_zone`` compared, by attribute name.
ESTIMATES = ("b", "b_paper", "b_first_order", "b_corrective_stick", "b_exact")


def _entry(
    value: float | None, b: float | None, b_error: float | None, element: float
) -> dict[str, Any] | None:
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return None
    if b is None:
        return {"value": value, "difference": None, "elements": None, "within_error": None}
    difference = value - b
    return {
        "value": value,
        "difference": difference,
        "elements": difference / element,
        "within_error": bool(abs(difference) <= (b_error or 0.0)),
    }


def asymptote_comparison(
    result: SolverResult, law: Any, cycle: LoadCycle, mu: float
) -> dict[str, dict[str, dict[str, Any] | None]]:
    """{"right": {estimate: entry}, "left": {...}} for the solver result of this cycle.

    Each entry is None where the estimate does not exist (``b_exact`` with tension), else
    ``value``, ``difference`` (estimate - solver b), ``elements`` (the difference over the
    element width) and ``within_error`` (|difference| <= the solver's b_error).

    Raises
    ------
    InputError
        If the result was not computed for this cycle and friction coefficient.
    """
    if not result.is_cycle:
        raise InputError("result", "the asymptotes exist only for the paper's two-state cycle")
    expected = LoadPath.from_cycle(cycle).points
    if not np.array_equal(result.path.points, expected) or result.mu != float(mu):
        raise InputError("cycle", "the solver result was computed for another cycle or mu")
    estimates = slip_zone(law, cycle, mu, edge="both")
    element = result.element_size
    out: dict[str, dict[str, dict[str, Any] | None]] = {}
    for side, estimate in (("right", estimates), ("left", estimates.left)):
        edge = result.edge(side)  # type: ignore[arg-type]
        out[side] = {
            name: _entry(getattr(estimate, name, None), edge.b, edge.b_error, element)
            for name in ESTIMATES
        }
    return out


@overload
def with_asymptotes(
    result: SolverResult, law: Any, cycle: LoadCycle, mu: float
) -> SolverResult: ...


@overload
def with_asymptotes(
    result: RefinementResult, law: Any, cycle: LoadCycle, mu: float
) -> RefinementResult: ...


def with_asymptotes(
    result: SolverResult | RefinementResult, law: Any, cycle: LoadCycle, mu: float
) -> SolverResult | RefinementResult:
    """The result with each edge's ``asymptotes`` filled in (shown by ``to_dict``).

    For a :class:`~asymslip.solver.refine.RefinementResult` the finest run gets them (its
    dictionary is the refinement's), compared with that run's b; the extrapolated b is in
    the dictionary's ``refinement``.

    Examples
    --------
    >>> from asymslip import HertzLaw, LoadCycle
    >>> from asymslip.solver import solve
    >>> from asymslip.solver.compare import with_asymptotes
    >>> law, cycle = HertzLaw(R=1, E_star=1), LoadCycle(100, 0, 105, 1)
    >>> result = with_asymptotes(solve(law, cycle, 0.1, elements=500), law, cycle, 0.1)
    >>> abs(result.right.asymptotes["b_exact"]["elements"]) < 1
    True
    """
    if isinstance(result, RefinementResult):
        finest = _compared(result.finest, law, cycle, mu)
        return replace(result, results=(*result.results[:-1], finest))
    return _compared(result, law, cycle, mu)


def _compared(result: SolverResult, law: Any, cycle: LoadCycle, mu: float) -> SolverResult:
    comparison = asymptote_comparison(result, law, cycle, mu)
    return result.with_edges(
        replace(result.right, asymptotes=comparison["right"]),
        replace(result.left, asymptotes=comparison["left"]),
    )
