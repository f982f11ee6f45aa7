"""The match is a leading-order statement: the headline widths differ at second order, within
the match's stated accuracy; a rounded-flat rig at the prototype's own half-widths removes the
second-order difference (issue 19)."""

from __future__ import annotations

import pytest

from asymslip.match import Rig, match
from tests.match.cases import MU, POWER, POWER_CYCLE, rounded_flat_at


def _headline_difference(result) -> float:
    widths = result.matched["slip_zone_width"]
    return (widths.rig - widths.prototype) / widths.prototype


def test_a_hertz_pad_on_a_rounded_flat_at_1015_differs_by_about_1_5_percent_of_the_width():
    """c/a1 = 0.7, a2/a1 = 1.015, lambda = 2 mu: the pad's contact is smaller (a1 about 0.3 of
    the flat's) and its edge advances further relative to it, so its width is larger."""
    law, cycle = rounded_flat_at(0.7, 0.015, 2.0)
    result = match(law, cycle, MU, Rig("hertz", 1.0))
    assert result.exact and result.order == "leading"
    difference = _headline_difference(result)
    assert 0.010 < difference < 0.020  # measured +0.0140
    assert float(result.rig_result.a1) < 0.35 * float(result.prototype.a1)
    growth_rig = float(result.rig_result.a2) / float(result.rig_result.a1) - 1
    assert growth_rig > 3 * 0.015
    widths = result.matched["slip_zone_width"]
    assert abs(widths.rig - widths.prototype) <= result.accuracy


def test_the_headline_difference_is_second_order_it_halves_with_the_edge_advance():
    law, cycle = rounded_flat_at(0.7, 0.015, 2.0)
    half_law, half_cycle = rounded_flat_at(0.7, 0.0075, 2.0)
    full = _headline_difference(match(law, cycle, MU, Rig("hertz", 1.0)))
    half = _headline_difference(match(half_law, half_cycle, MU, Rig("hertz", 1.0)))
    # relative difference ~ C (da/a1): a second-order absolute difference of the widths.
    assert half / full == pytest.approx(0.5, abs=0.05)


def test_the_stated_accuracy_is_the_sum_of_the_first_order_accuracies():
    law, cycle = rounded_flat_at(0.7, 0.015, 2.0)
    result = match(law, cycle, MU, Rig("hertz", 1.0))
    expected = 0.0
    for edge in (result.prototype, result.rig_result):
        a1, a2, width = float(edge.a1), float(edge.a2), float(edge.slip_zone_width)
        expected += 2 * (a2 - a1) / a1 * abs(width)
    assert result.accuracy == pytest.approx(expected, rel=1e-12)


def test_a_rounded_flat_rig_cuts_the_headline_difference_by_more_than_ten():
    hertz = match(POWER, POWER_CYCLE, MU, Rig("hertz", 1.0))
    flat = match(POWER, POWER_CYCLE, MU, Rig("flat-rounded", 1.0))
    assert flat.order == "second"
    assert abs(_headline_difference(flat)) * 10 < abs(_headline_difference(hertz))
    widths = flat.matched["slip_zone_width"]
    # Second order: the stated accuracy is the two headline (second-order) accuracies.
    assert flat.accuracy == pytest.approx(
        float(flat.prototype.b_accuracy) + float(flat.rig_result.b_accuracy), rel=1e-12
    )
    assert abs(widths.rig - widths.prototype) <= flat.accuracy


def test_a_rounded_flat_rig_whose_flat_is_fixed_matches_to_leading_order():
    from asymslip.match import Available

    rig = Rig("flat-rounded", 1.0, flat_half_width=Available.listed("rig_c", [5.0]))
    result = match(POWER, POWER_CYCLE, MU, rig)
    assert result.exact and result.order == "leading" and result.geometry.c == 5.0
