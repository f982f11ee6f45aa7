"""The reach of the slip prediction and the steady check's floor at the solves' resolution.

The paper's Fig. 5 cycle (Hertz, R = E* = 1, P1 = 100, Q1 = 0, P2 = 105, Q2 = 1, mu = 0.1, 20
steps a half-cycle) on 10^4 elements.  The references are independent of the code under test:
a solve of the same programme to a relative residual of 1e-14 (the solver's own to 1e-11), and
the same cycle solved with the prediction unbounded (the solution is unique: a guess changes
the work, never the answer).
"""

from __future__ import annotations

import numpy as np
import pytest

from asymslip import HertzLaw, LoadCycle
from asymslip.solver import settings as settings_module
from asymslip.solver import solve
from asymslip.solver import tangential as tangential_module
from asymslip.solver.qp import Workspace
from asymslip.solver.settings import steady_resolution
from asymslip.solver.tangential import distance_to

LAW = HertzLaw(R=1.0, E_star=1.0)
CYCLE = LoadCycle(100.0, 0.0, 105.0, 1.0)
MU = 0.1
ELEMENTS = 10_000


def _solve_counting(monkeypatch: pytest.MonkeyPatch) -> tuple[object, list[int], list[tuple]]:
    """The Fig. 5 cycle, with each tangential step's solves and its programme recorded."""
    solves: list[int] = []
    programmes: list[tuple] = []
    step, solve_box_qp = tangential_module.TangentialSolver.step, tangential_module.solve_box_qp

    def counted(self, *args, **kwargs):  # type: ignore[no-untyped-def]
        state = step(self, *args, **kwargs)
        solves.append(state.iterations)
        return state

    def kept(qp, at_lower, at_upper, **kwargs):  # type: ignore[no-untyped-def]
        solution = solve_box_qp(qp, at_lower, at_upper, **kwargs)
        programmes[:] = [(qp, solution)]  # only the last one is kept (memory)
        return solution

    monkeypatch.setattr(tangential_module.TangentialSolver, "step", counted)
    monkeypatch.setattr(tangential_module, "solve_box_qp", kept)
    result = solve(LAW, CYCLE, MU, elements=ELEMENTS, steps=20)
    return result, solves, programmes


def test_distances_to_a_set_count_elements_either_way():
    mask = np.zeros(9, dtype=bool)
    mask[[2, 6]] = True
    assert distance_to(mask).tolist() == [2, 1, 0, 1, 2, 1, 0, 1, 2]


def test_the_bounded_prediction_takes_the_reloadings_penultimate_step_in_one_solve(monkeypatch):
    # Unbounded, the r^2 extrapolation marks a band that stays stuck at the end of the
    # reloading, and the active set walks it back (4 solves measured at 10^4, 13 at 10^6).
    result, counted, _ = _solve_counting(monkeypatch)
    solves = list(counted)  # the second run's wrapper calls this one's too
    assert result.steady and result.load_steps == 60
    assert solves[-2] == 1
    monkeypatch.setattr(tangential_module, "PREDICTION_REACH", 10**9)
    unbounded, unbounded_solves, _ = _solve_counting(monkeypatch)
    assert unbounded_solves[-2] >= 3
    assert sum(solves) < sum(unbounded_solves)
    # The same answer (a unique solution): the stick boundaries within 1e-6 element.
    element = result.element_size
    assert abs(result.right.b - unbounded.right.b) < 1e-6 * element
    assert abs(result.left.b - unbounded.left.b) < 1e-6 * element


def test_a_solve_of_state_2_is_within_the_steady_resolution_of_the_exact_one(monkeypatch):
    # The last step solved is state 2 (1.5 periods); solved again from zero to 1e-14 with the
    # same stick/slip sets, it differs by the solver's own error (7.0e-10 mu max p measured),
    # which two solves may double: within steady_resolution(10^4) = 2e-9, and the steady
    # check asks for no finer change than that.
    _, _, programmes = _solve_counting(monkeypatch)
    qp, solution = programmes[0]
    tight, _, _ = Workspace().solve(
        qp, solution.at_lower, solution.at_upper, np.zeros_like(solution.y), 1e-14
    )
    scale = float(np.max(qp.upper[qp.domain]))  # mu max p of the step
    assert np.max(np.abs(tight - solution.y)) <= 0.5 * steady_resolution(ELEMENTS) * scale


def test_the_steady_resolution_grows_like_n_to_the_three_halves():
    assert steady_resolution(2_000) == settings_module.RESOLUTION
    assert steady_resolution(10_000) == settings_module.RESOLUTION
    assert np.isclose(steady_resolution(1_000_000), 1e3 * settings_module.RESOLUTION)


def test_the_reported_steady_tolerance_is_the_one_applied():
    small = solve(LAW, CYCLE, MU, elements=2_000, steps=20)
    assert small.tolerance == 1e-8  # the default: finer than the solves' resolution needs
    assert small.steady and small.steady_change <= small.tolerance
    coarse = solve(LAW, CYCLE, MU, elements=2_000, steps=20, tolerance=1e-12)
    assert coarse.tolerance == steady_resolution(2_000)  # 1e-12 is below what they resolve
