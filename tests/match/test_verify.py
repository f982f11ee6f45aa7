"""The match verified by the reference solver on three prototypes (issue 19): a rounded flat
with bulk tension, a power-law punch n = 3, and an asymmetric punch under a moment known only
through calibrated pressure traces.

For each: the solver's slip-zone widths of prototype and rig agree within the match's stated
accuracy plus two elements of each solve; the near-edge shear change q2 - q1 and the slip of the
two solves, compared in the edge's own coordinate over the prototype's slip zone, differ by no
more than a tolerance the test measures -- the solver's own grid noise on this comparison (the
prototype against itself on a grid of 1.37 times as many elements, so that the element centres
fall elsewhere relative to the edge) -- plus the expansion allowance (a2 - b)/a1, the relative
size of the first terms the leading-order match neglects at the far end of the slip zone.
The near-edge stress amplitude of the two agrees within the asymptotes' stated accuracies from
both sources (:mod:`asymslip.match.near_edge_stress`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
import pytest

from asymslip import LoadCycle
from asymslip.match import Rig, SolverProblem, match, verify
from asymslip.match.verification import largest_difference, solve_edge
from tests.match.cases import BLADE, BLADE_CYCLE, MU, POWER, POWER_CYCLE

solver = pytest.importorskip("asymslip.solver")

pytestmark = pytest.mark.slow

# The asymmetric punch of tests/calibration/test_solver_asymmetric.py: h = x^2/2 + k x^3 with a
# moment that grows with the load, so its two edges have different laws and multipliers.
PROFILE = ("x**2/2 + k*x**3", {"k": 0.005})
LOADS = (80.0, 90.0, 100.0, 105.0, 110.0, 120.0)
DOMAIN = (-14.5, 14.0)
ASYMMETRIC_MU, ASYMMETRIC_LAM = 0.1, 0.2


def moment(P: float) -> float:
    return 0.3 * (P - 100.0)


@dataclass(frozen=True)
class Prototype:
    law: Any
    cycle: LoadCycle
    mu: float
    problem: SolverProblem | None
    elements: int


def _calibrated_punch() -> Prototype:
    from asymslip.calibration import Traces, calibrate
    from asymslip.laws.calibrated import CalibratedLaw

    profile = solver.ExpressionProfile(*PROFILE)
    points = np.array([[P, 0.0, 0.0, moment(P)] for P in LOADS])
    normal = solver.solve(
        profile, solver.LoadPath(points), mu=0.5, E_star=1.0, elements=1000, steps=2, domain=DOMAIN
    )
    x = normal.x
    P = np.concatenate([np.full(x.size, state.P) for state in normal.states])
    p = np.concatenate([state.pressure for state in normal.states])
    law = CalibratedLaw(calibrate(Traces.from_arrays(P, np.tile(x, len(normal.states)), p)))
    dQ = ASYMMETRIC_LAM * 5.0
    path = solver.LoadPath(
        np.array([[100.0, 0.0, 0.0, moment(100.0)], [105.0, dQ, 0.0, moment(105.0)]])
    )
    problem = SolverProblem(profile, path, E_star=1.0, domain=DOMAIN)
    return Prototype(law, LoadCycle(100.0, 0.0, 105.0, dQ), ASYMMETRIC_MU, problem, 2000)


PROTOTYPES = {
    "rounded flat with tension": lambda: Prototype(BLADE, BLADE_CYCLE, MU, None, 2000),
    "power law n = 3": lambda: Prototype(POWER, POWER_CYCLE, MU, None, 4000),
    "asymmetric punch under a moment, calibrated": _calibrated_punch,
}


def _grid_noise(prototype: Prototype, side: str) -> tuple[float, float]:
    """The comparison of the prototype with itself on two grids: q2 - q1 and slip."""
    problem = prototype.problem or SolverProblem(prototype.law, prototype.cycle)
    solved = [
        solve_edge(
            problem.contact,
            problem.loading,
            prototype.mu,
            side,
            elements,
            problem.E_star,
            problem.domain,
        )
        for elements in (prototype.elements, int(1.37 * prototype.elements) + 1)
    ]
    return (
        largest_difference(solved[0], solved[1], "q_diff"),
        largest_difference(solved[0], solved[1], "slip"),
    )


@pytest.mark.parametrize("name", list(PROTOTYPES))
def test_the_solver_confirms_the_rig_reproduces_the_edge(name):
    prototype = PROTOTYPES[name]()
    side = "right"
    result = match(prototype.law, prototype.cycle, prototype.mu, Rig("hertz", 1.0), edge=side)
    assert result.exact
    check = verify(result, prototype.problem, elements=prototype.elements)
    assert check.compared_points >= 15, check.compared_points
    allowed = result.accuracy + 2 * check.prototype.element + 2 * check.rig.element
    assert abs(check.width_difference) <= allowed, (check.width_difference, allowed)
    noise_q, noise_slip = _grid_noise(prototype, side)
    print(
        f"{name}: widths {check.prototype.width:.5g} / {check.rig.width:.5g} (difference "
        f"{check.width_difference:.3g}, allowed {allowed:.3g}); shear change "
        f"{check.shear_change_difference:.4f} (grid noise {noise_q:.4f}, allowance "
        f"{check.expansion_allowance:.4f}); slip {check.slip_difference:.4f} (grid noise "
        f"{noise_slip:.4f})"
    )
    assert check.shear_change_difference <= noise_q + check.expansion_allowance
    assert check.slip_difference <= noise_slip + check.expansion_allowance
    for item in check.stress:
        print(
            f"  stress amplitude ({item.source}): difference {item.difference:.3g}, stated "
            f"accuracy {item.allowed:.3g}, explained {item.explained}"
        )
    # The near-edge stress amplitude (state 2 - state 1) of prototype and rig: the same within
    # the two asymptotes' stated accuracies, by the asymptotes and by the solvers' fields.
    asymptote, solved = check.stress
    assert asymptote.within_stated_accuracy and solved.within_stated_accuracy
    assert solved.explained
