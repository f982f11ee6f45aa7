"""What the solver returns: per load state, per edge, per point, and how far to trust it.

Edges are reported as ``slip-zone`` reports them: the right edge at the top level and the left
edge under ``left``; every position b or a is the distance from the profile's origin (the
contact centre of a symmetric profile) along the edge's outward direction -- the right edge's
x, minus the left edge's x.  A boundary's error is a bound of at least one element width
(:mod:`asymslip.solver.boundaries`).

Slip direction of an edge (+1, -1 or 0), as in ``slip-zone``: +1 when the traction q on the
indenter points away from the contact centre in the edge's slip zone (so the indenter slips
toward the centre relative to the lower body: the slip delta points inward) -- forward slip;
-1 the other way; 0 when the edge does not slip (conventions:
:mod:`asymslip.solver.conventions`).  It is the
direction of the element just outside the permanent stick zone at the point of largest P
(state 2 of the paper's cycle, i.e. on loading); 0 when that element does not slip there,
as when only the annulus a1 < |x| < a2 slips (|lambda| < mu, eta = 0).  Each state also
records the direction of the slip zone next to that state's own stick zone.

Examples
--------
The paper's Fig. 5 cycle, whose exact stick boundary is a(P_K) = sqrt(390/pi) = 11.1419 by
(29) and (33):

>>> from asymslip import HertzLaw, LoadCycle
>>> from asymslip.solver import solve
>>> result = solve(HertzLaw(R=1, E_star=1), LoadCycle(100, 0, 105, 1), mu=0.1, elements=200)
>>> edge = result.right
>>> bool(abs(edge.b - 11.1419) <= edge.b_error), edge.slip_direction, edge.edge
(True, 1, 'right')
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Any, Literal

import numpy as np
from numpy.typing import NDArray

from .boundaries import Boundary
from .conventions import CONVENTIONS
from .grid import Grid
from .path import LoadPath
from .toeplitz import FloatArray

Edge = Literal["right", "left"]
ORIENTATION = {"right": 1, "left": -1}


@dataclass(frozen=True)
class EdgeState:
    """One edge at one load state: contact edge, stick boundary, slip direction."""

    a: float  # contact edge, measured outward from the origin
    a_error: float
    b: float | None  # stick boundary of that state's stick zone (None: nothing sticks)
    b_error: float | None
    slip_direction: int


@dataclass(frozen=True)
class StateResult:
    """The solution at one point of the (steady) path."""

    label: str
    P: float
    Q: float
    sigma: float
    M: float
    pressure: FloatArray
    shear: FloatArray
    contact: NDArray[np.bool_]
    slip_sign: NDArray[np.int8]  # +1/-1 slipping, 0 stuck or out of contact
    slip: FloatArray  # delta accumulated since the period's first point (conventions)
    approach: float  # rigid approach delta of the normal problem
    tilt: float  # rigid tilt theta (the gap is h(x) - delta - theta x + opening)
    right: EdgeState
    left: EdgeState

    @property
    def stick(self) -> NDArray[np.bool_]:
        return self.contact & np.equal(self.slip_sign, 0)

    def edge(self, side: Edge) -> EdgeState:
        return self.right if side == "right" else self.left


@dataclass(frozen=True)
class EdgeResult:
    """The steady state seen from one edge."""

    edge: Edge
    b: float | None  # boundary of the permanent stick zone (never slips in the steady period)
    b_error: float | None
    b_method: str | None  # "fit" or "grid"
    slip_direction: int
    asymptotes: dict[str, Any] | None = None


@dataclass(frozen=True)
class SolverResult:
    """The steady state of the incremental half-plane contact solver.

    Per point of the grid (arrays over ``x``, the element centres): in each state of
    ``states`` (one per point of the path) the pressure, shear traction, slip state and the
    slip accumulated since the period's first point; over one steady period ``slip_range``
    (peak-to-peak relative slip), ``slip_amplitude`` (half of it) and ``energy`` (frictional
    energy dissipated per period per unit area of interface, int q ds, summed step by step by
    the trapezoid rule), and ``permanent_stick`` (never slips, always in contact).  Slip and
    energy of the elements that come into and leave the contact converge like 1/steps (see
    :mod:`asymslip.solver.tangential`).  The stick boundaries do not depend on the steps
    where both edges slip (to 1e-3 element between 1 and 8 steps); where one edge sticks under
    bulk tension they converge like 1/steps too (up to 0.35 element off at one step, about 0.02
    at the default 20; measured for the error map, :mod:`asymslip.solver.error_map`), an error
    the stated bound does not include.
    """

    grid: Grid
    mu: float
    E_star: float
    profile: dict[str, Any]
    path: LoadPath
    is_cycle: bool
    states: tuple[StateResult, ...]
    permanent_stick: NDArray[np.bool_]
    slip_range: FloatArray
    energy: FloatArray
    right: EdgeResult
    left: EdgeResult
    steps: int
    cycles: int
    steady: bool
    steady_change: float  # largest change of q over the last period / (mu max p)
    tolerance: float  # the steady tolerance applied (SolverSettings.steady_tolerance)
    load_steps: int
    active_set_solves: int
    cg_iterations: int
    fallbacks: int
    seconds: float
    warnings: tuple[str, ...] = field(default_factory=tuple)
    normal_solves: int = 0  # distinct loads whose normal problem was solved

    @property
    def x(self) -> FloatArray:
        return self.grid.centres

    @property
    def element_size(self) -> float:
        return self.grid.width

    @property
    def elements(self) -> int:
        return self.grid.count

    @property
    def slip_amplitude(self) -> FloatArray:
        return self.slip_range / 2

    @property
    def q_diff(self) -> FloatArray:
        """q2 - q1 of (46) for the paper's cycle (state 2 minus state 1)."""
        if not self.is_cycle:
            raise AttributeError("q_diff is defined for the paper's two-state cycle")
        return self.states[1].shear - self.states[0].shear

    def edge(self, side: Edge) -> EdgeResult:
        return self.right if side == "right" else self.left

    def with_edges(self, right: EdgeResult, left: EdgeResult) -> SolverResult:
        return replace(self, right=right, left=left)

    def _edge_dict(self, side: Edge) -> dict[str, Any]:
        edge = self.edge(side)
        data: dict[str, Any] = {
            "b": edge.b,
            "b_error": edge.b_error,
            "b_error_elements": None if edge.b_error is None else edge.b_error / self.element_size,
            "b_method": edge.b_method,
            "slip_direction": edge.slip_direction,
        }
        for state in self.states:
            at = state.edge(side)
            data[f"a{state.label}"] = at.a
            data[f"a{state.label}_error"] = at.a_error
        for state in self.states:
            at = state.edge(side)
            data[f"b{state.label}"] = at.b
            data[f"b{state.label}_error"] = at.b_error
            data[f"slip_direction{state.label}"] = at.slip_direction
        if edge.asymptotes is not None:
            data["asymptotes"] = edge.asymptotes
        return data

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready: the right edge at the top level, the left under ``left``.

        Per edge: ``b`` (permanent stick boundary), ``b_error``, ``slip_direction``, the contact
        edge ``a<k>`` and stick boundary ``b<k>`` (with ``_error``) at each path point k (for the
        paper's cycle a1, a2, b1, b2), and ``asymptotes`` when attached by
        :func:`asymslip.solver.compare.with_asymptotes`.  Then the loads of the states, the
        settings and the convergence record, the conventions (:mod:`.conventions`) and the
        warnings.
        """
        data = self._edge_dict("right")
        data["left"] = self._edge_dict("left")
        data["states"] = [
            {
                "label": s.label,
                "P": s.P,
                "Q": s.Q,
                "sigma": s.sigma,
                "M": s.M,
                "approach": s.approach,
                "tilt": s.tilt,
            }
            for s in self.states
        ]
        data["solver"] = {
            "elements": self.elements,
            "element_size": self.element_size,
            "domain": [self.grid.start, self.grid.end],
            "steps_per_segment": self.steps,
            "cycles": self.cycles,
            "steady": self.steady,
            "steady_change": self.steady_change,
            "steady_tolerance": self.tolerance,
            "load_steps": self.load_steps,
            "active_set_solves": self.active_set_solves,
            "cg_iterations": self.cg_iterations,
            "fallbacks": self.fallbacks,
            "normal_solves": self.normal_solves,
            "seconds": self.seconds,
            "mu": self.mu,
            "E_star": self.E_star,
            **self.profile,
        }
        data["conventions"] = dict(CONVENTIONS)
        data["warnings"] = list(self.warnings)
        return data


def measured(side: Edge, boundary: Boundary) -> tuple[float, float]:
    """A boundary's x as the edge's outward distance b, and its error."""
    return ORIENTATION[side] * boundary.x, boundary.error
