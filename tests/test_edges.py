"""Both edges and both slip directions (derivations/edge_symmetry.py), against Jaeger-Ciavarella.

With no bulk tension a Hertzian contact is symmetric, so both edges must give the same slip
zone; the exact stick zone is a(P_K) with P_K from the wedge of slopes -+mu enclosing the path:
(33) for lam >= mu, its mirror image for lam <= -mu, and P1 itself for |lam| < mu.
"""

from __future__ import annotations

import numpy as np
import pytest

from asymslip import HertzLaw, LoadCycle, slip_zone
from asymslip.tractions import traction_difference

LAW = HertzLaw(R=1.0, E_star=1.0)
MU = 0.3
P1, DP = 100.0, 0.5


def _hertz_half_width(P: float) -> float:
    return np.sqrt(4 * P / np.pi)  # (29) with R = E* = 1, typed from the paper


def _hertz_pressure(x, P):
    a = _hertz_half_width(P)
    return 2 * P / (np.pi * a**2) * np.sqrt(np.maximum(a**2 - np.asarray(x) ** 2, 0))  # (48)


@pytest.mark.parametrize("lam", [0.5, -0.5, 1.2, -1.2])
def test_without_bulk_tension_both_edges_of_a_hertz_contact_slip_alike(lam):
    result = slip_zone(LAW, LoadCycle(P1, 0.0, P1 + DP, lam * DP), MU, edge="both")
    for key in ("b", "slip_zone_width", "b_first_order", "b_exact", "b_corrective_stick"):
        assert getattr(result.left, key) == pytest.approx(getattr(result, key), rel=1e-14), key
    assert result.left.lam == -result.lam


@pytest.mark.parametrize("lam", [0.5, -0.5])
def test_the_exact_stick_zone_is_a_of_P_K_from_the_enclosing_wedge(lam):
    result = slip_zone(LAW, LoadCycle(P1, 0.0, P1 + DP, lam * DP), MU)
    P_K = P1 + DP * (MU - abs(lam)) / (2 * MU)  # (33) and its mirror image
    assert result.b_exact == pytest.approx(_hertz_half_width(P_K), rel=1e-14)
    # (22) agrees with the exact result through second order in dP/P1 for Hertz: they differ
    # by r (r - 1)(r + 1) eps^3 / 256 (r = |lam|/mu, eps = dP/P1; README, method_agreement),
    # here 1.4e-9 a1, up to O(eps^4).  Each edge slips its own way: r is the same for both.
    r, eps = abs(lam) / MU, DP / P1
    third_order = r * (r - 1) * (r + 1) / 256 * eps**3
    assert (result.b_paper - result.b_exact) / result.a1 == pytest.approx(third_order, rel=0.02)


@pytest.mark.parametrize("lam", [0.0, 0.29, -0.29])
def test_no_slip_when_the_shear_change_stays_within_friction(lam):
    result = slip_zone(LAW, LoadCycle(P1, 0.0, P1 + DP, lam * DP), MU)
    assert result.slip_zone_width == 0.0
    assert result.b == result.a1 == result.b_exact
    assert any(warning.startswith("no slip at this edge") for warning in result.warnings)


def test_backward_slip_reverses_the_traction_difference():
    cycle = LoadCycle(P1, 0.0, P1 + DP, -0.5 * DP)
    x = np.array([0.0, 0.5 * _hertz_half_width(P1), 0.9 * _hertz_half_width(P1 + DP)])
    result = traction_difference(LAW, cycle, MU, x, stick_boundary="exact")
    P_K = P1 + DP * (MU - 0.5) / (2 * MU)
    exact = -MU * (
        _hertz_pressure(x, P1 + DP) + _hertz_pressure(x, P1) - 2 * _hertz_pressure(x, P_K)
    )  # (47), negated for backward slip
    np.testing.assert_allclose(result.q_diff_exact, exact, rtol=1e-12)
    forward = traction_difference(
        LAW, LoadCycle(P1, 0.0, P1 + DP, 0.5 * DP), MU, x, stick_boundary="exact"
    )
    np.testing.assert_allclose(result.q_diff, -np.array(forward.q_diff), rtol=1e-14)


def test_bulk_tension_keeps_its_sign_at_the_left_edge_and_breaks_the_symmetry():
    cycle = LoadCycle(P1, 0.0, P1 + 1.0, 0.5, sigma1=0.0, sigma2=0.02)
    right = slip_zone(LAW, cycle, MU)
    left = slip_zone(LAW, cycle, MU, edge="left")
    assert (left.lam, left.eta) == (-right.lam, right.eta)
    # L_II = (lam + pi eta a/4) L_I (21): the tension term enters both edges alike.
    tension_term = np.pi * right.eta * right.a1 / 4 * right.L_I1
    assert left.L_II1 + right.L_II1 == pytest.approx(2 * tension_term, rel=1e-12)
    assert left.b != pytest.approx(right.b, rel=1e-6)


# --- the validity measures mean what their labels say, at both edges ---------------------------
@pytest.mark.parametrize("lam", [0.0, 0.2, -0.25])
def test_a_symmetric_cycle_without_slip_has_the_same_measures_at_both_edges(lam):
    result = slip_zone(LAW, LoadCycle(P1, 0.0, P1 + DP, lam * DP), MU, edge="both")
    assert result.slip_direction == result.left.slip_direction == 0
    assert result.validity == result.left.validity
    # No slip zone: |b - a1|/a1 = 0, and the necessary condition (27) on its size holds.
    assert result.validity["eq25"] == 0.0 and result.validity["eq27"] == 0.0


@pytest.mark.parametrize("lam", [0.5, -0.5, 1.2])
def test_eq25_is_the_reported_slip_zone_size_at_each_edge(lam):
    result = slip_zone(LAW, LoadCycle(P1, 0.0, P1 + DP, lam * DP), MU, edge="both")
    for edge in (result, result.left):
        # The measure uses the cancellation-free width; b - a1 from b itself loses digits.
        assert edge.validity["eq25"] == pytest.approx(abs(edge.b - edge.a1) / edge.a1, rel=1e-9)
        assert edge.validity["eq25"] > 0


def test_the_contact_growth_measures_are_the_same_at_both_edges_of_a_symmetric_law():
    result = slip_zone(LAW, LoadCycle(P1, 0.0, P1 + DP, 0.5 * DP, 0.0, 2e-3), MU, edge="both")
    for key in ("eq24", "eq26"):  # (24), (26): the law's growth, the same at both edges
        assert result.validity[key] == result.left.validity[key]
    # dP a'(P)/a1 with a'(P) = a/(2P) for Hertz, the larger at P1: dP/(2 P1).
    assert result.validity["eq24"] == pytest.approx(DP / (2 * P1), rel=1e-14)
