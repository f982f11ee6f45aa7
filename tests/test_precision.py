"""Small quantities keep full relative precision: no difference of nearly equal numbers."""

from __future__ import annotations

import mpmath
import pytest

import asymslip_gen as gen
from asymslip import HertzLaw, LoadCycle, slip_zone

DIGITS = 50


@pytest.fixture(autouse=True)
def _digits():
    """50-digit references for this module's tests only (a module-level ``mp.dps = ...``
    would set the precision of every test collected after it)."""
    with mpmath.workdps(DIGITS):
        yield


def _width_by_mpmath(mu, lam, eta, a1, da, L_I1, L_I2):
    """a1 - b from (22), in 50-digit arithmetic on the exact values of the doubles."""
    mu, lam, eta, a1, da, L_I1, L_I2 = map(mpmath.mpf, (mu, lam, eta, a1, da, L_I1, L_I2))
    a2 = a1 + da
    bracket2 = 1 - lam / mu - mpmath.pi * a2 / 4 * eta / mu
    bracket1 = 1 + lam / mu + mpmath.pi * a1 / 4 * eta / mu
    b = (bracket2 * L_I2 * a2 + bracket1 * L_I1 * a1) / (bracket2 * L_I2 + bracket1 * L_I1)
    return a1 - b


def test_slip_zone_width_keeps_1e_12_relative_accuracy_at_da_over_a1_of_1e_10():
    # Exactly representable inputs: dyadic fractions and da = 2^-33 ~ 1.16e-10 * a1.
    args = (0.125, 0.25, 0.0078125, 1.0, 2.0**-33, 1.5, 1.5 + 2.0**-35)
    computed = gen.slip_zone_width(*args)
    reference = _width_by_mpmath(*args)
    assert abs(computed - reference) / abs(reference) < 1e-12


def test_hertz_growth_keeps_1e_12_relative_accuracy_at_dP_over_P1_of_1e_10():
    P1, dP, R, E_star = 100.0, 100.0 * 2.0**-33, 1.0, 1.0
    computed = gen.hertz_half_width_growth(P1, dP, R, E_star)
    a = [
        mpmath.sqrt(4 * mpmath.mpf(P) * R / (mpmath.pi * E_star)) for P in (P1, mpmath.mpf(P1) + dP)
    ]
    reference = a[1] - a[0]
    assert abs(computed - reference) / reference < 1e-12


def test_api_slip_zone_width_at_dP_over_P1_of_1e_10_matches_mpmath_to_1e_12():
    P1, dP = 100.0, 100.0 * 2.0**-33
    result = slip_zone(HertzLaw(R=1.0, E_star=1.0), LoadCycle(P1, 0.0, P1 + dP, 0.2 * dP), mu=0.1)
    P2 = mpmath.mpf(P1 + dP)  # exactly representable, as is dP
    a1, a2 = (mpmath.sqrt(4 * P / mpmath.pi) for P in (mpmath.mpf(P1), P2))
    L_I1, L_I2 = (mpmath.sqrt(a / 2) for a in (a1, a2))
    lam = mpmath.mpf(0.2 * dP) / (P2 - P1)
    bracket2, bracket1 = 1 - lam / mpmath.mpf(0.1), 1 + lam / mpmath.mpf(0.1)
    b = (bracket2 * L_I2 * a2 + bracket1 * L_I1 * a1) / (bracket2 * L_I2 + bracket1 * L_I1)
    reference = a1 - b
    assert abs(result.slip_zone_width - reference) / reference < 1e-12
