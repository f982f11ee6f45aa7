"""The Python API refuses what is no input with a documented error naming the parameter
(issue 17): never a bare TypeError or OverflowError from NumPy, None as missing."""

from __future__ import annotations

import numpy as np
import pytest

from asymslip import HertzLaw, InputError, LoadCycle, slip_zone

LAW = HertzLaw(1.0, 1.0)
CYCLE = LoadCycle(100, 0, 105, 1)


def test_an_integer_beyond_double_precision_is_named():
    with pytest.raises(InputError, match=r"^P1: must be finite: it is beyond double precision"):
        LoadCycle(10**400, 0, 10**401, 1)


def test_none_is_missing_not_infinite():
    with pytest.raises(InputError, match=r"^P1: is missing \(None\)"):
        LoadCycle(None, 0, 105, 1)
    with pytest.raises(InputError, match=r"^mu: is missing \(None\)"):
        slip_zone(LAW, CYCLE, None)


def test_a_law_that_is_no_law_is_named():
    with pytest.raises(InputError, match=r"^law: must be a contact law"):
        slip_zone(None, CYCLE, 0.1)


def test_a_tuple_for_the_cycle_is_named():
    with pytest.raises(InputError, match=r"^cycle: must be a LoadCycle"):
        slip_zone(LAW, (100, 0, 105, 1), 0.1)


def test_shapes_that_do_not_broadcast_name_both_parameters():
    with pytest.raises(InputError, match=r"^P2: has shape \(3,\), .* with P1's shape \(2,\)"):
        LoadCycle([100, 101], 0, [105, 106, 107], 1)
    with pytest.raises(InputError, match=r"^mu: has shape \(3,\), .*cycle's shape \(2,\)"):
        slip_zone(LAW, LoadCycle([100, 101], 0, 105, 1), [0.1, 0.2, 0.3])


def test_masked_elements_are_refused_not_ignored():
    masked = np.ma.masked_array([100.0, 101.0], mask=[False, True])
    with pytest.raises(InputError, match=r"^P1: has masked elements.*at element 1"):
        LoadCycle(masked, 0, 105, 1)
    # without a masked element the array's data is taken
    unmasked = np.ma.masked_array([100.0, 101.0], mask=[False, False])
    a1 = slip_zone(LAW, LoadCycle(unmasked, 0, 105, 1), 0.1).a1
    assert np.array_equal(a1, LAW.half_width(np.array([100.0, 101.0])))


def test_invalid_mark_marks_what_the_cycle_itself_refuses_through_an_unchecked_cycle():
    # NaN and P2 <= P1 break the cycle's own rules: LoadCycle refuses them, so marking them
    # per element takes LoadCycle.unchecked (slip_zone's documented way).
    cycle = LoadCycle.unchecked([100, np.nan, 100], 0, [105, 105, 90], 1)
    result = slip_zone(LAW, cycle, 0.1, invalid="mark")
    assert result.errors[0] is None and np.isfinite(result.b[0])
    assert result.errors[1].startswith("P1: must be finite") and np.isnan(result.b[1])
    assert result.errors[2].startswith("P2: must exceed P1") and np.isnan(result.b[2])
