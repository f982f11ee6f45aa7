"""Invalid input fails loudly: an InputError naming the parameter and the rule, never a NaN."""

from __future__ import annotations

import math

import numpy as np
import pytest

from asymslip import HertzLaw, InputError, LoadCycle, slip_zone
from asymslip.laws.base import ContactLaw

LAW = HertzLaw(R=1.0, E_star=1.0)
CYCLE = LoadCycle(P1=100, Q1=0, P2=105, Q2=1)


@pytest.mark.parametrize("mu", [0.0, -0.1])
def test_friction_coefficient_must_be_positive(mu):
    with pytest.raises(InputError, match=r"^mu: must be > 0"):
        slip_zone(LAW, CYCLE, mu)


@pytest.mark.parametrize("field", ["P1", "Q1", "P2", "Q2", "sigma1", "sigma2"])
@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_non_finite_loads_are_refused_by_name(field, bad):
    values = {"P1": 100.0, "Q1": 0.0, "P2": 105.0, "Q2": 1.0, "sigma1": 0.0, "sigma2": 0.0}
    values[field] = bad
    with pytest.raises(InputError, match=rf"^{field}: must be finite"):
        LoadCycle(**values)


def test_non_finite_friction_is_refused():
    with pytest.raises(InputError, match=r"^mu: must be finite"):
        slip_zone(LAW, CYCLE, np.nan)


@pytest.mark.parametrize("P2", [100.0, 99.0])
def test_state_two_must_carry_the_larger_normal_load(P2):
    with pytest.raises(InputError, match=r"^P2: must exceed P1.*swap the two states"):
        LoadCycle(P1=100, Q1=0, P2=P2, Q2=1)


@pytest.mark.parametrize("field", ["P1", "P2"])
def test_normal_loads_must_be_positive(field):
    values = {"P1": 100.0, "Q1": 0.0, "P2": 105.0, "Q2": 1.0}
    values[field] = -5.0
    with pytest.raises(InputError, match=rf"^{field}: must be > 0"):
        LoadCycle(**values)


@pytest.mark.parametrize("field, value", [("R", 0.0), ("E_star", -1.0), ("R", np.nan)])
def test_hertz_parameters_must_be_positive_and_finite(field, value):
    values = {"R": 1.0, "E_star": 1.0}
    values[field] = value
    with pytest.raises(InputError, match=rf"^{field}: must be"):
        HertzLaw(**values)


def test_a_number_given_as_text_is_refused():
    with pytest.raises(InputError, match=r"^Q1: must be a real number"):
        LoadCycle(P1=100, Q1="abc", P2=105, Q2=1)


class _SofteningLaw(ContactLaw):
    """P(a) = a (3 - a): increasing only for a < 1.5."""

    name = "softening"

    def load(self, a):
        return a * (3 - a)

    def load_slope(self, a):
        return 3 - 2 * np.asarray(a)

    def half_width_where_possible(self, P):
        a = (3 + np.sqrt(9 - 4 * np.asarray(P))) / 2  # the decreasing branch
        return a, np.isfinite(a)

    def half_width_growth(self, P1, dP):
        return self.half_width(np.asarray(P1) + dP) - self.half_width(P1)


def test_a_decreasing_contact_law_is_refused():
    cycle = LoadCycle(P1=1.0, Q1=0.0, P2=1.1, Q2=0.05)
    with pytest.raises(InputError, match=r"^law: the softening contact law must be increasing"):
        slip_zone(_SofteningLaw(), cycle, 0.1)


def test_a_zero_denominator_in_eq17_is_refused():
    # The denominator of (22), mu (L_I1 + L_I2) + L_II1 - L_II2 with L_II = (lam + pi eta a/4)
    # L_I (21), vanishes for eta = (mu (L_I1 + L_I2) + lam (L_I1 - L_I2)) / (pi/4 (a2 L_I2 -
    # a1 L_I1)).  Without tension that needs |lam| beyond gross sliding; bulk tension reaches
    # it with Q unchanged.  For Hertz, a^2 = 4P/pi and L_I = (2P/pi) sqrt(2/a^3) (R = E* = 1).
    P1, P2, mu = 100.0, 105.0, 0.1
    a1, a2 = (np.sqrt(4 * P / np.pi) for P in (P1, P2))
    L_I1, L_I2 = (2 * P / np.pi * np.sqrt(2 / a**3) for P, a in ((P1, a1), (P2, a2)))
    eta = mu * (L_I1 + L_I2) / (np.pi / 4 * (a2 * L_I2 - a1 * L_I1))
    cycle = LoadCycle(P1=P1, Q1=0.0, P2=P2, Q2=0.0, sigma1=0.0, sigma2=eta * (P2 - P1))
    with pytest.raises(
        InputError, match=r"^sigma2: the bulk-tension change .* denominator of \(17\)"
    ):
        slip_zone(LAW, cycle, mu)


def test_an_unknown_edge_is_refused():
    with pytest.raises(InputError, match=r"^edge: must be"):
        slip_zone(LAW, CYCLE, 0.1, edge="top")


# --- messages that name the right cause (issue 17) ---------------------------------------------
def test_a_subnormal_P1_without_shear_is_not_gross_sliding():
    """mu P1 = 0.1 x 5e-324 rounds to 0, and |Q1| = 0 < 0 is false: the cycle was refused as
    gross sliding.  A contact with no shear force never slides as a whole."""
    result = slip_zone(LAW, LoadCycle(5e-324, 0.0, 1e-323, 0.0), 0.1)
    assert result.slip_direction == 0 and result.b == result.a1 > 0


def test_gross_sliding_is_decided_exactly_where_mu_P_is_subnormal():
    """P1 = 2^-1060, mu = 0.3: mu P1 = 4915.2 x 2^-1074 rounds to 4915 x 2^-1074.  |Q1| of
    4915 units of 2^-1074 lies below the true mu P1 (no gross sliding: the rounded product
    said otherwise); 4916 units lie above it (gross sliding)."""
    P1, mu = math.ldexp(1.0, -1060), 0.3
    unit = math.ldexp(1.0, -1074)
    assert mu * P1 == 4915 * unit  # the rounding the check must see through
    result = slip_zone(LAW, LoadCycle(P1, 4915 * unit, 2 * P1, 0.0), mu)
    assert result.b > 0
    with pytest.raises(InputError, match=r"^Q1: .*gross sliding"):
        slip_zone(LAW, LoadCycle(P1, 4916 * unit, 2 * P1, 0.0), mu)


def test_a_huge_tension_change_is_named_not_mu():
    """--sigma2 1e300 blamed --mu: the denominator of (17) is not positive because of the
    tension change; the same cycle without it has a partial-slip state."""
    with pytest.raises(InputError, match=r"^sigma2: the bulk-tension change") as raised:
        slip_zone(LAW, LoadCycle(100.0, 0.0, 105.0, 1.0, 0.0, 1e300), 0.1)
    assert raised.value.parameter == "sigma2"
    assert slip_zone(LAW, LoadCycle(100.0, 0.0, 105.0, 1.0), 0.1).b > 0


@pytest.mark.parametrize(
    "lam, eta, parameter",
    [
        (50.0, 0.0, "Q2"),  # no tension: the shear change alone
        (50.0, 1.0, "Q2"),  # the shear change alone already leaves no state
        (0.0, 1.0, "sigma2"),  # the tension change alone
        (0.1, 1.0, "sigma2"),  # without the tension change there would be a state
    ],
)
def test_a_non_positive_denominator_names_the_load_change_to_blame(lam, eta, parameter):
    """The rules themselves, on one edge: mu (L_I1 + L_I2) = 0.21 against lambda |L_I2 - L_I1|."""
    from asymslip.rules import Verdict, denominator_checks

    verdict = Verdict(())
    for key, ok in denominator_checks(False, 0.1, lam, eta, 1.0, 1.1):
        verdict.require(key, ok, None, side="right", denominator=-1.0, mu=0.1, note="")
    error = verdict.first_error()
    assert error is not None and error.parameter == parameter
    assert "too large for mu = 0.1" in str(error)
