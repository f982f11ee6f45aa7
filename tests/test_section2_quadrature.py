"""Section 2 against independent mpmath quadrature: (14), (16), and (15) solving (12)."""

from __future__ import annotations

import mpmath
import numpy as np
import pytest

import asymslip_gen as gen
from tests.transcription import section2 as paper

DIGITS = 30


@pytest.fixture(autouse=True)
def _digits():
    """30-digit quadratures for this module's tests only (a module-level ``mp.dps = ...``
    would set the precision of every test collected after it)."""
    with mpmath.workdps(DIGITS):
        yield


def principal_value(f, lower, upper, pole):
    """PV int_lower^upper f(t)/(t - pole) dt: subtract f(pole), add its exact PV back."""
    # Twice the digits: tanh-sinh nodes crowd the pole, where f(t) - f(pole) cancels.
    with mpmath.workdps(2 * mpmath.mp.dps):
        f_pole = f(pole)
        regular = mpmath.quad(lambda t: (f(t) - f_pole) / (t - pole), [lower, pole, upper])
        return regular + f_pole * mpmath.log((upper - pole) / (pole - lower))


@pytest.mark.parametrize("beta, x", [(-0.5, 0.2), (0.3, 0.95), (0.9, 0.91), (-3.0, -2.5)])
def test_eq14_inside_is_minus_pi(beta, x):
    def weight(t):
        return mpmath.sqrt((1 - t) / (t - beta))

    value = principal_value(weight, mpmath.mpf(beta), 1, mpmath.mpf(x))
    assert abs(value + mpmath.pi) < 1e-25  # the quadrature itself, at 30 digits
    assert abs(value - paper.eq14(beta, x)) < 4e-16 * mpmath.pi  # the transcription, in doubles


@pytest.mark.parametrize("beta, x", [(-0.5, 1.2), (0.3, 1.0001), (0.9, 40.0), (-3.0, 2.5)])
def test_eq14_outside_is_the_printed_closed_form(beta, x):
    value = mpmath.quad(lambda t: mpmath.sqrt((1 - t) / (t - beta)) / (t - x), [beta, 1])
    # 1 - sqrt(...) in the double-precision transcription loses up to ~2 digits at large x.
    assert abs(value - paper.eq14(beta, x)) < 1e-13 * abs(value)


@pytest.mark.parametrize("lower, top", [(0.0, 1.0), (9.7, 10.0), (-2.0, 3.5)])
def test_eq16_weight_integral_is_pi_times_half_the_interval(lower, top):
    value = mpmath.quad(lambda t: mpmath.sqrt((top - t) / (t - lower)), [lower, top])
    assert abs(value - paper.eq16_integral(lower, top)) < 1e-15 * value


# A Fig. 5-like cycle with b from (17), so that (15) solves (12).
CASE = {
    "mu": 0.3,
    "E_star": 2.0,
    "a1": 1.0,
    "a2": 1.05,
    "L_I1": 1.0,
    "L_I2": 1.1,
    "L_II1": 0.5,
    "L_II2": 0.55,
}


def _rhs_of_eq12(x: float, b: float) -> mpmath.mpf:
    """E*/(2 pi sqrt(a2 - x)) int_{a2}^{b} sqrt(a2 - t) B(a2 - t) dt/(t - x) by quadrature."""
    c = CASE

    def weighted(t):
        density = float(
            gen.dislocation_density(
                float(t),
                b,
                c["a1"],
                c["mu"],
                c["L_I1"],
                c["L_I2"],
                c["L_II1"],
                c["L_II2"],
                c["E_star"],
            )
        )
        return mpmath.sqrt(c["a2"] - t) * density

    pole = mpmath.mpf(x)
    f_pole = weighted(pole)
    regular = mpmath.quad(
        lambda t: (weighted(t) - f_pole) / (t - pole), sorted({b, c["a1"], x, c["a2"]})
    )
    integral = regular + f_pole * mpmath.log((c["a2"] - pole) / (pole - b))
    return -c["E_star"] / (2 * mpmath.pi * mpmath.sqrt(c["a2"] - pole)) * integral


@pytest.mark.parametrize("fraction", [0.05, 0.3, 0.62, 0.97])
def test_generated_eq15_solves_the_integral_equation_eq12(fraction):
    c = CASE
    b = float(
        gen.stick_boundary(c["mu"], c["a1"], c["a2"], c["L_I1"], c["L_I2"], c["L_II1"], c["L_II2"])
    )
    assert b < c["a1"]
    x = b + fraction * (c["a2"] - b)
    left = (c["mu"] * c["L_I1"] + c["L_II1"]) * np.sqrt(max(c["a1"] - x, 0.0)) + (
        c["mu"] * c["L_I2"] - c["L_II2"]
    ) * np.sqrt(c["a2"] - x)
    # The density is evaluated in double precision, so agreement is to ~1e-12 of the scale.
    assert abs(float(_rhs_of_eq12(x, b)) - left) < 1e-11 * (c["mu"] * c["L_I2"] + c["L_II2"])
