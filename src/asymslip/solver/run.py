"""The incremental solver: load the contact along the path, period after period, to steady state.

:func:`solve` is the entry point.  Each load step solves the normal problem at the step's
(P, M) (:mod:`.normal`; reused in every period) and then the tangential problem from the
previous step's shear state (:mod:`.tangential`).  Each step's solution is unique (a strictly
convex programme), so the shear state at the start of a period decides the whole period: a
period that ends in the state it began from repeats forever, and its stick zones, tractions,
slips and energies are the steady ones.  The steady state is declared when, over the last
period, no shear traction changed by more than ``tolerance`` times mu max p, and the changes
still to come -- the approach is geometric: change r/(1 - r) with r the ratio of the last two
periods' changes -- are within the tolerance too.  The result is built from that period.
Periods needed on the paper's cycle: 2 (4 when one edge does not slip and tension is present,
whose locked-in tractions settle geometrically, by about 2500 times per period).
"""

from __future__ import annotations

import time
from dataclasses import dataclass, replace
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..cycle import LoadCycle
from ..errors import InputError, as_float_array, positive
from .boundaries import Boundary, locate
from .grid import Grid, InfluenceOperators
from .normal import ContactOutsideGrid, NormalSolver, NormalState, extrapolated_contact
from .path import LoadPath, as_path
from .profiles import Profile, as_profile
from .result import ORIENTATION, Edge, EdgeResult, EdgeState, SolverResult, StateResult, measured
from .tangential import TangentialSolver, TangentialState, predict_slip
from .toeplitz import FloatArray, Runs, SolverError

#: Fewest elements accepted: the boundary fits need a few elements in every zone.
MIN_ELEMENTS = 64
#: Default number of elements.
DEFAULT_ELEMENTS = 2000
#: Default load steps per segment of the path.
DEFAULT_STEPS = 20
#: Default steady-state tolerance on the shear tractions, relative to mu max p.
DEFAULT_TOLERANCE = 1e-8
#: Default cap on the number of periods.
DEFAULT_MAX_CYCLES = 20
#: Margin of the computational domain beyond the largest contact, as a fraction of its width.
DOMAIN_MARGIN = 0.03
#: Elements of the coarse grid that places the domain.
COARSE_ELEMENTS = 400
#: A slip below this fraction of the period's largest slip increment counts as none: the
#: residue of the geometric approach to the steady state (see ``_significant_slip``).
SLIP_SIGNIFICANCE = 1e-6


def _modulus(contact: Any, E_star: float | None) -> float:
    law_modulus = getattr(contact, "E_star", None)
    if E_star is None:
        if law_modulus is None:
            raise InputError("E_star", "is needed with a profile (a law carries its own E*)")
        return float(law_modulus)
    value = float(positive("E_star", E_star))
    if law_modulus is not None and value != float(law_modulus):
        raise InputError("E_star", f"differs from the law's E* = {law_modulus!r}; give one", value)
    return value


def _integer(parameter: str, value: Any, minimum: int, rule: str) -> int:
    if isinstance(value, bool) or not float(as_float_array(parameter, value)).is_integer():
        raise InputError(parameter, "must be a whole number", value)
    number = int(value)
    if number < minimum:
        raise InputError(parameter, rule, number)
    return number


def _normal_extent(
    profile_heights, left: float, right: float, E_star: float, loads: FloatArray, count: int
) -> tuple[float, float]:
    """Union of the contacts at the given (P, M) on a grid over [left, right]."""
    grid = Grid.spanning(left, right, count)
    solver = NormalSolver(grid, InfluenceOperators(grid, E_star), profile_heights(grid.centres))
    lo, hi, start = np.inf, -np.inf, None
    for P, M in loads:
        state = solver.solve(P, M, start)
        start = state.contact
        lo = min(lo, grid.boundary(state.first, -1))
        hi = max(hi, grid.boundary(state.last, 1))
    return lo, hi


def choose_domain(
    profile: Profile, E_star: float, path: LoadPath, margin: float = DOMAIN_MARGIN
) -> tuple[float, float]:
    """A domain holding every contact of the path with ``margin`` to spare on each side.

    The contacts at the path's points are found on a coarse grid, widened until no contact
    reaches its ends (and narrowed if they fill little of it).
    """
    loads = path.points[:, [0, 3]]
    scale = profile.length_scale(float(loads[:, 0].max()), E_star)
    span = profile.defined_span()
    centre = 0.0 if span is None else 0.5 * (span[0] + span[1])
    half = 1.5 * scale if scale else 1.0
    heights = profile.checked_heights
    for _ in range(60):
        try:
            lo, hi = _normal_extent(
                heights, centre - half, centre + half, E_star, loads, COARSE_ELEMENTS
            )
        except ContactOutsideGrid:
            half *= 2
            continue
        except SolverError:  # the normal problem has no solution: a profile falling away (-x**2)
            break
        if hi - lo < 0.2 * half:  # the contact fills little of the grid: zoom in once more
            centre, half = 0.5 * (lo + hi), 0.75 * (hi - lo)
            continue
        width = hi - lo
        if span is not None and (lo < span[0] or hi > span[1]):
            raise InputError(
                "profile",
                f"the contact reaches [{lo:.6g}, {hi:.6g}], beyond the table's x range "
                f"[{span[0]:.6g}, {span[1]:.6g}]: extend the table",
            )
        return lo - margin * width, hi + margin * width
    raise InputError(
        "profile",
        "no finite contact was found for the path's loads (is the "
        "profile rising away from its lowest point on both sides?)",
    )


def _check_moment(profile: Profile, grid: Grid, heights: FloatArray, path: LoadPath) -> None:
    """Refuse M != 0 on a profile of constant curvature: a cylinder rolls instead."""
    if not np.any(path.points[:, 3] != 0):
        return
    curvature = np.diff(heights, 2) / grid.width**2
    middle = np.median(curvature)
    if middle > 0 and np.max(np.abs(curvature - middle)) <= 1e-6 * middle:
        raise InputError(
            "M",
            "a moment cannot be resisted by this profile: its curvature is constant (a "
            "cylinder), so a rigid tilt only moves the contact -- the indenter rolls (the "
            "paper, Sec. 1); give M = 0 for it",
        )


@dataclass
class _StepRecord:
    """One load step of the period being solved."""

    normal: NormalState
    state: TangentialState
    energy: FloatArray


def _energy(
    old: TangentialState, new: TangentialState, before: NormalState, after: NormalState
) -> FloatArray:
    """Frictional dissipation q ds of one step, per unit area, at every element.

    The slip of the step times the traction while slipping: the mean of the two ends' where
    the element slipped the same way at both (trapezoid, second order in the step), half the
    end traction where it came into contact during the step (its traction rose from zero),
    half the start traction where it left, and the end traction where it started to slip
    (its traction reached the limit before it moved).
    """
    kept = (old.slip_sign == new.slip_sign) & (new.slip_sign != 0)
    traction = np.where(kept, 0.5 * (old.shear + new.shear), new.shear)
    traction = np.where(after.contact & ~before.contact, 0.5 * new.shear, traction)
    traction = np.where(before.contact & ~after.contact, 0.5 * old.shear, traction)
    return traction * new.slip_increment


def solve(
    contact: Any,
    loading: LoadCycle | LoadPath | Any,
    mu: float,
    *,
    elements: int = DEFAULT_ELEMENTS,
    steps: int = DEFAULT_STEPS,
    E_star: float | None = None,
    tolerance: float = DEFAULT_TOLERANCE,
    max_cycles: int = DEFAULT_MAX_CYCLES,
    domain: tuple[float, float] | None = None,
) -> SolverResult:
    """Solve the frictional contact incrementally along a load path to its steady state.

    Parameters
    ----------
    contact
        A built-in law with a profile (``HertzLaw``, ``FlatRoundedLaw``, ``PowerLaw``; its E*
        is used), or a :class:`~asymslip.solver.profiles.Profile` (``ExpressionProfile``,
        ``TableProfile``) with ``E_star`` given.
    loading
        The paper's cycle (:class:`asymslip.LoadCycle`: state 1, state 2, back), or a
        :class:`~asymslip.solver.path.LoadPath` of (P, Q, sigma, M) points.
    mu
        Coulomb friction coefficient, > 0.
    elements
        Number of elements N of the grid over the computational domain (the largest contact
        plus 3 % on each side), at least 64.
    steps
        Load steps per segment of the path, at least 1.  Where one edge sticks under bulk
        tension the stick boundary of the other converges like 1/steps (about 0.02 element
        off at the default 20); otherwise the steps change it by less than 1e-3 element.
    E_star
        Plane-strain contact modulus; needed with a profile, optional with a law.
    tolerance
        Steady-state tolerance: the largest change of a shear traction over one period,
        relative to mu max p.
    max_cycles
        Most periods to run; if the steady state is not reached the result says so
        (``steady`` False, and a warning).
    domain
        (left, right) of the computational domain, instead of the automatic choice.

    Returns
    -------
    SolverResult

    Raises
    ------
    InputError
        Invalid input, naming the parameter and the rule (see the messages).
    SolverError
        The numerical iteration did not converge (never an unconverged answer).

    Examples
    --------
    >>> from asymslip import HertzLaw, LoadCycle
    >>> from asymslip.solver import solve
    >>> result = solve(HertzLaw(R=1, E_star=1), LoadCycle(100, 0, 105, 1), mu=0.1,
    ...                elements=500, steps=10)
    >>> result.steady, result.right.slip_direction
    (True, 1)
    >>> abs(result.right.b - 11.14185) < result.right.b_error
    True
    """
    started = time.perf_counter()
    mu = float(positive("mu", mu))
    elements = _integer(
        "elements",
        elements,
        MIN_ELEMENTS,
        f"must be at least {MIN_ELEMENTS} (the boundary fits need several elements in every zone)",
    )
    steps = _integer("steps", steps, 1, "must be at least 1 (load steps per segment)")
    max_cycles = _integer(
        "max_cycles",
        max_cycles,
        2,
        "must be at least 2 (a steady state is seen by repeating a period)",
    )
    tolerance = float(positive("tolerance", tolerance))
    profile = as_profile(contact)
    E_star = _modulus(contact, E_star)
    path = as_path(loading)
    path.check_partial_slip(mu)
    is_cycle = isinstance(loading, LoadCycle)

    # Loads, moduli or lengths so far from 1 that the influence sums overflow (loads of 1e300)
    # are refused, never answered with inf or NaN.
    with np.errstate(over="raise"):
        try:
            if domain is not None:
                left, right = (float(v) for v in as_float_array("domain", domain))
                if not right > left:
                    raise InputError("domain", "must be (left, right) with right > left", domain)
                attempts = [(left, right)]
            else:
                left, right = choose_domain(profile, E_star, path)
                width = right - left
                attempts = [(left, right), (left - width, right + width)]
            for left, right in attempts:
                grid = Grid.spanning(left, right, elements)
                try:
                    return _run(
                        profile,
                        E_star,
                        path,
                        mu,
                        grid,
                        steps,
                        tolerance,
                        max_cycles,
                        is_cycle,
                        started,
                    )
                except ContactOutsideGrid:
                    continue
        except FloatingPointError:
            raise InputError(
                "cycle",
                "the reference solver overflows double precision for these "
                "loads and this modulus: give them in units that keep the "
                "pressures far from 1e308",
            ) from None
    raise InputError(
        "domain", "the contact reaches the end of the computational domain; give a wider domain"
    )


def _run(
    profile: Profile,
    E_star: float,
    path: LoadPath,
    mu: float,
    grid: Grid,
    steps: int,
    tolerance: float,
    max_cycles: int,
    is_cycle: bool,
    started: float,
) -> SolverResult:
    heights = profile.checked_heights(grid.centres)
    _check_moment(profile, grid, heights, path)
    operators = InfluenceOperators(grid, E_star)
    normal_solver = NormalSolver(grid, operators, heights)
    tangential = TangentialSolver(grid, operators, mu)
    counters = {"steps": 0, "solves": 0, "cg": 0, "fallbacks": 0}

    def advance(
        state: TangentialState,
        normal: NormalState,
        Q: float,
        sigma: float,
        predicted: NDArray[np.int8] | None = None,
        previous: NormalState | None = None,
    ) -> TangentialState:
        new = tangential.step(state, normal, Q, sigma, predicted, previous)
        counters["steps"] += 1
        counters["solves"] += new.iterations
        counters["cg"] += new.cg_iterations
        counters["fallbacks"] += int(new.fallback)
        return new

    initial = path.initial_loads(steps)
    normal = normal_solver.solve(initial[0, 0], initial[0, 3])
    state = tangential.initial()
    for _, Q, sigma, _ in initial[1:]:
        state = advance(state, normal, Q, sigma)

    segments = path.segment_loads(steps)
    normals: list[list[NormalState | None]] = [[None] * steps for _ in segments]
    change = np.inf
    steady = False
    cycles = 0
    records: list[_StepRecord] = []
    while cycles < max_cycles:
        cycles += 1
        start = state
        records = []
        for s, loads in enumerate(segments):
            previous_step: tuple[NormalState, TangentialState] | None = None
            for j, (P, Q, sigma, M) in enumerate(loads):
                cached = normals[s][j]
                if cached is None:
                    guess = normal.contact
                    if previous_step is not None:  # the contact's ends move steadily too
                        guess = extrapolated_contact(previous_step[0], normal)
                    cached = normal_solver.solve(P, M, guess)
                    normals[s][j] = cached
                # Within a segment the slip zones grow steadily: extrapolate the last two steps.
                # At a segment's start (a reversal, for the paper's cycle) everything sticks.
                if previous_step is None:
                    predicted = np.zeros(grid.count, dtype=np.int8)
                else:
                    predicted = predict_slip(mu, previous_step, (normal, state), cached)
                previous_step = (normal, state)
                before, normal = normal, cached
                new = advance(state, normal, Q, sigma, predicted, before)
                records.append(_StepRecord(normal, new, _energy(state, new, before, normal)))
                state = new
        # Each step's solution is unique, so the shear state at the start of a period decides
        # the whole period: when a period ends where it began, it repeats forever.
        scale = mu * max(float(r.normal.pressure.max()) for r in records)
        previous_change, change = change, float(np.max(np.abs(state.shear - start.shear))) / scale
        # The approach is geometric: with the ratio r of the last two changes the changes
        # still to come sum to change r/(1 - r), which must be within the tolerance too.
        ratio = change / previous_change if np.isfinite(previous_change) and previous_change else 0
        remaining = change * ratio / (1 - ratio) if ratio < 1 else np.inf
        if change <= tolerance and remaining <= tolerance:
            steady = True
            break
    return _build(
        profile,
        E_star,
        path,
        mu,
        grid,
        steps,
        tolerance,
        is_cycle,
        records,
        cycles,
        steady,
        change,
        counters,
        started,
    )


# --- post-processing --------------------------------------------------------------------------


def _central_run(mask: NDArray[np.bool_], anchor: NDArray[np.bool_]) -> tuple[int, int] | None:
    """(first, last) of the run of ``mask`` overlapping ``anchor`` most (else the longest)."""
    runs = Runs.of(mask)
    if not runs.starts:
        return None
    overlaps = [int(anchor[a:b].sum()) for a, b in zip(runs.starts, runs.stops, strict=True)]
    lengths = runs.lengths
    best = max(range(len(lengths)), key=lambda i: (overlaps[i], lengths[i]))
    return runs.starts[best], runs.stops[best] - 1


def _edge_state(
    grid: Grid,
    mu: float,
    normal: NormalState,
    state: TangentialState,
    anchor: NDArray[np.bool_],
    side: Edge,
) -> EdgeState:
    direction = ORIENTATION[side]
    edge_index = normal.last if direction > 0 else normal.first
    a, a_error = measured(side, locate(grid, normal.pressure, edge_index, direction))
    stick = normal.contact & (state.slip_sign == 0)
    run = _central_run(stick, anchor)
    if run is None:
        return EdgeState(a, a_error, None, None, 0)
    end = run[1] if direction > 0 else run[0]
    outside = end + direction
    sign = int(state.slip_sign[outside]) if normal.contact[outside] else 0
    if sign == 0:  # the stick zone reaches the contact edge
        return EdgeState(a, a_error, a, a_error, 0)
    reserve = mu * normal.pressure - sign * state.shear
    b, b_error = measured(side, locate(grid, reserve, end, direction))
    return EdgeState(a, a_error, b, b_error, sign * direction)


def _permanent_boundary(
    grid: Grid,
    mu: float,
    records: list[_StepRecord],
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
    slipping = [
        i
        for i, r in enumerate(records)
        if r.normal.contact[outside] and r.state.slip_sign[outside] != 0
    ]
    if slipping:
        chosen = [i for i in slipping if i in vertex_steps] or slipping
        reserve = np.zeros(grid.count)
        for i in chosen:
            r = records[i]
            reserve += mu * r.normal.pressure - r.state.slip_sign[outside] * r.state.shear
        candidates.append(locate(grid, reserve, end, direction))
    normals = {id(r.normal): r.normal for r in records if not r.normal.contact[outside]}
    candidates.extend(locate(grid, n.pressure, end, direction) for n in normals.values())
    return min(candidates, key=lambda boundary: direction * boundary.x)


def _significant_slip(records: list[_StepRecord]) -> list[_StepRecord]:
    """The period's steps with slips below SLIP_SIGNIFICANCE of the largest one set to zero.

    A steady state is approached geometrically: the last period still carries residual slips,
    of the order of the steady tolerance, where the limit has none (the permanent stick
    zone).  Counted as slip they would shrink that zone; they are far below any slip of a real
    slip zone except within a tiny fraction of an element of its boundary.
    """
    largest = max(float(np.max(np.abs(r.state.slip_increment))) for r in records)
    threshold = SLIP_SIGNIFICANCE * largest
    out = []
    for r in records:
        significant = np.abs(r.state.slip_increment) > threshold
        state = replace(
            r.state,
            slip_sign=np.where(significant, r.state.slip_sign, 0).astype(np.int8),
            slip_increment=np.where(significant, r.state.slip_increment, 0.0),
        )
        out.append(_StepRecord(r.normal, state, np.where(significant, r.energy, 0.0)))
    return out


def _build(
    profile: Profile,
    E_star: float,
    path: LoadPath,
    mu: float,
    grid: Grid,
    steps: int,
    tolerance: float,
    is_cycle: bool,
    records: list[_StepRecord],
    cycles: int,
    steady: bool,
    change: float,
    counters: dict[str, int],
    started: float,
) -> SolverResult:
    warnings: list[str] = []
    if not steady:
        warnings.append(
            f"no steady state after {cycles} periods: the tractions still changed by "
            f"{change:.3g} mu max p (tolerance {tolerance:g}) or the stick/slip state moved; "
            "the results are those of the last period"
        )
    records = _significant_slip(records)
    in_contact_always = np.logical_and.reduce([r.normal.contact for r in records])
    never_slips = np.logical_and.reduce([r.state.slip_sign == 0 for r in records])
    permanent = in_contact_always & never_slips
    slip = np.cumsum([r.state.slip_increment for r in records], axis=0)
    slip_range = np.maximum(slip.max(axis=0), 0.0) - np.minimum(slip.min(axis=0), 0.0)
    energy = np.sum([r.energy for r in records], axis=0)
    vertex_steps = {(s + 1) * steps - 1 for s in range(path.count)}
    states = []
    for k in range(path.count):
        # Point k ends segment k - 1 (point 1 ends the period); the period starts at point 1.
        index = (k - 1) % path.count
        record = records[(index + 1) * steps - 1]
        P, Q, sigma, M = path.points[k]
        shift = slip[k * steps - 1] if k > 0 else np.zeros(grid.count)
        states.append(
            StateResult(
                label=path.labels[k],
                P=float(P),
                Q=float(Q),
                sigma=float(sigma),
                M=float(M),
                pressure=record.normal.pressure,
                contact=record.normal.contact,
                shear=record.state.shear,
                slip_sign=record.state.slip_sign,
                slip=shift,
                approach=record.normal.approach,
                tilt=record.normal.tilt,
                right=_edge_state(grid, mu, record.normal, record.state, permanent, "right"),
                left=_edge_state(grid, mu, record.normal, record.state, permanent, "left"),
            )
        )
    run = _central_run(permanent, permanent)
    runs = Runs.of(permanent)
    if len(runs.starts) > 1:
        warnings.append(
            f"the permanent stick zone is in {len(runs.starts)} pieces; b refers to the longest"
        )
    loaded = int(np.argmax(path.points[:, 0]))
    loaded_step = records[((loaded - 1) % path.count + 1) * steps - 1]
    edges = {}
    for side in ("right", "left"):
        if run is None:
            direction = states[loaded].edge(side).slip_direction
            edges[side] = EdgeResult(side, None, None, None, direction)
            continue
        end = run[1] if side == "right" else run[0]
        # The edge's slip direction: that of the element just outside the permanent stick
        # zone at the point of largest load (state 2 of the paper's cycle: on loading); 0 if
        # it does not slip there (e.g. only the annulus a1 < |x| < a2 ever slips).
        outside = end + ORIENTATION[side]
        direction = int(loaded_step.state.slip_sign[outside]) * ORIENTATION[side]
        boundary = _permanent_boundary(grid, mu, records, vertex_steps, end, side)
        b, b_error = measured(side, boundary)
        edges[side] = EdgeResult(side, b, b_error, boundary.method, direction)
        if is_cycle and direction != 0:
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
        E_star=E_star,
        profile=profile.describe(),
        path=path,
        is_cycle=is_cycle,
        states=tuple(states),
        permanent_stick=permanent,
        slip_range=slip_range,
        energy=energy,
        right=edges["right"],
        left=edges["left"],
        steps=steps,
        cycles=cycles,
        steady=steady,
        steady_change=float(change),
        tolerance=tolerance,
        load_steps=counters["steps"],
        active_set_solves=counters["solves"],
        cg_iterations=counters["cg"],
        fallbacks=counters["fallbacks"],
        seconds=time.perf_counter() - started,
        warnings=tuple(warnings),
    )
