"""The slip displacement on loading: the integral of the density (15), with its sign stated.

The reference integrates the paper's (15), transcribed by hand, with mpmath, using the stick
boundary and multipliers the API reports; the sign convention is checked against friction
itself: the traction resists the slip.
"""

from __future__ import annotations

import mpmath
import numpy as np
import pytest

from asymslip import HertzLaw, LoadCycle, slip_zone
from asymslip.tractions import slip_displacement, traction_difference
from tests.transcription.section2 import eq15

LAW = HertzLaw(R=1.0, E_star=2.0)
MU = 0.1
CYCLE = LoadCycle(100.0, 0.0, 105.0, 1.0)  # Fig. 5 loads: forward slip at the right edge


def slip_by_quadrature(x: float, edge) -> float:
    """int_b^x B(a2 - t) dt with B from (15), 30 digits (zero in the stick zone)."""
    if x <= edge.b_paper:  # (15) is built on the b of (17)/(22)
        return 0.0
    with mpmath.workdps(30):

        def density(t):
            return eq15(
                float(t),
                edge.b_paper,
                edge.a1,
                MU,
                edge.L_I1,
                edge.L_I2,
                edge.L_II1,
                edge.L_II2,
                2.0,
            )

        points = [edge.b_paper, *([edge.a1] if edge.b_paper < edge.a1 < x else []), x]
        return float(mpmath.quad(lambda t: mpmath.mpf(density(t)), points))


def test_slip_equals_the_quadrature_of_the_density_15_to_1e_10():
    # The density (15) integrates to the lower body's displacement relative to the indenter's;
    # delta is the indenter's relative to the lower body's (SLIP_CONVENTION): minus it.
    edge = slip_zone(LAW, CYCLE, MU)
    x = np.linspace(edge.b - 0.05, edge.a2 - 1e-9, 9)
    computed = slip_displacement(LAW, CYCLE, MU, x).slip
    reference = [-slip_by_quadrature(float(point), edge) for point in x]
    assert computed == pytest.approx(reference, rel=1e-10, abs=1e-14)


def test_the_stick_zone_does_not_slip():
    edge = slip_zone(LAW, CYCLE, MU)
    assert slip_displacement(LAW, CYCLE, MU, [0.0, edge.b_paper * 0.999]).slip == [0.0, 0.0]


def test_in_a_slip_zone_the_slip_has_the_sign_of_the_traction_change():
    # Coulomb: the sliding indenter drags the lower body along its own slip.
    edge = slip_zone(LAW, CYCLE, MU)
    x = np.linspace(edge.b + 0.01, edge.a2 - 0.01, 5)
    slip = np.array(slip_displacement(LAW, CYCLE, MU, x).slip)
    traction = np.array(traction_difference(LAW, CYCLE, MU, x).q_diff)
    assert np.all(traction > 0) and np.all(slip > 0)


def test_both_edges_slip_the_same_way_in_the_global_frame_when_the_shear_force_grows():
    a2 = slip_zone(LAW, CYCLE, MU).a2
    right = slip_displacement(LAW, CYCLE, MU, [0.999 * a2]).slip[0]
    left = slip_displacement(LAW, CYCLE, MU, [-0.999 * a2], edge="left").slip[0]
    assert right > 0 and left == pytest.approx(right, rel=1e-14)  # symmetric contact, eta = 0


@pytest.mark.xfail(
    strict=True,
    reason="the solver's slip.csv is delta, opposite to q2 - q1 (branch solver); "
    "slip_displacement returns to the same delta on branch core2: remove this mark then",
)
def test_the_slip_is_the_reference_solvers_slip_csv_in_sign_and_size():
    # The solver's slip.csv column slip_2: u_x(indenter) - u_x(lower body) accumulated from
    # state 1 to state 2 (asymslip.solver.outputs), the same convention.
    from asymslip.solver import solve

    solved = solve(LAW, CYCLE, MU, elements=2000)
    loaded = solved.states[1]
    assert loaded.label == "2"
    edge = slip_zone(LAW, CYCLE, MU)
    # Where both states are in contact, b < x < a1; in the annulus a1 < x < a2, in contact at
    # state 2 only, the solver's relative displacement differs (noted in issue 17's report).
    inside = (solved.x > edge.b + 0.02) & (solved.x < edge.a1)
    x = solved.x[inside]
    asymptotic = np.array(slip_displacement(LAW, CYCLE, MU, x).slip)
    assert np.all(np.sign(asymptotic) == np.sign(loaded.slip[inside]))
    # within 2 % of the largest slip there: the solver's own error at N = 2000
    scale = np.max(np.abs(loaded.slip[inside]))
    assert np.max(np.abs(asymptotic - loaded.slip[inside])) < 0.02 * scale
