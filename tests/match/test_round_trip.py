"""Where the match is exact, the rig cycle fed back through slip-zone reproduces the prototype's
edge: L_I1, L_I2, L_II1, L_II2 and a2 - a1 to 1e-9 relative (issue 19)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from asymslip import HertzLaw, LoadCycle, slip_zone
from asymslip.match import QUANTITIES, Rig, match
from tests.match.cases import BLADE, BLADE_CYCLE, MU, POWER, POWER_CYCLE, relative, width_17

MULTIPLIERS = ("L_I1", "L_I2", "L_II1", "L_II2")


def _edge_numbers(law, cycle: LoadCycle, mu: float, edge: str) -> dict[str, float]:
    """What slip-zone reports for the edge, and a2 - a1 from the law's own growth."""
    result = slip_zone(law, cycle, mu, edge=edge)
    numbers = {key: float(getattr(result, key)) for key in MULTIPLIERS}
    P1 = float(cycle.P1)
    numbers["a2_minus_a1"] = float(law.for_edge(edge).cycle_state(P1, float(cycle.P2) - P1).da)
    return numbers


def _assert_round_trip(law, cycle, mu, rig, edge="right", tolerance=1e-9):
    result = match(law, cycle, mu, rig, edge=edge)
    prototype = _edge_numbers(law, cycle, mu, edge)
    rig_edge = _edge_numbers(result.law, result.cycle, result.mu, edge)
    for quantity in QUANTITIES:
        assert relative(rig_edge[quantity], prototype[quantity]) < tolerance, quantity
    assert result.exact
    return result


@pytest.mark.parametrize("edge", ["right", "left"])
def test_a_hertz_pad_with_tension_reproduces_a_rounded_flat_edge_to_1e_9(edge):
    result = _assert_round_trip(BLADE, BLADE_CYCLE, MU, Rig("hertz", 1.0), edge)
    assert result.order == "leading"
    assert result.cycle.sigma2 != result.cycle.sigma1  # tension is needed: L_II/L_I changes


def test_a_hertz_pad_reproduces_a_power_law_edge_to_1e_9():
    _assert_round_trip(POWER, POWER_CYCLE, MU, Rig("hertz", 1.0))


def test_the_hertz_pad_is_the_one_of_LT3_transcribed_by_hand():
    """(31): L_I = (E*/R) sqrt(a/2) at a1 and a1 + da gives a1 = da L1^2/(L2^2 - L1^2)."""
    result = match(BLADE, BLADE_CYCLE, MU, Rig("hertz", 2.5))
    state = result.prototype_state
    a1 = state.da * state.L_I1**2 / (state.L_I2**2 - state.L_I1**2)
    R = 2.5 * math.sqrt(a1 / 2) / state.L_I1
    assert relative(result.geometry.R, R) < 1e-12
    P1 = math.pi * 2.5 * a1**2 / (4 * R)  # (29)
    assert relative(float(result.cycle.P1), P1) < 1e-12


def test_a_hertz_prototype_is_reproduced_by_itself():
    law = HertzLaw(R=3.0, E_star=2.0)
    cycle = LoadCycle(100.0, -3.0, 105.0, 3.0, 0.0, 0.4)
    result = _assert_round_trip(law, cycle, MU, Rig("hertz", 2.0))
    assert relative(result.geometry.R, 3.0) < 1e-9
    assert relative(float(result.cycle.P1), 100.0) < 1e-9
    assert relative(float(result.cycle.P2), 105.0) < 1e-9


def test_without_tension_in_the_prototype_the_rig_needs_none():
    law = HertzLaw(R=3.0, E_star=2.0)
    result = match(law, LoadCycle(100.0, 0.0, 105.0, 4.0), MU, Rig("hertz", 2.0, tension=False))
    assert result.exact and result.cycle.sigma1 == result.cycle.sigma2 == 0.0


def test_a_rounded_flat_rig_matches_a_power_law_to_second_order():
    result = _assert_round_trip(POWER, POWER_CYCLE, MU, Rig("flat-rounded", 1.0))
    assert result.order == "second"
    prototype = slip_zone(POWER, POWER_CYCLE, MU)
    assert relative(float(result.rig_result.a1), float(prototype.a1)) < 1e-9
    assert relative(float(result.rig_result.a2), float(prototype.a2)) < 1e-9


def test_a_rounded_flat_rig_finds_the_rounded_flat_prototype_itself():
    result = _assert_round_trip(BLADE, BLADE_CYCLE, MU, Rig("flat-rounded", 1.0))
    assert relative(result.geometry.c, 1.0) < 1e-9 and relative(result.geometry.R, 10.0) < 1e-9
    widths = result.matched["slip_zone_width"]
    assert relative(widths.rig, widths.prototype) < 1e-9


def test_a_different_rig_friction_matches_mu_L_I_and_the_shear_not_the_pressure():
    result = match(BLADE, BLADE_CYCLE, MU, Rig("hertz", 1.0, mu=0.6))
    rig_edge = _edge_numbers(result.law, result.cycle, 0.6, "right")
    prototype = _edge_numbers(BLADE, BLADE_CYCLE, MU, "right")
    for k in ("1", "2"):
        assert relative(0.6 * rig_edge[f"L_I{k}"], MU * prototype[f"L_I{k}"]) < 1e-9
        assert relative(rig_edge[f"L_II{k}"], prototype[f"L_II{k}"]) < 1e-9
    assert not result.exact and any("mu" in text for text in result.unmatched)
    assert relative(result.rig_state.width, result.prototype_state.width) < 1e-9


def test_the_consistent_width_and_peak_shear_change_agree_where_the_match_is_exact():
    result = match(BLADE, BLADE_CYCLE, MU, Rig("hertz", 1.0))
    p = result.prototype_state
    hand = width_17(p.mu, p.L_I1, p.L_I2, p.L_II1, p.L_II2, p.da)
    assert relative(result.prototype_state.width, hand) < 1e-12
    assert relative(result.rig_state.width, hand) < 1e-9
    # LT2 by hand: mu (L_I1 sqrt(w) + L_I2 sqrt(w + da)).
    peak = MU * (p.L_I1 * math.sqrt(hand) + p.L_I2 * math.sqrt(hand + p.da))
    assert relative(result.peak_shear_change.prototype, peak) < 1e-12
    assert relative(result.peak_shear_change.rig, peak) < 1e-9


def test_the_rig_cycle_is_as_far_from_gross_sliding_at_both_states():
    result = match(BLADE, BLADE_CYCLE, MU, Rig("hertz", 1.0))
    c = result.cycle
    margins = [1 - abs(float(Q)) / (MU * float(P)) for P, Q in ((c.P1, c.Q1), (c.P2, c.Q2))]
    assert margins[0] == pytest.approx(margins[1], rel=1e-12)
    assert result.margin == pytest.approx(min(margins), rel=1e-12)
    # Any other mean shear force leaves less margin at one of the states.
    for shift in np.linspace(-0.01, 0.01, 9):
        if shift == 0:
            continue
        other = min(
            1 - abs(float(Q) + shift) / (MU * float(P)) for P, Q in ((c.P1, c.Q1), (c.P2, c.Q2))
        )
        assert other < result.margin
