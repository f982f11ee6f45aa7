"""The incremental solver: load the contact along the path, period after period, to steady state.

:func:`solve` is the entry point.  Each load step solves the normal problem at the step's
(P, M) (:mod:`.normal`; each distinct load once, :class:`~.period.NormalCache`) and then the
tangential problem from the previous step's shear state (:mod:`.tangential`).  Each step's
solution is unique (a strictly convex programme), so the shear state at any point of the path
decides everything after it: once the state at the end of a segment is the one it was a
period earlier, the period that ends there repeats forever, and its stick zones, tractions,
slips and energies are the steady ones.  The steady state is declared at the first point where,
over the last period, no shear traction changed by more than ``tolerance`` times mu max p, and
the changes still to come -- the approach is geometric: change r/(1 - r) with r the ratio of
this change to the one found at the point before -- are within the tolerance too.  A change
smaller than the solves resolve on the grid is not counted
(:attr:`~.settings.SolverSettings.steady_tolerance`).  The result
is that period, read from point 1 (:mod:`.steady`).  The paper's cycle is steady one segment
into its second period (1.5 periods: the state at state 2 repeats; before, the whole second
period was run to see state 1 repeat); 3.5 when one edge does not slip and tension is present,
whose locked-in tractions settle geometrically, by about 2500 times per period.

The work per load step is what the step needs (measured in ``tests/benchmarks/bench_solver.py``):
the normal problem only at loads not met before; the tangential problem warm-started three
ways -- its slip zones predicted from the last two steps (:func:`~.tangential.predict_slip`),
or taken from the same step a period earlier once the state repeats it; the conjugate
gradients started from the last solution, whose image under the influence matrix is carried
along so that only the change costs a product (:class:`~.qp.Workspace`); and no BLAS call in
the inner loop, so a solve runs on one thread whatever the BLAS is set to
(:mod:`.inner_products`).  Memory is one period of shear tractions and one normal solution per
distinct load, checked before the grid is allocated (:mod:`.memory`).
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..cycle import LoadCycle
from ..errors import InputError, as_float_array, positive
from .grid import Grid, InfluenceOperators
from .memory import check_memory
from .normal import ContactOutsideGrid, NormalSolver, NormalState
from .path import LoadPath, as_path
from .period import NormalCache, PeriodWindow, SlipRecord, StepRecord
from .profiles import Profile, as_profile
from .result import SolverResult
from .settings import Convergence, SolverSettings
from .steady import build_result
from .tangential import TangentialSolver, TangentialState, predict_slip
from .toeplitz import FloatArray, SolverError

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
#: The state counts as repeating the previous period's when it differs from it by at most
#: this fraction of the last step's change: the next step then starts from its own solution
#: of a period earlier (a guess, which affects only the work).
REPEAT_FRACTION = 1e-2


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
    profile_heights: Callable[[FloatArray], FloatArray],
    left: float,
    right: float,
    E_star: float,
    loads: FloatArray,
    count: int,
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
class _Work:
    """The work done so far: load steps, active-set solves, CG iterations, fallbacks."""

    steps: int = 0
    solves: int = 0
    cg: int = 0
    fallbacks: int = 0

    def count(self, state: TangentialState) -> TangentialState:
        self.steps += 1
        self.solves += state.iterations
        self.cg += state.cg_iterations
        self.fallbacks += int(state.fallback)
        return state


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
        relative to mu max p.  Where the solves on this grid resolve less, their resolution
        is applied instead (:func:`~asymslip.solver.settings.steady_resolution`: 2e-9 up to
        10^4 elements, growing like N^3/2, so above the default from about 29,000 elements);
        the result's ``tolerance`` is the one applied.
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
    check_memory(elements, steps, path)

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
                settings = SolverSettings(
                    profile, E_star, path, mu, grid, steps, tolerance, max_cycles, is_cycle
                )
                try:
                    return _run(settings, started)
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


def _run(settings: SolverSettings, started: float) -> SolverResult:
    grid, path, steps, mu = settings.grid, settings.path, settings.steps, settings.mu
    heights = settings.profile.checked_heights(grid.centres)
    _check_moment(settings.profile, grid, heights, path)
    operators = InfluenceOperators(grid, settings.E_star)
    normals = NormalCache(NormalSolver(grid, operators, heights))
    tangential = TangentialSolver(grid, operators, mu)
    work = _Work()

    initial = path.initial_loads(steps)
    normal = normals.solve(float(initial[0, 0]), float(initial[0, 3]))
    state = tangential.initial()
    for _, Q, sigma, _ in initial[1:]:
        state = work.count(tangential.step(state, normal, Q, sigma))
    initial_shear = state.shear

    segments = path.segment_loads(steps)
    window = PeriodWindow(path.count, steps)
    # The per-step change from the period before, at each step of the period: the ratio of
    # two at the same step is the geometric rate of the approach to the steady state.
    changes = np.full((path.count, steps), np.inf)
    change = np.inf
    steady = False
    cycles = 0
    repeating = False
    stick = np.zeros(grid.count, dtype=np.int8)
    for segment_number in range(settings.max_cycles * path.count):
        s = segment_number % path.count
        if s == 0:
            cycles += 1
            state = tangential.refreshed(state)
        previous_step: tuple[NormalState, TangentialState] | None = None
        for j, (P, Q, sigma, M) in enumerate(segments[s]):
            upcoming = normals.solve(float(P), float(M), steady_motion=previous_step is not None)
            earlier = window.get(s, j)  # this step, a period ago
            guess = None
            if repeating and earlier is not None:
                predicted, guess = earlier.slip.signs(grid.count), earlier.shear
            elif previous_step is None:
                # At a segment's start (a reversal, for the paper's cycle) the slip zones are
                # those of the same step a period ago; in the first period, everything sticks.
                predicted = stick if earlier is None else earlier.slip.signs(grid.count)
            else:
                # Within a segment the slip zones grow steadily: extrapolate the last two
                # steps, the slip zones as the friction reserves close, the tractions linearly.
                predicted = predict_slip(mu, previous_step, (normal, state), upcoming)
                guess = 2 * state.shear - previous_step[1].shear
            new = work.count(
                tangential.step(
                    state,
                    upcoming,
                    Q,
                    sigma,
                    predicted,
                    normal,
                    guess=guess,
                    settle=previous_step is None and not repeating,
                )
            )
            energy = _energy(state, new, normal, upcoming)
            replaced = window.put(s, j, StepRecord(upcoming, new.shear, SlipRecord.of(new, energy)))
            ago = replaced.shear if replaced is not None else None
            if ago is None and cycles == 1 and s == path.count - 1 and j == steps - 1:
                ago = initial_shear  # point 1 a period ago: the state after initial loading
            previous_step = (normal, state)
            normal, state = upcoming, new
            if ago is None:
                continue
            # Each step's solution is unique, so the state after a step decides everything
            # after it: when it is the state of a period ago, the period that ends here repeats
            # forever (read from point 1, it is the steady period).
            difference = float(np.max(np.abs(new.shear - ago)))
            moved = float(np.max(np.abs(new.shear - previous_step[1].shear)))
            repeating = difference <= REPEAT_FRACTION * moved
            change = difference / (mu * window.largest_pressure())
            # The approach is geometric: with the ratio r of this change to the one at the
            # same step a period earlier, the changes still to come sum to change r/(1 - r),
            # which must be within the tolerance too.
            last = changes[s, j]
            ratio = change / last if np.isfinite(last) and last else 0.0
            remaining = change * ratio / (1 - ratio) if ratio < 1 else np.inf
            changes[s, j] = change
            if change <= settings.steady_tolerance and remaining <= settings.steady_tolerance:
                steady = True
                break
        if steady:
            break
    convergence = Convergence(
        cycles,
        steady,
        change,
        work.steps,
        work.solves,
        work.cg,
        work.fallbacks,
        len(normals),
    )
    return build_result(settings, window.records(), convergence, time.perf_counter() - started)
