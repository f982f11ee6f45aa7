"""What the slip zone says in words where a number alone would mislead (issue 17).

Each claim with the cycle that showed it; the class checks run every estimate at both edges of
random cycles, with and without bulk tension.
"""

from __future__ import annotations

import numpy as np
import pytest

from asymslip import HertzLaw, LoadCycle, PowerLaw, slip_zone
from asymslip.calibration import calibrate
from asymslip.core.flags import BEYOND_A1, DISAGREE_PAPER, OWN_MULTIPLIERS_TENSION
from asymslip.laws.calibrated import CalibratedLaw
from tests.calibration.helpers import mesh, sampled_traces

HERTZ = HertzLaw(1.0, 1.0)
POWER = PowerLaw(0.1, 3.0, 1.0)


def _random_cycles(seed: int, count: int) -> tuple[LoadCycle, np.ndarray, np.ndarray]:
    """Load steps up to half of P1, shear slopes of either sign up to 1.6 mu, half with tension."""
    rng = np.random.default_rng(seed)
    P1 = rng.uniform(5, 150, count)
    P2 = P1 * (1 + 10 ** rng.uniform(-4, np.log10(0.5), count))
    mu = rng.uniform(0.05, 0.8, count)
    lam = rng.uniform(-1.6, 1.6, count) * mu
    Q1 = rng.uniform(-0.9, 0.9, count) * mu * P1
    eta = np.where(rng.random(count) < 0.5, 0.0, rng.uniform(-0.3, 0.3, count))
    cycle = LoadCycle(P1, Q1, P2, Q1 + lam * (P2 - P1), 0.0, eta * (P2 - P1))
    return cycle, mu, eta


@pytest.mark.parametrize("law", [HERTZ, POWER], ids=["hertz", "power n=3"])
def test_every_estimate_beyond_a1_at_a_slipping_edge_is_said_in_words(law):
    cycle, mu, _ = _random_cycles(seed=1, count=10_000)
    result = slip_zone(law, cycle, mu, edge="both", invalid="mark")
    found = 0
    for edge in (result, result.left):
        slips = edge.slip_direction != 0
        for key in BEYOND_A1:
            beyond = slips & (getattr(edge, key) > edge.a1)
            flagged = (edge.warning_flags & BEYOND_A1[key]) != 0
            assert np.array_equal(beyond, flagged), key
            found += int(beyond.sum())
    assert found > 10  # the class is there to be checked (b and (28), (40) with tension)


def test_a_negative_slip_zone_width_says_that_no_slip_zone_lies_inside_a1():
    # Hertz, right edge, with tension: b2 lies 0.0074 beyond a1 = 12.969.
    cycle = LoadCycle(
        132.09787898040418,
        20.515359841986204,
        142.04768808649453,
        8.370880934197451,
        0.0,
        1.9398783153743648,
    )
    result = slip_zone(HERTZ, cycle, 0.7788558012255118)
    assert result.slip_direction != 0 and result.slip_zone_width < 0
    assert any(text.startswith("b lies beyond a1") for text in result.warnings)
    assert any("no slip zone inside a1" in text for text in result.warnings)


def test_the_22_disagreement_names_tension_only_where_there_is_tension():
    # Power law n = 3 without tension: (22) is off by (1 - lam^2/mu^2)(a'' + a'^2/a) dP^2/8.
    cycle = LoadCycle(25.903143844346893, -4.563902514291677, 25.91053531210546, -4.558700392976079)
    without = slip_zone(POWER, cycle, 0.6943217462300602, edge="both")
    flags = [without.warning_flags, without.left.warning_flags]
    assert any(flag & DISAGREE_PAPER for flag in flags)
    texts = [*without.warnings, *without.left.warnings]
    assert not any("22-T" in text or "with bulk tension" in text for text in texts)
    assert any("affine in P" in text for text in texts)
    # With tension (the Fig. 5 loads, sigma 0 -> 0.5) the erratum is named.
    tension = slip_zone(HERTZ, LoadCycle(100, 0, 105, 1, 0, 0.5), 0.1)
    assert tension.warning_flags & DISAGREE_PAPER
    assert any("erratum 22-T" in text for text in tension.warnings)


def _calibrated_hertz() -> CalibratedLaw:
    rng = np.random.default_rng(4)
    loads = (70.0, 85.0, 100.0, 115.0, 130.0, 150.0)
    x = mesh("graded", float(HERTZ.half_width(100.0)), 200, rng)
    return CalibratedLaw(calibrate(sampled_traces(HERTZ.pressure, loads, x, 0.0, rng), origin=0.0))


def test_a_calibrated_law_with_bulk_tension_states_the_accuracy_of_its_b():
    law = _calibrated_hertz()
    with_tension = slip_zone(law, LoadCycle(100, 0, 105, 1, 0, 0.05), 0.1, edge="both")
    for edge in (with_tension, with_tension.left):
        assert edge.warning_flags & OWN_MULTIPLIERS_TENSION
        text = next(text for text in edge.warnings if text.startswith("bulk tension at an edge"))
        assert "10 % of the slip-zone width" in text and "2 (da/a1) |a1 - b|" in text
        # the accuracy it states is the first-order one, 2 (da/a1) |a1 - b|
        da = edge.a2 - edge.a1
        assert edge.b_accuracy == pytest.approx(2 * da / edge.a1 * abs(edge.slip_zone_width))
    without = slip_zone(law, LoadCycle(100, 0, 105, 1), 0.1)
    assert not without.warning_flags & OWN_MULTIPLIERS_TENSION
