"""Invalid input fails loudly: an InputError naming the parameter and the rule, never a NaN."""

from __future__ import annotations

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
    with pytest.raises(InputError, match=r"^sigma2: at the right edge the denominator of \(17\)"):
        slip_zone(LAW, cycle, mu)


def test_an_unknown_edge_is_refused():
    with pytest.raises(InputError, match=r"^edge: must be"):
        slip_zone(LAW, CYCLE, 0.1, edge="top")
