"""Where the rig cannot reach the prototype, the closest rig cycle by the stated edge-state
mismatch, naming what could not be matched and what it does (issue 19); infeasible requests
refused with the reason."""

from __future__ import annotations

import math

import numpy as np
import pytest

from asymslip import FlatRoundedLaw, LoadCycle, PowerLaw, slip_zone
from asymslip.errors import InputError
from asymslip.match import Available, EdgeSignature, Rig, match
from asymslip.match.solutions import best_slopes, edge_signature, law_point
from tests.match.cases import BLADE, BLADE_CYCLE, MU, width_17


def _measure_by_hand(rig_state: EdgeSignature, target: EdgeSignature) -> float:
    """The measure of asymslip.match.signature, transcribed: five relative mismatches."""
    parts = [
        math.log(rig_state.L_I1 / target.L_I1),
        math.log(rig_state.L_I2 / target.L_I2),
        (rig_state.L_II1 - target.L_II1) / (target.mu * target.L_I1),
        (rig_state.L_II2 - target.L_II2) / (target.mu * target.L_I2),
        math.log(rig_state.da / target.da),
    ]
    return math.sqrt(sum(part * part for part in parts))


def _measure_of(rig: Rig, result, P1: float, P2: float) -> float:
    """The mismatch of the rig's pad at other loads, with the best slopes there."""
    point = law_point(result.law, P1, P2 - P1)
    lam, eta = best_slopes(point, result.prototype_state, rig)
    return edge_signature(point, MU, lam, eta).distance(result.prototype_state)


def test_without_tension_the_closest_cycle_says_tension_could_not_be_applied():
    rig = Rig("hertz", 1.0, tension=False)
    result = match(BLADE, BLADE_CYCLE, MU, rig)
    assert not result.exact and result.order == "approximate"
    assert result.cycle.sigma1 == result.cycle.sigma2 == 0.0
    assert any("bulk tension" in text for text in result.unmatched)
    assert 0 < result.measure < 0.01
    assert result.measure == pytest.approx(
        _measure_by_hand(result.rig_state, result.prototype_state), rel=1e-12
    )


def test_the_closest_cycle_is_a_minimum_of_the_measure():
    rig = Rig("hertz", 1.0, tension=False)
    result = match(BLADE, BLADE_CYCLE, MU, rig)
    P1, P2 = float(result.cycle.P1), float(result.cycle.P2)
    for factor1, factor2 in ((1.001, 1.001), (0.999, 0.999), (1.0, 1.002), (1.0, 0.998)):
        assert _measure_of(rig, result, P1 * factor1, P2 * factor2) > result.measure


def test_each_mismatch_s_effect_is_the_width_with_that_quantity_alone_changed():
    result = match(BLADE, BLADE_CYCLE, MU, Rig("hertz", 1.0, tension=False))
    p, r = result.prototype_state, result.rig_state
    base = width_17(p.mu, p.L_I1, p.L_I2, p.L_II1, p.L_II2, p.da)
    values = {"L_I1": p.L_I1, "L_I2": p.L_I2, "L_II1": p.L_II1, "L_II2": p.L_II2, "da": p.da}
    for item in result.mismatches:
        key = "da" if item.quantity == "a2_minus_a1" else item.quantity
        changed = dict(values, **{key: getattr(r, key)})
        alone = width_17(p.mu, *(changed[k] for k in ("L_I1", "L_I2", "L_II1", "L_II2", "da")))
        assert item.width_change == pytest.approx(alone / base - 1, rel=1e-9, abs=1e-15)


def test_a_radius_from_a_list_is_one_of_the_list():
    rig = Rig("hertz", 1.0, radius=Available.listed("rig_R", [5.0, 20.0]))
    result = match(BLADE, BLADE_CYCLE, MU, rig)
    assert result.geometry.R in (5.0, 20.0) and result.order == "approximate"
    assert any("not available" in text for text in result.unmatched)
    others = match(
        BLADE, BLADE_CYCLE, MU, Rig("hertz", 1.0, radius=Available.listed("rig_R", [5.0]))
    )
    assert result.measure <= others.measure


def test_a_load_limit_is_kept():
    rig = Rig("hertz", 1.0, max_P=0.3)
    result = match(BLADE, BLADE_CYCLE, MU, rig)
    assert float(result.cycle.P2) <= 0.3 * (1 + 1e-12)
    assert any("exceeds the rig's largest" in text for text in result.unmatched)


def test_a_shear_force_limit_is_kept():
    exact = match(BLADE, BLADE_CYCLE, MU, Rig("hertz", 1.0))
    limit = 0.5 * max(abs(float(exact.cycle.Q1)), abs(float(exact.cycle.Q2)))
    result = match(BLADE, BLADE_CYCLE, MU, Rig("hertz", 1.0, max_Q=limit))
    assert max(abs(float(result.cycle.Q1)), abs(float(result.cycle.Q2))) <= limit * (1 + 1e-12)


def test_a_falling_L_I_is_refused_for_an_unbounded_rig():
    wedge_like = PowerLaw(A=0.05, n=1.2, E_star=1.0)  # L_I ~ a^(n - 3/2) falls with the load
    with pytest.raises(InputError, match="L_I does not rise"):
        match(wedge_like, LoadCycle(1.0, 0.0, 1.05, 0.02), MU, Rig("hertz", 1.0))


def test_a_falling_L_I_gives_the_closest_within_a_bounded_rig():
    wedge_like = PowerLaw(A=0.05, n=1.2, E_star=1.0)
    rig = Rig("hertz", 1.0, radius=Available.between("rig_R", 0.1, 100.0))
    result = match(wedge_like, LoadCycle(1.0, 0.0, 1.05, 0.02), MU, rig)
    assert result.order == "approximate" and result.geometry.R <= 100.0 * (1 + 1e-12)
    assert any("does not rise" in text for text in result.unmatched)


def test_an_edge_that_does_not_slip_is_refused():
    cycle = LoadCycle(0.5, 0.0, 0.52, 0.001)  # |lambda| < mu, no tension: no slip inside a1
    with pytest.raises(InputError, match="does not slip"):
        match(BLADE, cycle, MU, Rig("hertz", 1.0))


def test_a_rig_that_comes_nowhere_near_is_refused():
    rig = Rig("hertz", 1.0, radius=Available.listed("rig_R", [1000.0]), max_P=1e-3)
    with pytest.raises(InputError, match="no rig within its limits"):
        match(BLADE, BLADE_CYCLE, MU, rig)


def test_gross_sliding_in_every_rig_cycle_is_refused():
    """A nearly flat punch (c/a1 = 0.99): the matching pad's load changes by 1.4 times as much
    relative to its load, so the shear change that the prototype bears slides the pad."""
    law = FlatRoundedLaw(c=10.0, R=1.0, E_star=1.0)
    a1 = 10.0 / 0.99
    P1, P2 = float(law.load(a1)), float(law.load(a1 * 1.003))
    dQ = 4.5 * MU * (P2 - P1)
    Q1 = -dQ * P1 / (P1 + P2)
    cycle = LoadCycle(P1, Q1, P2, Q1 + dQ)
    assert slip_zone(law, cycle, MU).slip_zone_width > 0  # the prototype itself is valid
    with pytest.raises(InputError, match="slides grossly"):
        match(law, cycle, MU, Rig("hertz", 1.0))


@pytest.mark.parametrize(
    ("make", "parameter"),
    [
        (lambda: Rig("cylinder", 1.0), "rig"),
        (lambda: Rig("hertz", -1.0), "rig_E_star"),
        (lambda: Rig("hertz", 1.0, mu=0.0), "rig_mu"),
        (lambda: Rig("hertz", 1.0, max_P=-2.0), "rig_max_P"),
        (lambda: Rig("hertz", 1.0, radius=Available.listed("rig_R", [])), "rig_R"),
        (lambda: Rig("hertz", 1.0, radius=Available.between("rig_R", 2.0, 1.0)), "rig_R"),
        (lambda: Rig("hertz", 1.0, flat_half_width=Available.listed("rig_c", [1.0])), "rig_c"),
    ],
)
def test_bad_rigs_are_refused_naming_the_parameter(make, parameter):
    with pytest.raises(InputError) as error:
        make()
    assert error.value.parameter == parameter


def test_arrays_of_cycles_are_refused():
    cycle = LoadCycle(np.array([0.5, 0.5]), 0.0, np.array([0.52, 0.53]), 0.04)
    with pytest.raises(InputError):
        match(BLADE, cycle, MU, Rig("hertz", 1.0))


def test_a_rounded_flat_rig_without_tension_gives_the_closest_rounded_flat():
    from tests.match.cases import POWER, POWER_CYCLE

    result = match(POWER, POWER_CYCLE, MU, Rig("flat-rounded", 1.0, tension=False))
    assert result.order == "approximate" and result.cycle.sigma1 == result.cycle.sigma2 == 0.0
    assert result.geometry.c > 0 and 0 < result.measure < 0.01
    assert any("bulk tension" in text for text in result.unmatched)
    assert result.measure == pytest.approx(
        _measure_by_hand(result.rig_state, result.prototype_state), rel=1e-12
    )
