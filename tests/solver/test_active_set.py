"""The active-set iteration's safeguards: settled ends, cycles, a fallback that starts near.

Each is checked against the dense optimality conditions of ``test_linear_algebra`` (a strictly
convex programme has one KKT point), so a safeguard can change the work, never the answer.
"""

from __future__ import annotations

import numpy as np
import pytest

from asymslip import HertzLaw
from asymslip.solver import qp as qp_module
from asymslip.solver.grid import Grid, InfluenceOperators
from asymslip.solver.normal import NormalSolver
from asymslip.solver.qp import Workspace, settle_ends, solve_box_qp
from asymslip.solver.toeplitz import Checkpoint, Runs, onto_constraints, projected_cg, unpack

from .test_linear_algebra import GRID, _check_kkt, _tangential_problem


def _settle_hertz_from_short_guess(count: int) -> tuple[np.ndarray, np.ndarray, int]:
    """The normal problem of a Hertz contact (P = 100) on ``count`` elements, its ends settled
    from a guess 3 % of the contact short at each end.

    Returns the exact contact, the settled set at the lower bound and the solves taken.
    """
    law = HertzLaw(R=1.0, E_star=1.0)
    grid = Grid.spanning(-12.0, 12.0, count)
    solver = NormalSolver(grid, InfluenceOperators(grid, 1.0), law.profile(grid.centres))
    exact = solver.solve(100.0, 0.0, settle=False).contact
    first, last = int(np.argmax(exact)), exact.size - 1 - int(np.argmax(exact[::-1]))
    short = np.zeros_like(exact)
    shift = (last - first) * 3 // 200
    short[first + shift : last - shift + 1] = True
    lower, _, solves = settle_ends(
        solver.problem(100.0, 0.0), ~short, np.zeros_like(short), Workspace()
    )
    return exact, lower, solves


def test_settled_ends_land_within_a_few_elements_of_the_contact():
    # The normal problem of a Hertz contact from a guess 3 % short at each end: the primal-dual
    # iteration alone overshoots and halves its way back; the settled ends land next to it.
    exact, lower, solves = _settle_hertz_from_short_guess(20_000)
    settled = ~lower
    assert np.count_nonzero(settled != exact) <= 8  # of 2 x 150 elements moved
    assert solves <= qp_module.SETTLING_SOLVES


def test_settling_changes_the_work_not_the_answer():
    law = HertzLaw(R=1.0, E_star=1.0)
    grid = Grid.spanning(-12.0, 12.0, 4000)
    solver = NormalSolver(grid, InfluenceOperators(grid, 1.0), law.profile(grid.centres))
    plain = solver.solve(103.0, 0.0, settle=False)
    settled = solver.solve(103.0, 0.0, settle=True)
    assert np.array_equal(plain.contact, settled.contact)
    # Two paths of the conjugate gradients (each to a residual of 1e-11) agree to their
    # accuracy: measured 2.8e-9 of the peak pressure.
    assert np.allclose(plain.pressure, settled.pressure, rtol=0, atol=1e-8 * plain.pressure.max())


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_a_fallback_started_from_the_last_iterate_meets_the_optimality_conditions(
    seed, monkeypatch
):
    problem = _tangential_problem(seed)
    none = np.zeros(GRID.count, dtype=bool)
    monkeypatch.setattr(qp_module, "MAX_PRIMAL_DUAL", 2)  # force the fallback early
    capacity = problem.upper

    def feasible(inside: np.ndarray) -> np.ndarray:
        # The room left in the box, shared to meet the force (as the tangential solver does).
        deficit = problem.targets[0] / GRID.width - inside.sum()
        room = np.where(problem.domain, capacity - inside if deficit > 0 else inside + capacity, 0)
        return inside + np.sign(deficit) * min(1.0, abs(deficit) / room.sum()) * room

    solution = solve_box_qp(problem, none, none, feasible_start=feasible)
    assert solution.method == "primal (fallback)"
    _check_kkt(problem, solution)


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_the_checkpoint_saves_iterations_and_changes_no_answer(seed, monkeypatch):
    # From a guess with nothing at a bound (every element of the domain sticking) the first
    # solve's sets are wrong: asked at 1e3 times its target residual, it stops there.
    problem = _tangential_problem(seed)
    none = np.zeros(GRID.count, dtype=bool)
    asked = solve_box_qp(problem, none, none)
    monkeypatch.setattr(qp_module, "CHECKPOINT_FACTOR", 0.0)  # never asked
    unasked = solve_box_qp(problem, none, none)
    _check_kkt(problem, asked)
    assert np.array_equal(asked.at_lower, unasked.at_lower)
    assert np.array_equal(asked.at_upper, unasked.at_upper)
    # Two paths of the conjugate gradients, each to a residual of 1e-11: measured 1e-11.
    assert np.allclose(asked.y, unasked.y, rtol=0, atol=1e-9 * np.abs(unasked.y).max())
    assert asked.cg_iterations < unasked.cg_iterations


def test_a_checkpoint_answered_no_stops_the_conjugate_gradients_there():
    problem = _tangential_problem(1)
    free = problem.domain
    runs = Runs.of(free)
    rows = problem.rows[:, free]
    start = onto_constraints(np.zeros(runs.count), rows, problem.targets)
    # M y0 - b over the free elements, for the feasible start y0.
    residual = problem.operator.apply(unpack(start, runs, GRID.count))[free] - problem.linear[free]
    target = 1e-11 * np.abs(problem.linear[free]).max()
    full = projected_cg(problem.operator, runs, residual, rows, target=target)
    seen: list[int] = []

    def refuse(step: np.ndarray, multipliers: np.ndarray) -> bool:
        seen.append(step.size)
        return False

    stopped = projected_cg(
        problem.operator,
        runs,
        residual,
        rows,
        target=target,
        checkpoint=Checkpoint(1e4 * target, refuse),
    )
    assert stopped.abandoned and not full.abandoned
    assert seen == [runs.count]  # asked once, with the step over the runs
    assert 0 < stopped.iterations < full.iterations


def test_settled_ends_on_a_fine_grid_land_on_the_contact():
    # At N = 10^5 the solves at LOOSE_TOLERANCE leave the settled ends 2 elements off (measured);
    # at settling_tolerance (falling like N^-3/2 beyond 10^4 elements) they land on the contact.
    exact, lower, solves = _settle_hertz_from_short_guess(100_000)
    assert np.count_nonzero(~lower != exact) == 0  # each end moved by about 1,400 elements
    assert solves <= qp_module.SETTLING_SOLVES


def test_the_settling_tolerance_is_the_loose_one_up_to_ten_thousand_elements():
    assert qp_module.settling_tolerance(2_000) == qp_module.LOOSE_TOLERANCE
    assert qp_module.settling_tolerance(10_000) == qp_module.LOOSE_TOLERANCE
    # 10^6 elements: (10^4 / 10^6)^(3/2) = 10^-3 of it.
    assert np.isclose(qp_module.settling_tolerance(1_000_000), 1e-3 * qp_module.LOOSE_TOLERANCE)
