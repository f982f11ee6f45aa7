"""Profiles typed or tabulated, and load paths beyond the paper's cycle.

The independent references for general paths are the classical constant-load fretting
solutions (Hills & Nowell, Mechanics of Fretting Fatigue, Ch. 3-4): a Hertz contact under a
constant P and a shear force and bulk tension cycling in phase between (Q0, sigma0) and
(-Q0, -sigma0) has, in the steady state (Mindlin-Deresiewicz: each half-cycle is the monotonic
problem with 2Q0, 2sigma0 and 2mu), a stick zone of half-width c = a sqrt(1 - Q0/(mu P))
centred at e = -sigma0 a/(4 mu p0), p0 = 2P/(pi a): from q = mu p - mu (c/a) p0
sqrt(1 - (x - e)^2/c^2) in the stick zone, whose Hilbert transform must be the full-stick
value -sigma/4 of (38) (the tension pushes the right edge outward, so the stick zone moves left).
"""

from __future__ import annotations

import numpy as np
import pytest

from asymslip import HertzLaw, LoadCycle, PowerLaw
from asymslip.solver import ExpressionProfile, LoadPath, TableProfile, solve

HERTZ = HertzLaw(R=1.0, E_star=1.0)
CYCLE = LoadCycle(100.0, 0.0, 105.0, 1.0)


def test_typed_profile_reproduces_the_hertz_law():
    law = solve(HERTZ, CYCLE, 0.1, elements=500, steps=5)
    typed = solve(
        ExpressionProfile("x**2/(2*R)", {"R": 1.0}),
        CYCLE,
        0.1,
        E_star=1.0,
        elements=500,
        steps=5,
        domain=(law.grid.start, law.grid.end),
    )
    assert np.allclose(typed.q_diff, law.q_diff, rtol=0, atol=1e-12)
    assert typed.right.b == pytest.approx(law.right.b, rel=1e-12)


@pytest.mark.parametrize("interpolation, points", [("pchip", 41), ("linear", 401)])
def test_tabulated_hertz_profile_gives_the_stick_boundary_of_the_law(interpolation, points):
    x = np.linspace(-14.0, 14.0, points)
    table = TableProfile(x, x**2 / 2, interpolation)
    result = solve(table, CYCLE, 0.1, E_star=1.0, elements=500, steps=5)
    exact = float(HERTZ.half_width(97.5))  # a(P_K) of (33)
    assert abs(result.right.b - exact) <= result.element_size
    assert abs(result.left.b - exact) <= result.element_size


def test_pchip_passes_through_the_points_without_overshoot_and_is_smooth():
    x = np.array([-3.0, -1.0, 0.0, 0.5, 2.0, 4.0])
    h = np.array([4.0, 0.5, 0.0, 0.1, 1.5, 6.0])
    table = TableProfile(x, h)
    assert np.allclose(table.heights(x), h, rtol=0, atol=1e-15)
    fine = np.linspace(-3.0, 4.0, 7001)
    values = table.heights(fine)
    # monotone data on each side of the minimum stay monotone (Fritsch-Carlson)
    assert np.all(np.diff(values[fine <= 0.0]) <= 1e-15)
    assert np.all(np.diff(values[fine >= 0.0]) >= -1e-15)
    # C1: the slope is continuous at the interior points
    for knot in x[1:-1]:
        left = (table.heights(np.array([knot])) - table.heights(np.array([knot - 1e-7]))) / 1e-7
        right = (table.heights(np.array([knot + 1e-7])) - table.heights(np.array([knot]))) / 1e-7
        assert left == pytest.approx(right, abs=1e-5)
    # beyond the table: the end tangents
    slope = (table.heights(np.array([4.0])) - table.heights(np.array([4.0 - 1e-7]))) / 1e-7
    assert table.heights(np.array([5.0]))[0] == pytest.approx(6.0 + slope[0], rel=1e-6)


def test_csv_files_are_read(tmp_path):
    profile_file = tmp_path / "profile.csv"
    profile_file.write_text("x,h\n-2,2\n0,0\n1,0.5\n2,2\n")
    table = TableProfile.from_csv(profile_file)
    assert table.heights(np.array([1.0]))[0] == pytest.approx(0.5)
    path_file = tmp_path / "path.csv"
    path_file.write_text("P,Q,M\n100,0,\n105,1,0.5\n")
    path = LoadPath.from_csv(path_file)
    assert path.points.tolist() == [[100.0, 0.0, 0.0, 0.0], [105.0, 1.0, 0.0, 0.5]]


def test_csv_path_errors_name_the_line(tmp_path):
    from asymslip import InputError

    path_file = tmp_path / "path.csv"
    path_file.write_text("P,Q\n100,0\n105,one\n")
    with pytest.raises(InputError, match="line 3: Q must be a number"):
        LoadPath.from_csv(path_file)
    path_file.write_text("P,Qx\n100,0\n")
    with pytest.raises(InputError, match="must have a header with columns P and Q"):
        LoadPath.from_csv(path_file)


def test_the_cycle_as_a_two_point_path_gives_the_same_solution():
    as_cycle = solve(HERTZ, CYCLE, 0.1, elements=400, steps=5)
    as_path = solve(HERTZ, LoadPath([[100.0, 0.0], [105.0, 1.0]]), 0.1, elements=400, steps=5)
    assert as_path.right.b == as_cycle.right.b
    assert np.array_equal(as_path.states[1].shear, as_cycle.states[1].shear)


@pytest.mark.parametrize("Q0, sigma0", [(20.0, 0.0), (20.0, 1.0), (10.0, -0.8), (29.9, 0.0)])
def test_constant_load_fretting_cycle_has_the_classical_eccentric_stick_zone(Q0, sigma0):
    P, mu = 100.0, 0.3
    a = float(HERTZ.half_width(P))
    p0 = 2 * P / (np.pi * a)
    c = a * np.sqrt(1 - Q0 / (mu * P))
    e = -sigma0 * a / (4 * mu * p0)
    assert abs(e) + c < a  # the stick zone lies inside the contact: both edges slip
    path = LoadPath([[P, Q0, sigma0], [P, -Q0, -sigma0]])
    result = solve(HERTZ, path, mu, elements=1000, steps=6)
    assert result.steady
    assert abs(result.right.b - (e + c)) <= result.element_size
    assert abs(result.left.b - (c - e)) <= result.element_size


def test_general_path_with_tension_and_moment_reaches_a_steady_state():
    law = PowerLaw(A=0.05, n=3.0, E_star=1.0)
    P = float(law.load(2.0))
    points = [
        [P, 0.0, 0.0, 0.0],
        [1.08 * P, 0.05 * P, 0.02, 0.05 * P],
        [1.04 * P, -0.03 * P, 0.05, -0.02 * P],
    ]
    result = solve(law, LoadPath(points), 0.3, elements=600, steps=6)
    assert result.steady
    assert [s.label for s in result.states] == ["1", "2", "3"]
    for state, (P_k, _, _, M_k) in zip(result.states, points, strict=True):
        assert np.sum(state.pressure) * result.element_size == pytest.approx(P_k, rel=1e-12)
        assert np.sum(result.x * state.pressure) * result.element_size == pytest.approx(
            M_k, abs=1e-9 * P_k
        )
        assert np.sum(state.shear) * result.element_size == pytest.approx(
            points[int(state.label) - 1][1], abs=1e-10 * P_k
        )
    assert np.all(result.energy >= 0) and result.energy.max() > 0
    assert np.all(result.slip_range[result.permanent_stick] == 0)
    # every point of the permanent stick zone sticks at every state
    for state in result.states:
        assert np.all(state.slip_sign[result.permanent_stick] == 0)
