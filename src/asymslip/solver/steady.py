"""The steady period's results: states at the path's points, slip, energy and stick boundaries.

Built from the records of one period (:mod:`.period`), in the period's order from point 1.
The permanent stick zone is the set of elements in contact at every step that never slip;
each edge's stick boundary b is where its friction reserve vanishes like a square root
(:mod:`.boundaries`), its error a bound of at least one element.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from .boundaries import Boundary, locate
from .grid import Grid
from .normal import NormalState
from .period import StepRecord
from .result import ORIENTATION, Edge, EdgeResult, EdgeState, SolverResult, StateResult, measured
from .settings import Convergence, SolverSettings
from .toeplitz import FloatArray, Runs

BoolArray = NDArray[np.bool_]
Int8Array = NDArray[np.int8]

#: A slip below this fraction of the period's largest slip increment counts as none: the
#: residue of the geometric approach to the steady state (see :func:`significant_slip`).
SLIP_SIGNIFICANCE = 1e-6


def central_run(mask: BoolArray, anchor: BoolArray) -> tuple[int, int] | None:
    """(first, last) of the run of ``mask`` overlapping ``anchor`` most (else the longest)."""
    runs = Runs.of(mask)
    if not runs.starts:
        return None
    overlaps = [int(anchor[a:b].sum()) for a, b in zip(runs.starts, runs.stops, strict=True)]
    lengths = runs.lengths
    best = max(range(len(lengths)), key=lambda i: (overlaps[i], lengths[i]))
    return runs.starts[best], runs.stops[best] - 1


def edge_state(
    grid: Grid,
    mu: float,
    normal: NormalState,
    shear: FloatArray,
    slip_sign: Int8Array,
    anchor: BoolArray,
    side: Edge,
) -> EdgeState:
    """One edge at one state: its contact edge, the stick boundary next to it, the direction."""
    direction = ORIENTATION[side]
    edge_index = normal.last if direction > 0 else normal.first
    a, a_error = measured(side, locate(grid, normal.pressure, edge_index, direction))
    stick = normal.contact & (slip_sign == 0)
    run = central_run(stick, anchor)
    if run is None:
        return EdgeState(a, a_error, None, None, 0)
    end = run[1] if direction > 0 else run[0]
    outside = end + direction
    sign = int(slip_sign[outside]) if normal.contact[outside] else 0
    if sign == 0:  # the stick zone reaches the contact edge
        return EdgeState(a, a_error, a, a_error, 0)
    reserve = mu * normal.pressure - sign * shear
    b, b_error = measured(side, locate(grid, reserve, end, direction))
    return EdgeState(a, a_error, b, b_error, sign * direction)


def permanent_boundary(
    grid: Grid,
    mu: float,
    records: list[StepRecord],
    vertex_steps: set[int],
    end: int,
    side: Edge,
) -> Boundary:
    """The permanent stick zone's boundary beyond element ``end`` on ``side``.

    The element just outside the zone slips at some steps, or leaves the contact at some, or
    both.  Where it slips, the friction reserves mu p -+ q of those steps (the path's points
    among them if any) are summed: each vanishes like a square root at the boundary.  Where it
    leaves the contact, the innermost of those steps' contact edges is the candidate.  The
    boundary is the innermost candidate.
    """
    direction = ORIENTATION[side]
    outside = end + direction
    candidates = []
    signs = [record.slip.sign_at(outside) for record in records]
    slipping = [
        i for i, record in enumerate(records) if record.normal.contact[outside] and signs[i] != 0
    ]
    if slipping:
        chosen = [i for i in slipping if i in vertex_steps] or slipping
        reserve = np.zeros(grid.count)
        for i in chosen:
            reserve += mu * records[i].normal.pressure - signs[i] * records[i].shear
        candidates.append(locate(grid, reserve, end, direction))
    normals = {id(r.normal): r.normal for r in records if not r.normal.contact[outside]}
    candidates.extend(locate(grid, n.pressure, end, direction) for n in normals.values())
    return min(candidates, key=lambda boundary: direction * boundary.x)


def significant_slip(records: list[StepRecord]) -> list[StepRecord]:
    """The period's steps with slips below SLIP_SIGNIFICANCE of the largest one dropped.

    A steady state is approached geometrically: the last period still carries residual slips,
    of the order of the steady tolerance, where the limit has none (the permanent stick
    zone).  Counted as slip they would shrink that zone; they are far below any slip of a real
    slip zone except within a tiny fraction of an element of its boundary.
    """
    threshold = SLIP_SIGNIFICANCE * max(record.slip.largest() for record in records)
    return [
        StepRecord(record.normal, record.shear, record.slip.significant(threshold))
        for record in records
    ]


def build_result(
    settings: SolverSettings,
    records: list[StepRecord],
    convergence: Convergence,
    seconds: float,
) -> SolverResult:
    """The :class:`SolverResult` of the steady period (or the last one, if not steady)."""
    grid, mu, path, steps = settings.grid, settings.mu, settings.path, settings.steps
    warnings: list[str] = []
    if not convergence.steady:
        warnings.append(
            f"no steady state after {convergence.cycles} periods: the tractions still changed "
            f"by {convergence.change:.3g} mu max p (tolerance {settings.steady_tolerance:g}) "
            "or the stick/slip state moved; the results are those of the last period"
        )
    records = significant_slip(records)
    count = grid.count
    normals = {id(record.normal): record.normal for record in records}.values()
    in_contact_always = np.logical_and.reduce([normal.contact for normal in normals])
    slips = np.zeros(count, dtype=bool)
    # The slip delta accumulated from point 1, its extremes over the period, the energy.  The
    # steps record the derivation's s = u_x(body 2) - u_x(body 1), body 1 carrying q: here the
    # indenter (conventions), so delta = u_x(indenter) - u_x(lower body) = -s.
    slip = np.zeros(count)
    highest = np.zeros(count)
    lowest = np.zeros(count)
    energy = np.zeros(count)
    vertex_steps = {(s + 1) * steps - 1 for s in range(path.count)}
    slip_at: dict[int, FloatArray] = {}
    for i, record in enumerate(records):
        moved = record.slip
        slips[moved.index[moved.sign != 0]] = True
        slip[moved.index] -= moved.increment
        highest[moved.index] = np.maximum(highest[moved.index], slip[moved.index])
        lowest[moved.index] = np.minimum(lowest[moved.index], slip[moved.index])
        energy[moved.index] += moved.energy
        if i in vertex_steps:
            slip_at[i] = slip.copy()
    permanent = in_contact_always & ~slips
    slip_range = highest - lowest
    states = []
    for k in range(path.count):
        # Point k ends segment k - 1 (point 1 ends the period); the period starts at point 1.
        index = (k - 1) % path.count
        record = records[(index + 1) * steps - 1]
        signs = record.slip.signs(count)
        P, Q, sigma, M = path.points[k]
        states.append(
            StateResult(
                label=path.labels[k],
                P=float(P),
                Q=float(Q),
                sigma=float(sigma),
                M=float(M),
                pressure=record.normal.pressure,
                contact=record.normal.contact,
                shear=record.shear,
                slip_sign=signs,
                slip=slip_at[k * steps - 1] if k > 0 else np.zeros(count),
                approach=record.normal.approach,
                tilt=record.normal.tilt,
                right=edge_state(grid, mu, record.normal, record.shear, signs, permanent, "right"),
                left=edge_state(grid, mu, record.normal, record.shear, signs, permanent, "left"),
            )
        )
    run = central_run(permanent, permanent)
    runs = Runs.of(permanent)
    if len(runs.starts) > 1:
        warnings.append(
            f"the permanent stick zone is in {len(runs.starts)} pieces; b refers to the longest"
        )
    loaded = int(np.argmax(path.points[:, 0]))
    loaded_step = records[((loaded - 1) % path.count + 1) * steps - 1]
    edges = {}
    sides: tuple[Edge, Edge] = ("right", "left")
    for side in sides:
        if run is None:
            direction = states[loaded].edge(side).slip_direction
            edges[side] = EdgeResult(side, None, None, None, direction)
            continue
        end = run[1] if side == "right" else run[0]
        # The edge's slip direction: that of the element just outside the permanent stick
        # zone at the point of largest load (state 2 of the paper's cycle: on loading); 0 if
        # it does not slip there (e.g. only the annulus a1 < |x| < a2 ever slips).
        outside = end + ORIENTATION[side]
        direction = loaded_step.slip.sign_at(outside) * ORIENTATION[side]
        boundary = permanent_boundary(grid, mu, records, vertex_steps, end, side)
        b, b_error = measured(side, boundary)
        edges[side] = EdgeResult(side, b, b_error, boundary.method, direction)
        if settings.is_cycle and direction != 0:
            for state in states:
                at = state.edge(side)
                if at.b is not None and abs(at.b - b) > max(at.b_error or 0.0, b_error):
                    warnings.append(
                        f"{side} edge: the stick boundary at state {state.label} ({at.b:.6g}) "
                        f"differs from the permanent one ({b:.6g}) by more than its error"
                    )
    if run is None:
        warnings.append(
            "no element sticks throughout the period: there is no permanent stick "
            "zone, and b is undefined"
        )
    return SolverResult(
        grid=grid,
        mu=mu,
        E_star=settings.E_star,
        profile=settings.profile.describe(),
        path=path,
        is_cycle=settings.is_cycle,
        states=tuple(states),
        permanent_stick=permanent,
        slip_range=slip_range,
        energy=energy,
        right=edges["right"],
        left=edges["left"],
        steps=steps,
        cycles=convergence.cycles,
        steady=convergence.steady,
        steady_change=float(convergence.change),
        tolerance=settings.steady_tolerance,
        load_steps=convergence.load_steps,
        active_set_solves=convergence.active_set_solves,
        cg_iterations=convergence.cg_iterations,
        fallbacks=convergence.fallbacks,
        seconds=seconds,
        warnings=tuple(warnings),
        normal_solves=convergence.normal_solves,
    )
