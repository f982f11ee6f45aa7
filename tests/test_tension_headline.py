"""With bulk tension the headline b is the second-order b2, not the paper's (22): the reference
solver decides (the issue's finding, erratum 22-T).

Hertz, mu = 0.3, a1 = 2, a2/a1 = 1.10, lambda = 2 mu, pi eta a1/4 = 0.2 (both edges slip,
opposite ways in the global frame).  Errors in units of the solver's stated bound on its
stick boundary (at least one element).
"""

from __future__ import annotations

import math

import pytest

from asymslip import HertzLaw, LoadCycle, slip_zone
from asymslip.solver import solve

MU, A1, RATIO = 0.3, 2.0, 1.10
LAW = HertzLaw(R=1.0, E_star=1.0)


@pytest.fixture(scope="module")
def tension_case():
    P1, P2 = float(LAW.load(A1)), float(LAW.load(RATIO * A1))
    dP = P2 - P1
    lam, eta = 2 * MU, 0.2 * 4 / (math.pi * A1)
    cycle = LoadCycle(P1, 0.0, P2, lam * dP, 0.0, eta * dP)
    return slip_zone(LAW, cycle, MU, edge="both"), solve(LAW, cycle, MU, elements=2000)


@pytest.mark.parametrize("edge", ["right", "left"])
def test_the_headline_b_lies_within_the_solver_bound_at_both_edges(tension_case, edge):
    asymptotic, solved = tension_case
    estimate, truth = (
        (asymptotic, solved.right) if edge == "right" else (asymptotic.left, solved.left)
    )
    assert abs(estimate.b - truth.b) <= truth.b_error


@pytest.mark.parametrize("edge", ["right", "left"])
def test_the_paper_eq22_misses_by_several_solver_bounds_with_tension(tension_case, edge):
    asymptotic, solved = tension_case
    estimate, truth = (
        (asymptotic, solved.right) if edge == "right" else (asymptotic.left, solved.left)
    )
    assert abs(estimate.b_paper - truth.b) > 3 * truth.b_error
    assert any(text.startswith("(22) (b_paper) differs from b") for text in estimate.warnings)


def test_the_headline_states_an_accuracy_the_solver_confirms(tension_case):
    asymptotic, solved = tension_case
    for estimate, truth in ((asymptotic, solved.right), (asymptotic.left, solved.left)):
        assert abs(estimate.b - truth.b) <= estimate.b_accuracy + truth.b_error
