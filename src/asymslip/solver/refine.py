"""Refinement mode: the same problem on N, 2N, 4N elements, and what the sequence says.

Every run uses the same computational domain, so the grids are nested.  For each reported
boundary (the permanent stick boundary b of each edge, and at each path point the contact edge
a<k> and stick boundary b<k>) the three values v1, v2, v4 are compared:

* if the differences d1 = v2 - v1 and d2 = v4 - v2 have the same sign and shrink, the observed
  order is p = log2(d1/d2); for 0.5 <= p <= 6 the value is Richardson-extrapolated,
  v = v4 + d2/(2^p - 1), with the error max(|d2|, |d2|/(2^p - 1)): the last change, or the
  correction if larger.  (The correction alone is the error only once the sequence is in its
  asymptotic regime; sub-element fits reach it late: on a Hertz edge at N = 250-1000 the
  extrapolated value was 2 corrections off, within the last change.)
* otherwise (no order observed: sub-element fits converge erratically, as the element ends
  move relative to the boundary) the value is the finest run's and the error the spread,
  max(|v1 - v4|, |v2 - v4|).

Examples
--------
Values on N, 2N, 4N elements whose differences halve (first order) extrapolate to their limit:

>>> from asymslip.solver.refine import extrapolate
>>> result = extrapolate((1.25, 1.125, 1.0625))
>>> result.value, result.order, result.method
(1.0, 1.0, 'richardson')
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from ..cycle import LoadCycle
from .memory import check_memory
from .path import LoadPath, as_path
from .profiles import as_profile
from .result import SolverResult
from .run import DEFAULT_ELEMENTS, DEFAULT_STEPS, _integer, _modulus, choose_domain, solve

#: Accepted range of an observed convergence order for Richardson extrapolation.
ORDER_RANGE = (0.5, 6.0)


@dataclass(frozen=True)
class Extrapolation:
    """One quantity over the refinement levels, and its extrapolated value and error."""

    values: tuple[float | None, ...]
    value: float | None
    error: float | None
    order: float | None
    method: str  # "richardson", "spread" or "unavailable"

    def to_dict(self) -> dict[str, Any]:
        return {
            "values": list(self.values),
            "value": self.value,
            "error": self.error,
            "order": self.order,
            "method": self.method,
        }


def extrapolate(values: tuple[float | None, ...]) -> Extrapolation:
    """Richardson extrapolation of a sequence on grids refined by 2, or its spread."""
    known = [v for v in values if v is not None]
    if len(known) < len(values) or len(values) < 2:
        return Extrapolation(values, None, None, None, "unavailable")
    finest = float(known[-1])
    spread = max(abs(float(v) - finest) for v in known[:-1])
    if len(known) >= 3:
        d1 = float(known[-2]) - float(known[-3])
        d2 = finest - float(known[-2])
        if d1 * d2 > 0 and abs(d2) < abs(d1):
            ratio = d1 / d2
            order = math.log2(ratio)
            if ORDER_RANGE[0] <= order <= ORDER_RANGE[1]:
                correction = d2 / (ratio - 1)
                error = max(abs(correction), abs(d2))
                return Extrapolation(values, finest + correction, error, order, "richardson")
    return Extrapolation(values, finest, spread, None, "spread")


@dataclass(frozen=True)
class RefinementResult:
    """The runs on N, 2N, 4N ... elements and the extrapolated boundaries of each edge."""

    results: tuple[SolverResult, ...]
    right: dict[str, Extrapolation]
    left: dict[str, Extrapolation]

    @property
    def finest(self) -> SolverResult:
        return self.results[-1]

    def to_dict(self) -> dict[str, Any]:
        """The finest run's dictionary, each edge with ``refinement``: quantity -> sequence."""
        data = self.finest.to_dict()
        data["refinement"] = {key: value.to_dict() for key, value in self.right.items()}
        data["left"]["refinement"] = {key: value.to_dict() for key, value in self.left.items()}
        data["solver"]["refinement_elements"] = [r.elements for r in self.results]
        return data


def _quantities(result: SolverResult, side: str) -> dict[str, float | None]:
    edge = result.edge(side)  # type: ignore[arg-type]
    values: dict[str, float | None] = {"b": edge.b}
    for state in result.states:
        at = state.edge(side)  # type: ignore[arg-type]
        values[f"a{state.label}"] = at.a
        values[f"b{state.label}"] = at.b
    return values


def refine(
    contact: Any,
    loading: LoadCycle | LoadPath | Any,
    mu: float,
    *,
    elements: int = DEFAULT_ELEMENTS,
    levels: int = 3,
    E_star: float | None = None,
    domain: tuple[float, float] | None = None,
    **options: Any,
) -> RefinementResult:
    """Run :func:`~asymslip.solver.solve` on N, 2N, 4N (``levels`` grids) and extrapolate.

    Parameters are those of :func:`~asymslip.solver.solve` (``elements`` is the coarsest N);
    ``levels`` >= 2 grids, each twice as fine as the last.
    """
    levels = _integer("levels", levels, 2, "must be at least 2 (a sequence needs two grids)")
    elements = _integer("elements", elements, 1, "must be at least 1")
    steps = _integer("steps", options.get("steps", DEFAULT_STEPS), 1, "must be at least 1")
    path = as_path(loading)
    finest = elements * 2 ** (levels - 1)
    check_memory(finest, steps, path, subject=f"the finest grid ({finest:,} elements) needs")
    if domain is None:
        domain = choose_domain(as_profile(contact), _modulus(contact, E_star), path)
    results = tuple(
        solve(
            contact, loading, mu, elements=elements * 2**k, E_star=E_star, domain=domain, **options
        )
        for k in range(levels)
    )
    edges = {}
    for side in ("right", "left"):
        per_run = [_quantities(r, side) for r in results]
        edges[side] = {key: extrapolate(tuple(q[key] for q in per_run)) for key in per_run[0]}
    return RefinementResult(results, edges["right"], edges["left"])
