"""Where and how hard each edge fatigues: the criteria near both edges of a solved cycle.

From a steady solver result (:func:`asymslip.solver.solve`; conventions:
:mod:`asymslip.stress`), for each edge and each criterion asked for:

``peak``
    the largest value over a window around the edge -- from the permanent stick boundary b
    less half the slip zone to the outermost contact edge plus as much, and as deep as the
    slip zone is wide (or twice the critical distance) -- on a grid of ``GRID`` points and
    a surface line of ``SURFACE`` points, with its location and the normal angle of its
    critical plane; a location is known to the grid's spacing (reported).
``point``, ``line``
    the theory of critical distances below the surface hot spot (the criterion's largest
    value on the surface): the criterion at depth L/2, and on the stress history averaged
    over depths 0 to 2L (Gauss-Legendre, ``LINE_NODES`` points), each on its own critical
    plane.
Ruiz
    tau delta and sigma_T tau delta along the surface at the solver's element centres: tau the
    largest shear traction of the states, delta the slip amplitude (half the peak-to-peak
    slip of the steady cycle), sigma_T the largest surface sxx of the states.

The asymptotic source cannot give these: it gives the change of the stress over the cycle,
not the stress at each extreme (whose locked-in shear depends on the history), and every
criterion here needs a maximum over the cycle.

Examples
--------
The frictional work of the paper's Fig. 5 cycle peaks in the right edge's slip zone, between
b = 11.14 and a2 = 11.56:

>>> from asymslip import HertzLaw, LoadCycle
>>> from asymslip.solver import solve
>>> result = solve(HertzLaw(1, 1), LoadCycle(100, 0, 105, 1), mu=0.1, elements=200)
>>> found = nucleation(result, Material(E=1.82, nu=0.3), [Criterion.RUIZ], edges=["right"])
>>> work = found.find("right", "ruiz", "frictional_work")
>>> bool(11.14 < work.x < 11.56), work.angle
(True, None)
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from asymslip_gen.nucleation import ruiz_frictional_work, ruiz_parameter

from ..errors import InputError
from ..solver import SolverResult
from ..stress.field import FloatArray
from ..stress.solver_source import solver_stress
from .criteria import Criterion, History, Material, critical_plane

#: Grid of the window (along the surface, in depth).
GRID = (121, 61)
#: Points of the surface line searched for the hot spot.
SURFACE = 801
#: Gauss-Legendre points of the line method's average.
LINE_NODES = 40
SIDES = ("right", "left")


@dataclass(frozen=True)
class Finding:
    """One value of one criterion at one edge: where it is, on which plane."""

    edge: str
    criterion: str
    method: str  # peak, point, line; for Ruiz: frictional_work, ruiz
    value: float
    x: float
    depth: float
    angle: float | None  # the critical plane's normal from +x towards the depth [degrees];
    # None for Ruiz (a surface quantity) and where every plane gives 0
    resolution: float  # the spacing of the points the location was found among

    def to_dict(self) -> dict[str, object]:
        return {
            "value": self.value,
            "x": self.x,
            "depth": self.depth,
            "angle": self.angle,
            "resolution": self.resolution,
        }


@dataclass(frozen=True)
class EdgeMap:
    """A criterion's value over the window of one edge (for the picture)."""

    edge: str
    criterion: str
    x: FloatArray  # (nx,)
    depth: FloatArray  # (ny,)
    values: FloatArray  # (ny, nx)


@dataclass(frozen=True)
class NucleationResult:
    """Every finding, the maps of the plane criteria and the doubts in words."""

    findings: tuple[Finding, ...]
    maps: tuple[EdgeMap, ...]
    material: Material
    warnings: tuple[str, ...] = field(default_factory=tuple)

    def find(self, edge: str, criterion: str, method: str) -> Finding:
        for finding in self.findings:
            if (finding.edge, finding.criterion, finding.method) == (edge, criterion, method):
                return finding
        raise KeyError((edge, criterion, method))

    def to_dict(self) -> dict[str, object]:
        """JSON-ready: ``right`` and ``left``, each criterion with its methods' findings."""
        edges: dict[str, dict[str, dict[str, object]]] = {side: {} for side in SIDES}
        for finding in self.findings:
            block = edges[finding.edge].setdefault(finding.criterion, {})
            block[finding.method] = finding.to_dict()
        material = {
            key: value for key, value in self.material.__dict__.items() if value is not None
        }
        return {**edges, "material": material, "warnings": list(self.warnings)}


def _degrees(value: float, angle: float) -> float | None:
    """The critical plane's angle in degrees; None where every plane gives 0 (SWT where no
    plane opens: no plane is critical)."""
    return float(np.degrees(angle)) if value != 0 else None


@dataclass(frozen=True)
class _Window:
    side: str
    sign: float
    inner: float  # outward distances from the origin
    outer: float
    deep: float

    def grid(self) -> tuple[FloatArray, FloatArray]:
        outward = np.linspace(self.inner, self.outer, GRID[0])
        return self.sign * outward, np.linspace(0.0, self.deep, GRID[1])


def _window(result: SolverResult, side: str, material: Material) -> _Window:
    edge = result.edge(side)  # type: ignore[arg-type]
    edges = [state.edge(side).a for state in result.states]  # type: ignore[arg-type]
    outer_edge = max(edges)
    inner_edge = edge.b if edge.b is not None else min(edges)
    width = max(outer_edge - inner_edge, 8 * result.element_size)
    deep = max(width, 2 * material.L if material.L is not None else 0.0)
    return _Window(
        side, 1.0 if side == "right" else -1.0, inner_edge - width / 2, outer_edge + width / 2, deep
    )


def _history(result: SolverResult, x: FloatArray, depth: FloatArray) -> History:
    field_ = solver_stress(result, x, depth)
    return History(
        np.stack([s.sxx for s in field_.states]),
        np.stack([s.syy for s in field_.states]),
        np.stack([s.sxy for s in field_.states]),
    )


def _ruiz(result: SolverResult, window: _Window) -> list[Finding]:
    centres = result.x
    inside = (window.sign * centres >= window.inner) & (window.sign * centres <= window.outer)
    x = centres[inside]
    traction = np.max(np.abs(np.stack([state.shear[inside] for state in result.states])), axis=0)
    slip = result.slip_amplitude[inside]
    surface = _history(result, x, np.zeros_like(x))
    tension = surface.sxx.max(axis=0)
    findings = []
    for method, values in (
        ("frictional_work", np.asarray(ruiz_frictional_work(traction, slip), dtype=float)),
        ("ruiz", np.asarray(ruiz_parameter(tension, traction, slip), dtype=float)),
    ):
        best = int(np.argmax(values))
        findings.append(
            Finding(
                window.side,
                Criterion.RUIZ.value,
                method,
                float(values[best]),
                float(x[best]),
                0.0,
                None,
                result.element_size,
            )
        )
    return findings


def _plane_findings(
    result: SolverResult, window: _Window, criterion: Criterion, material: Material
) -> tuple[list[Finding], EdgeMap]:
    xs, depths = window.grid()
    X, Y = np.meshgrid(xs, depths)
    values, angles = critical_plane(_history(result, X.ravel(), Y.ravel()), criterion, material)
    values, angles = values.reshape(X.shape), angles.reshape(X.shape)
    line = window.sign * np.linspace(window.inner, window.outer, SURFACE)
    surface_values, surface_angles = critical_plane(
        _history(result, line, np.zeros_like(line)), criterion, material
    )
    spacing = float(max(np.ptp(xs) / (GRID[0] - 1), depths[1] - depths[0]))
    name = criterion.value
    best = np.unravel_index(int(np.argmax(values)), values.shape)
    hot = int(np.argmax(surface_values))
    if surface_values[hot] >= values[best]:
        peak = Finding(
            window.side,
            name,
            "peak",
            float(surface_values[hot]),
            float(line[hot]),
            0.0,
            _degrees(float(surface_values[hot]), float(surface_angles[hot])),
            float(abs(line[1] - line[0])),
        )
    else:
        peak = Finding(
            window.side,
            name,
            "peak",
            float(values[best]),
            float(X[best]),
            float(Y[best]),
            _degrees(float(values[best]), float(angles[best])),
            spacing,
        )
    findings = [peak]
    if material.L is not None:
        x_hot = float(line[hot])
        point_value, point_angle = critical_plane(
            _history(result, np.array([x_hot]), np.array([material.L / 2])), criterion, material
        )
        findings.append(
            Finding(
                window.side,
                name,
                "point",
                float(point_value[0]),
                x_hot,
                material.L / 2,
                _degrees(float(point_value[0]), float(point_angle[0])),
                float(abs(line[1] - line[0])),
            )
        )
        nodes, weights = np.polynomial.legendre.leggauss(LINE_NODES)
        depth = material.L * (nodes + 1)  # over (0, 2L)
        along = _history(result, np.full(depth.size, x_hot), depth)
        w = weights / weights.sum()
        averaged = History(
            *(
                np.sum(c * w[None, :], axis=1, keepdims=True)
                for c in (along.sxx, along.syy, along.sxy)
            )
        )
        line_value, line_angle = critical_plane(averaged, criterion, material)
        findings.append(
            Finding(
                window.side,
                name,
                "line",
                float(line_value[0]),
                x_hot,
                material.L,
                _degrees(float(line_value[0]), float(line_angle[0])),
                float(abs(line[1] - line[0])),
            )
        )
    return findings, EdgeMap(window.side, name, xs, depths, values)


def nucleation(
    result: SolverResult,
    material: Material,
    criteria: Sequence[Criterion],
    *,
    edges: Sequence[str] = SIDES,
) -> NucleationResult:
    """The crack-nucleation parameters near the edges of a steady solver result.

    Parameters
    ----------
    result
        A steady cycle of the reference solver.
    material
        The lower body's constants (those the criteria need; L for the critical distances).
    criteria
        Which criteria (:class:`Criterion`).
    edges
        ``"right"`` and/or ``"left"``.

    Returns
    -------
    NucleationResult
        For each edge and criterion the peak (and with L the point and line methods of the
        theory of critical distances), each with value, location and critical-plane angle.
    """
    if not result.steady:
        raise InputError("solver", "the solver did not reach its steady state (raise max_cycles)")
    for side in edges:
        if side not in SIDES:
            raise InputError("edge", "must be 'right' or 'left'", side)
    for criterion in criteria:
        material.require(criterion)
    findings: list[Finding] = []
    maps: list[EdgeMap] = []
    warnings = list(result.warnings)
    for side in edges:
        window = _window(result, side, material)
        if result.edge(side).slip_direction == 0:  # type: ignore[arg-type]
            warnings.append(
                f"the {side} edge does not slip in the steady cycle: its slip, and Ruiz's "
                "parameters, come only from the annulus the contact grows into (a1 < |x| < a2)"
            )
        for criterion in criteria:
            if criterion is Criterion.RUIZ:
                findings += _ruiz(result, window)
            else:
                found, edge_map = _plane_findings(result, window, criterion, material)
                findings += found
                maps.append(edge_map)
    return NucleationResult(tuple(findings), tuple(maps), material, tuple(warnings))
