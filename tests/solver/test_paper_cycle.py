"""The paper's cycle solved numerically: what the exact solutions of Section 3 say must happen.

References, all independent of the solver:
* a(P_K), P_K = (P1 + P2)/2 - |Q2 - Q1|/(2 mu) (33), from each law's own ``half_width`` (the
  permanent stick zone of any symmetric law without tension, Jaeger-Ciavarella; for
  |lambda| < mu it is a1, the errata's correction of (33));
* the exact q_diff of (47) with the Hertz pressure (48), transcribed here;
* K_II of (38) under full stick, transcribed here;
* the slip range of the Hertz cycle, 2 mu g(x; P_K), with g the gap outside a Hertz contact,
  g(x) = (x sqrt(x^2 - a^2) - a^2 arccosh(x/a))/(2R) (its slope sqrt(x^2 - a^2)/R is h'(x)
  minus the gap closure of (48)): by superposition q_diff = mu (p1 + p2 - 2 p_K) moves the
  slip zone by 2 mu g_K relative to the stick zone.
"""

from __future__ import annotations

import numpy as np
import pytest

from asymslip import FlatRoundedLaw, HertzLaw, LoadCycle, PowerLaw
from asymslip.solver import LoadPath, solve

LAWS = {
    "hertz": HertzLaw(R=1.0, E_star=1.0),
    "flat-rounded": FlatRoundedLaw(c=1.0, R=10.0, E_star=1.0),
    "power n=1.5": PowerLaw(A=0.3, n=1.5, E_star=1.0),
    "power n=3": PowerLaw(A=0.05, n=3.0, E_star=1.0),
}
MU = 0.2


def cycle_for(law, lam: float, growth: float = 1.05) -> LoadCycle:
    P1 = float(law.load(2.0))
    P2 = float(law.load(2.0 * growth))
    return LoadCycle(P1, 0.3 * MU * P1, P2, 0.3 * MU * P1 + lam * (P2 - P1))


def permanent_stick_load(cycle: LoadCycle, mu: float) -> float:
    """(33) for either slip direction, P1 when |lambda| < mu."""
    if abs(cycle.lam) < mu:
        return float(cycle.P1)
    return float((cycle.P1 + cycle.P2) / 2 - abs(cycle.Q2 - cycle.Q1) / (2 * mu))


@pytest.mark.parametrize("name", LAWS)
@pytest.mark.parametrize("lam", [0.5, -0.5], ids=["forward", "backward"])
def test_stick_boundary_is_within_one_element_of_a_of_PK(name, lam):
    law = LAWS[name]
    cycle = cycle_for(law, lam)
    result = solve(law, cycle, MU, elements=600, steps=8)
    exact = float(law.half_width(permanent_stick_load(cycle, MU)))
    assert result.steady
    for side in ("right", "left"):
        edge = result.edge(side)
        assert abs(edge.b - exact) <= result.element_size
        assert abs(edge.b - exact) <= edge.b_error
    # Seen from each edge the slip is forward (+1) for lam > mu at the right edge, and the left
    # edge, whose lambda is -lam, slips the other way: as slip-zone reports them.
    direction = 1 if lam > 0 else -1
    assert (result.right.slip_direction, result.left.slip_direction) == (direction, -direction)


def test_no_slip_cycle_sticks_everywhere_inside_a1():
    law = LAWS["hertz"]
    cycle = cycle_for(law, 0.1)  # |lambda| < mu
    result = solve(law, cycle, MU, elements=600, steps=8)
    a1 = float(law.half_width(cycle.P1))
    inside = np.abs(result.x) < a1 - result.element_size
    assert np.all(result.permanent_stick[inside])
    assert result.right.slip_direction == result.left.slip_direction == 0
    assert abs(result.right.b - a1) <= result.element_size


def hertz_pressure(x: np.ndarray, P: float, R: float = 1.0, E_star: float = 1.0) -> np.ndarray:
    """(48) with (29): p = (2P/(pi a^2)) sqrt(a^2 - x^2)."""
    a = np.sqrt(4 * P * R / (np.pi * E_star))
    return 2 * P / (np.pi * a**2) * np.sqrt(np.maximum(a**2 - x**2, 0.0))


def test_hertz_q_diff_matches_the_exact_solution_47():
    law = LAWS["hertz"]
    cycle = LoadCycle(100.0, 0.0, 105.0, 1.0)  # Fig. 5 with mu = 0.1
    mu = 0.1
    result = solve(law, cycle, mu, elements=1000, steps=10)
    x = result.x
    P_K = (100.0 + 105.0) / 2 - 1.0 / (2 * mu)
    a = {P: np.sqrt(4 * P / np.pi) for P in (100.0, 105.0, P_K)}
    b = a[P_K]
    p1, p2, pK = (hertz_pressure(x, P) for P in (100.0, 105.0, P_K))
    # (47), extended by symmetry to x < 0
    exact = np.where(np.abs(x) < b, mu * (p2 + p1 - 2 * pK), mu * (p2 + p1))
    exact = np.where(np.abs(x) < a[100.0], exact, mu * p2)
    h = result.element_size
    away = np.all([np.abs(np.abs(x) - edge) > 3 * h for edge in (b, a[100.0], a[105.0])], axis=0)
    scale = mu * p2.max()
    assert np.max(np.abs(result.q_diff - exact)[away]) <= 1e-3 * scale
    assert np.max(np.abs(result.q_diff - exact)[away & (np.abs(x) < 0.9 * b)]) <= 1e-4 * scale


def test_full_stick_with_tension_gives_K_II_of_38():
    law = LAWS["hertz"]
    P, Q, sigma = 100.0, 3.0, 0.4
    # Friction high enough that nothing slips; P fixed, so the stick state is elastic.
    result = solve(law, LoadPath([[P, Q, sigma], [P, 0.0, 0.0]]), 50.0, elements=2000, steps=2)
    state = result.states[0]
    assert not np.any(state.slip_sign)
    x, a = result.x, float(law.half_width(P))
    # Under stick q sqrt(a^2 - x^2) is linear in x; fitted in the interior, its value at the
    # right edge over sqrt(2a) is K_II = lim q sqrt(a - x).
    inner = np.abs(x) < 0.8 * a
    slope, intercept = np.polyfit(x[inner], state.shear[inner] * np.sqrt(a**2 - x[inner] ** 2), 1)
    K_II = (intercept + slope * a) / np.sqrt(2 * a)
    K_II_38 = Q / (np.pi * np.sqrt(2 * a)) + sigma / 4 * np.sqrt(a / 2)
    # Measured 4e-4 relative at N = 2000 (the edge singularities on piecewise-constant elements).
    assert K_II == pytest.approx(K_II_38, rel=1e-3)
    # The tension part alone: sign and size (sigma/4) sqrt(a/2) at the right edge.
    assert slope * a / np.sqrt(2 * a) == pytest.approx(sigma / 4 * np.sqrt(a / 2), rel=1e-3)


def hertz_gap(x: np.ndarray, a: float, R: float = 1.0) -> np.ndarray:
    """Separation outside a Hertz contact of half-width a, zero inside."""
    X = np.maximum(np.abs(x), a)
    return (X * np.sqrt(X**2 - a**2) - a**2 * np.arccosh(X / a)) / (2 * R)


def test_hertz_slip_range_is_twice_mu_times_the_gap_of_PK():
    law = LAWS["hertz"]
    mu = 0.1
    cycle = LoadCycle(100.0, 0.0, 105.0, 1.0)
    result = solve(law, cycle, mu, elements=1000, steps=10)
    x, h = result.x, result.element_size
    b, a1 = np.sqrt(4 * 97.5 / np.pi), np.sqrt(4 * 100 / np.pi)
    zone = (np.abs(x) > b + 2 * h) & (np.abs(x) < a1 - 2 * h)
    expected = 2 * mu * hertz_gap(x, b)
    assert np.allclose(result.slip_range[zone], expected[zone], rtol=0.02)
    assert np.all(result.slip_range[np.abs(x) < b - h] == 0)
    # Energy: each point slips through twice its range per period, under mu p1 <= |q| <= mu p2.
    p1, p2 = hertz_pressure(x, 100.0), hertz_pressure(x, 105.0)
    work = 2 * result.slip_range
    assert np.all(result.energy[zone] >= 0.99 * mu * p1[zone] * work[zone])
    assert np.all(result.energy[zone] <= 1.01 * mu * p2[zone] * work[zone])
    assert np.all(result.energy >= 0)
    assert np.all(result.energy[np.abs(x) < b - h] == 0)


def test_stick_boundary_does_not_depend_on_the_number_of_steps():
    # Within a monotone half-cycle the slip zone only grows, and every element of the final
    # stick zone is in contact throughout: the steady boundary needs no load steps to resolve.
    law = LAWS["hertz"]
    cycle = cycle_for(law, 0.5)
    coarse = solve(law, cycle, MU, elements=600, steps=1)
    fine = solve(law, cycle, MU, elements=600, steps=16)
    assert abs(coarse.right.b - fine.right.b) <= 0.05 * fine.element_size


def test_slip_range_and_energy_converge_with_the_number_of_steps():
    # Only the slip history of elements coming into or leaving the contact depends on the
    # steps (each counts the fraction of its entry step spent in contact).
    law = LAWS["hertz"]
    cycle = LoadCycle(100.0, 0.0, 105.0, 1.0)
    coarse = solve(law, cycle, 0.1, elements=600, steps=10)
    fine = solve(law, cycle, 0.1, elements=600, steps=40)
    assert coarse.slip_range.max() == pytest.approx(fine.slip_range.max(), rel=0.03)
    assert np.max(np.abs(coarse.energy - fine.energy)) <= 0.02 * fine.energy.max()
    assert coarse.energy.sum() == pytest.approx(fine.energy.sum(), rel=0.02)  # measured 1.1 %
