"""Both edges: the left edge is the paper's problem with the shear force reversed."""

from __future__ import annotations

import numpy as np
import pytest

from asymslip import HertzLaw, LoadCycle, slip_zone

LAW = HertzLaw(R=1.0, E_star=1.0)
MU = 0.3


def _hertz_half_width(P: float) -> float:
    return np.sqrt(4 * P / np.pi)  # (29) with R = E* = 1, typed from the paper


def test_left_edge_slips_when_the_shear_force_falls_faster_than_friction_allows():
    # lam = -0.5 < -mu: by Jaeger-Ciavarella the left edge's permanent stick zone is a(P_K')
    # with P_K' = (P1 + P2)/2 + (Q2 - Q1)/(2 mu), the mirror image of (33).
    P1, dP, lam = 100.0, 0.5, -0.5
    cycle = LoadCycle(P1, 0.0, P1 + dP, lam * dP)
    result = slip_zone(LAW, cycle, MU, edge="both")
    P_K_left = (2 * P1 + dP) / 2 + lam * dP / (2 * MU)
    assert result.left.b_exact == pytest.approx(_hertz_half_width(P_K_left), rel=1e-14)
    assert result.left.slip_zone_width > 0
    # (22) agrees with the exact stick boundary through second order in dP/P1 for Hertz:
    # the difference is O((dP/P1)^3) of a1, here (5e-3)^3 ~ 1e-7.
    assert abs(result.left.b - result.left.b_exact) / result.left.a1 < 1e-6


def test_right_edge_of_the_same_cycle_sticks():
    cycle = LoadCycle(100.0, 0.0, 100.5, -0.25)
    result = slip_zone(LAW, cycle, MU)
    assert result.b >= result.a2
    assert any("no slip" in warning for warning in result.warnings)


def test_bulk_tension_keeps_its_sign_at_the_left_edge():
    cycle = LoadCycle(100.0, 0.0, 101.0, 0.5, sigma1=0.0, sigma2=0.02)
    right = slip_zone(LAW, cycle, MU)
    left = slip_zone(LAW, cycle, MU, edge="left")
    assert (left.lam, left.eta) == (-right.lam, right.eta)
    # L_II = (lam + pi eta a/4) L_I (21): the tension term enters both edges alike.
    tension_term = np.pi * right.eta * right.a1 / 4 * right.L_I1
    assert left.L_II1 + right.L_II1 == pytest.approx(2 * tension_term, rel=1e-12)
