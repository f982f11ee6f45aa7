"""Rounded flat and power-law punches, and the root finder, against independent mpmath references.

References are computed here without SymPy: the plane-contact relation
    P(a) = (E*/2) int_{-a}^{a} x h'(x) / sqrt(a^2 - x^2) dx
by quadrature, (19) transcribed by hand, the pressure by a principal-value inversion of the
profile, and the published rounded-flat law E* a^2 (pi - 2 phi0 - sin 2 phi0)/(4R) typed by hand.
"""

from __future__ import annotations

import sys
import warnings

import mpmath
import numpy as np
import pytest
from hypothesis import given, settings

from asymslip.errors import InputError
from asymslip.laws.flat_rounded import FlatRoundedLaw
from asymslip.laws.hertz import HertzLaw
from asymslip.laws.power import PowerLaw, shape_factor
from asymslip.laws.roots import growth_from, invert_increasing, load_difference
from asymslip.laws.table import TableLaw
from tests.accuracy.references import (
    flat_half_width_mp,
    flat_slope,
    load_by_quadrature,
    load_slope_by_quadrature,
    power_slope,
    pressure_by_inversion,
)
from tests.accuracy.references import normal_multiplier_19 as eq19
from tests.strategies import real

EPS = np.finfo(float).eps


# --- hand transcriptions and quadratures (mpmath) ---------------------------------------------
# Shared with the accuracy harness (tests/accuracy/references.py): flat_slope, power_slope,
# load_by_quadrature, load_slope_by_quadrature, (19) as eq19, pressure_by_inversion,
# published_flat_load and flat_half_width_mp.


def no_warnings(function, *args):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return function(*args)


# --- the rounded flat ----------------------------------------------------------------------------

FLAT = FlatRoundedLaw(c=1.0, R=5.0, E_star=2.0)
FLAT_CASES = [(1.3, 1.0), (2.0, 1.0), (1.02, 1.0), (6.0, 0.5), (2.5, 0.0)]  # (a, c)


@pytest.mark.parametrize("a, c", FLAT_CASES)
def test_flat_load_matches_quadrature_of_the_plane_contact_relation(a, c):
    law = FlatRoundedLaw(c=c, R=5.0, E_star=2.0)
    with mpmath.workdps(30):
        reference = load_by_quadrature(lambda t: flat_slope(t, c, 5), a, 2, breaks=(c,))
    # P(a) near a = c is a difference of nearly equal terms: relative error ~ eps c/(a - c).
    assert abs(law.load(a) - reference) <= 4 * EPS * (1 + c / (a - c)) * reference


@pytest.mark.parametrize("a, c", FLAT_CASES)
def test_flat_multiplier_matches_eq19_with_quadrature_slope(a, c):
    law = FlatRoundedLaw(c=c, R=5.0, E_star=2.0)
    with mpmath.workdps(30):
        slope = load_slope_by_quadrature(
            lambda t: flat_slope(t, c, 5), lambda t: 0.2 if abs(t) > c else 0, a, 2, breaks=(c,)
        )
        reference = eq19(a, slope)
    P = law.load(a)
    assert abs(law.normal_multiplier(P) - reference) < 1e-13 * reference
    assert abs(law.load_slope(a) - slope) < 1e-14 * slope


def test_flat_multiplier_slope_matches_central_difference_of_eq19():
    law, P = FLAT, 0.8
    with mpmath.workdps(40):

        def multiplier(load):
            a = flat_half_width_mp(load, 1, 5, 2)
            dP_da = 2 * a * mpmath.acos(1 / a) / 5  # d/da of the published law, by hand
            return eq19(a, dP_da)

        reference = mpmath.diff(multiplier, P)
    assert abs(law.normal_multiplier_slope(P) - reference) < 1e-12 * abs(reference)


def test_flat_law_reduces_to_hertz_eq29_for_c_zero():
    law = FlatRoundedLaw(c=0.0, R=2.0, E_star=3.0)
    P = np.array([1e-3, 1.0, 1e4])
    np.testing.assert_allclose(law.half_width(P) ** 2, 4 * P * 2.0 / (np.pi * 3.0), rtol=4e-16)


PRESSURE_POINTS = [
    (2.0, 1.0, 0.0),
    (2.0, 1.0, 0.6),
    (2.0, 1.0, -1.4),
    (2.0, 1.0, 1.97),
    (1.1, 1.0, 0.5),
    (3.0, 0.5, 2.0),
]  # (a, c, x)


@pytest.mark.parametrize("a, c, x", PRESSURE_POINTS)
def test_flat_pressure_matches_principal_value_inversion_of_the_profile(a, c, x):
    law = FlatRoundedLaw(c=c, R=5.0, E_star=2.0)
    with mpmath.workdps(30):
        reference = pressure_by_inversion(lambda t: flat_slope(t, c, 5), a, x, 2, (-c, c))
    computed = law.pressure(x, law.load(a))
    # Near a -> c and near the edges the closed form's terms exceed p (see its docstring).
    assert abs(computed - reference) < 2e-13 * reference


@pytest.mark.parametrize("a, c", [(2.0, 1.0), (1.2, 1.0), (4.0, 0.0)])
def test_flat_pressure_integrates_to_the_load(a, c):
    law = FlatRoundedLaw(c=c, R=5.0, E_star=2.0)
    P = law.load(a)
    with mpmath.workdps(15):
        total = mpmath.quad(lambda t: float(law.pressure(float(t), P)), [-a, -c, 0, c, a])
    assert abs(total - P) < 1e-12 * P


def test_flat_pressure_edge_asymptote_is_eq4_with_eq19():
    a = 2.0
    P = FLAT.load(a)
    gap = 1e-6 * a
    ratio = FLAT.pressure(a - gap, P) / np.sqrt(gap)
    # p = L_I sqrt(a - x) (1 + O((a - x)/a)).
    assert abs(ratio - FLAT.normal_multiplier(P)) < 1e-5 * ratio


@pytest.mark.parametrize("c", [0.0, 0.7, 1.0])
def test_flat_pressure_warns_nowhere_on_the_contact_and_is_zero_outside(c):
    law = FlatRoundedLaw(c=c, R=1.0, E_star=1.0)
    P = 0.3
    a = float(law.half_width(P))
    x = np.array(
        [
            0.0,
            -0.0,
            c,
            -c,
            np.nextafter(c, 0),
            np.nextafter(c, 9),
            a,
            -a,
            np.nextafter(a, 0),
            1.5 * a,
            -1e300,
            1e-300,
        ]
    )
    p = no_warnings(law.pressure, x, P)
    assert np.all(np.isfinite(p)) and np.all(p >= 0)
    assert np.all(p[np.abs(x) >= a] == 0)
    assert np.all(p[np.abs(x) < np.nextafter(a, 0)] > 0)


@pytest.mark.parametrize("exponent", range(-6, 7))
def test_flat_half_width_is_the_mpmath_root_to_1e_14_for_P_from_1e_6_to_1e_6(exponent):
    P = 10.0**exponent
    computed = FLAT.half_width(P)
    with mpmath.workdps(40):
        reference = flat_half_width_mp(P, 1, 5, 2)
    assert abs(computed - reference) < 1e-14 * reference


@settings(max_examples=60, deadline=None)
@given(c=real(0.0, 10.0), R=real(1e-2, 1e2), E_star=real(1e-2, 1e3), log_load=real(-6, 6))
def test_flat_load_of_half_width_returns_the_load_to_rounding(c, R, E_star, log_load):
    law = FlatRoundedLaw(c=c, R=R, E_star=E_star)
    P = 10.0**log_load * E_star * max(c, 1.0) ** 2 / R
    a = law.half_width(P)
    # The root is within ~2 ulp of a; P(a) amplifies that by the condition a P'(a)/P.
    condition = a * law.load_slope(a) / P
    assert abs(law.load(a) - P) <= 8 * EPS * (1 + condition) * P


@settings(max_examples=40, deadline=None)
@given(c=real(0.0, 10.0), ratio=real(1.0 + 1e-9, 1e3))
def test_flat_half_width_of_load_returns_the_half_width_to_1e_14(c, ratio):
    law = FlatRoundedLaw(c=c, R=3.0, E_star=1.0)
    a = max(c, 1e-3) * ratio
    assert abs(law.half_width(law.load(a)) - a) <= 1e-14 * a


@pytest.mark.parametrize("relative_change", [1e-12, 1e-6, 0.1, 1.0, 50.0, 1e4])
def test_flat_growth_keeps_1e_13_relative_accuracy(relative_change):
    P1 = 0.4
    dP = P1 * relative_change
    computed = FLAT.half_width_growth(P1, dP)
    with mpmath.workdps(50):
        P2 = mpmath.mpf(P1) + mpmath.mpf(dP)  # the exact sum of the two doubles
        reference = flat_half_width_mp(P2, 1, 5, 2) - flat_half_width_mp(P1, 1, 5, 2)
    assert abs(computed - reference) < 1e-13 * reference


# --- the power law --------------------------------------------------------------------------------


@pytest.mark.parametrize("n", [1.0, 1.5, 2.0, 2.5, 3.0, 7.0])
def test_power_shape_factor_matches_quadrature(n):
    with mpmath.workdps(30):
        reference = load_by_quadrature(lambda t: power_slope(t, 1, n), 1, 1)
    assert abs(shape_factor(n) - reference) < 4 * EPS * reference


@pytest.mark.parametrize("n", [1.0, 2.5, 3.0])
def test_power_load_matches_quadrature_of_the_plane_contact_relation(n):
    law = PowerLaw(A=0.3, n=n, E_star=2.0)
    with mpmath.workdps(30):
        reference = load_by_quadrature(lambda t: power_slope(t, 0.3, n), 1.7, 2)
    assert abs(law.load(1.7) - reference) < 1e-14 * reference


def test_power_law_n2_reproduces_eq29_and_eq31():
    R, E_star, P = 1.5, 2.0, np.array([1e-4, 3.0, 1e5])
    law = PowerLaw(A=1 / (2 * R), n=2.0, E_star=E_star)
    a = law.half_width(P)
    np.testing.assert_allclose(a**2, 4 * P * R / (np.pi * E_star), rtol=4e-16)  # (29)
    np.testing.assert_allclose(
        law.normal_multiplier(P), E_star / R * np.sqrt(a / 2), rtol=1e-15
    )  # (31)


@pytest.mark.parametrize("n", [1.0, 1.5, 3.0])
def test_power_multiplier_matches_eq19_with_quadrature_slope(n):
    law = PowerLaw(A=0.7, n=n, E_star=1.3)
    a = 1.9
    with mpmath.workdps(30):
        dP_da = load_slope_by_quadrature(
            lambda t: power_slope(t, 0.7, n),
            lambda t: n * (n - 1) * 0.7 * abs(t) ** (n - 2) if n != 1 else 0,
            a,
            1.3,
        )
        reference = eq19(a, dP_da)
    assert abs(law.normal_multiplier(law.load(a)) - reference) < 1e-13 * reference


@pytest.mark.parametrize("n", [1.0, 1.5, 3.0])
def test_power_multiplier_slope_is_the_derivative_of_eq19(n):
    law = PowerLaw(A=0.7, n=n, E_star=1.3)
    P = 2.0
    with mpmath.workdps(30):
        K = shape_factor_mp(n)

        def multiplier(load):  # (19) with P = K E* A a^n differentiated by hand
            a = (load / (K * mpmath.mpf(1.3) * mpmath.mpf(0.7))) ** (1 / mpmath.mpf(n))
            return eq19(a, n * load / a)

        reference, slope = multiplier(mpmath.mpf(P)), mpmath.diff(multiplier, mpmath.mpf(P))
    # On the scale L_I/P of the slope (it vanishes at n = 3/2).
    assert abs(law.normal_multiplier_slope(P) - slope) < 1e-14 * reference / P


def shape_factor_mp(n):
    return (
        mpmath.sqrt(mpmath.pi)
        * mpmath.gamma((mpmath.mpf(n) + 1) / 2)
        / mpmath.gamma(mpmath.mpf(n) / 2)
    )


@settings(max_examples=60, deadline=None)
@given(A=real(1e-3, 1e3), n=real(1.0, 8.0), E_star=real(1e-2, 1e3), log_load=real(-6, 6))
def test_power_half_width_round_trip_to_1e_14(A, n, E_star, log_load):
    law = PowerLaw(A=A, n=n, E_star=E_star)
    P = 10.0**log_load
    a = law.half_width(P)
    assert abs(law.load(a) - P) <= 1e-14 * P * n


@pytest.mark.parametrize("relative_change", [1e-300, 1e-12, 1e-3, 1.0, 1e6])
@pytest.mark.parametrize("n", [1.0, 2.5])
def test_power_growth_keeps_full_relative_precision(relative_change, n):
    law = PowerLaw(A=0.4, n=n, E_star=1.0)
    P1 = 3.0
    dP = P1 * relative_change
    computed = law.half_width_growth(P1, dP)
    with mpmath.workdps(400):
        K = shape_factor_mp(n)
        ratio = mpmath.mpf(dP) / P1
        a1 = (P1 / (K * mpmath.mpf(0.4))) ** (1 / mpmath.mpf(n))
        reference = a1 * mpmath.expm1(mpmath.log1p(ratio) / n)
    assert abs(computed - reference) < 1e-14 * reference


@pytest.mark.parametrize(
    "n, x", [(1.0, 0.3), (1.0, -1.1), (2.0, 0.4), (2.5, 0.0), (2.5, 0.9), (3.0, -0.5), (1.2, 0.05)]
)
def test_power_pressure_matches_principal_value_inversion_of_the_profile(n, x):
    if n not in (1.0, 2.0):
        pytest.importorskip("scipy")
    law = PowerLaw(A=0.8, n=n, E_star=1.5)
    a = 1.25
    P = law.load(a)
    with mpmath.workdps(30):
        reference = pressure_by_inversion(lambda t: power_slope(t, 0.8, n), a, x, 1.5, (0,))
    assert abs(law.pressure(x, P) - reference) < 5e-14 * reference


@pytest.mark.parametrize("n", [1.0, 2.0, 2.5])
def test_power_pressure_integrates_to_the_load(n):
    if n not in (1.0, 2.0):
        pytest.importorskip("scipy")
    law = PowerLaw(A=0.8, n=n, E_star=1.5)
    a = 1.25
    P = law.load(a)
    with mpmath.workdps(15):
        total = mpmath.quad(lambda t: float(law.pressure(float(t), P)), [-a, 0, a])
    assert abs(total - P) < 1e-12 * P


def test_wedge_pressure_is_infinite_at_the_apex_without_a_warning():
    law = PowerLaw(A=0.5, n=1.0, E_star=1.0)
    a = float(law.half_width(1.0))  # P = E* A a for the wedge: a = 2
    p = no_warnings(law.pressure, np.array([0.0, 1e-300, 0.5, a, -a, 3 * a]), 1.0)
    assert p[0] == np.inf
    np.testing.assert_allclose(
        p[1:3], 0.5 / np.pi * np.arccosh(a / np.array([1e-300, 0.5])), rtol=1e-15
    )
    assert np.all(p[3:] == 0.0)


@pytest.mark.parametrize("n", [2.0, 1.5, 4.0])
def test_power_pressure_warns_nowhere_and_is_zero_outside(n):
    if n != 2.0:
        pytest.importorskip("scipy")
    law = PowerLaw(A=1.0, n=n, E_star=1.0)
    a = float(law.half_width(1.0))
    x = np.array([0.0, 0.5 * a, a, -a, np.nextafter(a, 0), 2 * a])
    p = no_warnings(law.pressure, x, 1.0)
    assert np.all(np.isfinite(p)) and np.all(p[:2] > 0) and np.all(p[[2, 3, 5]] == 0)


def test_power_pressure_without_scipy_names_the_special_extra(monkeypatch):
    monkeypatch.setitem(sys.modules, "scipy", None)
    monkeypatch.setitem(sys.modules, "scipy.special", None)
    law = PowerLaw(A=1.0, n=3.0, E_star=1.0)
    with pytest.raises(InputError, match=r"^n: .*asymslip\[special\]"):
        law.pressure(0.1, 1.0)
    # n = 1 and n = 2 need no SciPy.
    assert np.isfinite(PowerLaw(A=1.0, n=2.0, E_star=1.0).pressure(0.1, 1.0))
    assert np.isfinite(PowerLaw(A=1.0, n=1.0, E_star=1.0).pressure(0.1, 1.0))


def test_flat_half_width_refuses_a_load_too_small_to_separate_a_from_c():
    # a - c ~ (P R/(E* c^2))^(2/3) c: at P = 1e-30 it is below the rounding of a = c.
    with pytest.raises(InputError) as error:
        FlatRoundedLaw(c=1.0, R=1.0, E_star=1.0).normal_multiplier_slope(1e-30)
    assert error.value.parameter == "P"


# --- invalid parameters ------------------------------------------------------------------------


@pytest.mark.parametrize(
    "kwargs, parameter",
    [
        ({"c": -0.1, "R": 1.0, "E_star": 1.0}, "c"),
        ({"c": float("nan"), "R": 1.0, "E_star": 1.0}, "c"),
        ({"c": 1.0, "R": 0.0, "E_star": 1.0}, "R"),
        ({"c": 1.0, "R": 1.0, "E_star": -2.0}, "E_star"),
    ],
)
def test_flat_law_refuses_invalid_parameters_naming_them(kwargs, parameter):
    with pytest.raises(InputError) as error:
        FlatRoundedLaw(**kwargs)
    assert error.value.parameter == parameter


@pytest.mark.parametrize(
    "kwargs, parameter",
    [
        ({"A": 0.0, "n": 2.0, "E_star": 1.0}, "A"),
        ({"A": 1.0, "n": 0.99, "E_star": 1.0}, "n"),
        ({"A": 1.0, "n": float("inf"), "E_star": 1.0}, "n"),
        ({"A": 1.0, "n": 2.0, "E_star": 0.0}, "E_star"),
    ],
)
def test_power_law_refuses_invalid_parameters_naming_them(kwargs, parameter):
    with pytest.raises(InputError) as error:
        PowerLaw(**kwargs)
    assert error.value.parameter == parameter
    if kwargs["n"] == 0.99:
        assert "incomplete contact" in str(error.value)


@pytest.mark.parametrize("law", [FLAT, PowerLaw(A=1.0, n=2.0, E_star=1.0)])
@pytest.mark.parametrize(
    "method, args, parameter",
    [
        ("half_width", (0.0,), "P"),
        ("half_width", (-1.0,), "P"),
        ("half_width_growth", (0.0, 1.0), "P1"),
        ("half_width_growth", (1.0, -1.0), "dP"),
        ("pressure", (float("nan"), 1.0), "x"),
        ("normal_multiplier", (np.inf,), "P"),
    ],
)
def test_law_methods_refuse_invalid_loads_naming_the_parameter(law, method, args, parameter):
    with pytest.raises(InputError) as error:
        getattr(law, method)(*args)
    assert error.value.parameter == parameter


# --- the root finder -----------------------------------------------------------------------------


@pytest.mark.parametrize("with_slope", [True, False])
@pytest.mark.parametrize("power, span", [(2.0, 300), (3.0, 300), (0.5, 150)])
def test_inverse_of_a_power_is_within_rounding_over_the_double_range(power, span, with_slope):
    target = np.logspace(-span, span, 301)
    root = invert_increasing(
        lambda a: a**power, target, (lambda a: power * a ** (power - 1)) if with_slope else None
    )
    with mpmath.workdps(30):
        exact = np.array([float(mpmath.mpf(t) ** (1 / mpmath.mpf(power))) for t in target])
    # a**power rounds to within ~1 ulp, i.e. a within ~1/power ulp: allow 1 + 2/power ulp.
    assert np.all(np.abs(root - exact) <= (1 + 2 / power) * np.spacing(exact))


def test_inverse_keeps_the_shape_and_returns_a_float_for_a_scalar():
    root = invert_increasing(np.exp, np.full((2, 3), 5.0), np.exp)
    assert root.shape == (2, 3)
    scalar = invert_increasing(np.exp, 5.0, np.exp)
    assert isinstance(scalar, np.float64) and abs(scalar - np.log(5.0)) <= EPS * np.log(5.0)


def test_inverse_handles_a_flat_stretch_below_the_root():
    # Like the rounded flat: zero for a <= 3, where Newton's step is undefined.
    target = np.array([1e-12, 1.0, 8.0])
    root = invert_increasing(
        lambda a: np.maximum(0.0, a - 3.0) ** 1.5,
        target,
        lambda a: 1.5 * np.sqrt(np.maximum(0.0, a - 3.0)),
    )
    np.testing.assert_allclose(root, 3.0 + target ** (2 / 3), rtol=2 * EPS)


def test_inverse_refuses_a_target_outside_the_range():
    with pytest.raises(ValueError, match="target"):
        invert_increasing(lambda a: a * a, np.array([1.0, -1.0]))
    with pytest.raises(ValueError, match="target"):
        invert_increasing(lambda a: a * a, np.nan)


@settings(max_examples=50, deadline=None)
@given(scale=real(1e-3, 1e3), offset=real(0.0, 10.0), log_target=real(-8, 8))
def test_inverse_of_a_cubic_with_secant_matches_numpy_roots(scale, offset, log_target):
    target = 10.0**log_target
    root = invert_increasing(lambda a: scale * (a**3 + offset * a), target)
    exact = max(np.roots([scale, 0.0, scale * offset, -target]).real)
    assert abs(root - exact) <= 1e-12 * exact


@pytest.mark.parametrize("relative_change", [1e-15, 1e-8, 0.01, 0.5, 1.0, 1e3])
def test_growth_of_a_square_root_law_is_accurate_from_one_newton_correction(relative_change):
    P1 = 2.0
    dP = P1 * relative_change
    load, slope = (lambda a: a * a), (lambda a: 2 * a)  # P = a^2: a = sqrt(P), P' = 2a
    growth, found = growth_from(
        load, slope, lambda a, d: load_difference(slope, load, a, d), np.sqrt(P1), P1 + dP, dP
    )
    with mpmath.workdps(50):
        reference = mpmath.sqrt(mpmath.mpf(P1) + mpmath.mpf(dP)) - mpmath.sqrt(P1)
    assert found
    assert abs(growth - reference) < 4e-15 * reference


# --- a law's parameters: one finite number each (issue 17) -------------------------------------
LAW_BUILDERS = {
    "HertzLaw R": (lambda v: HertzLaw(v, 1.0), "R"),
    "HertzLaw E_star": (lambda v: HertzLaw(1.0, v), "E_star"),
    "FlatRoundedLaw c": (lambda v: FlatRoundedLaw(v, 1.0, 1.0), "c"),
    "FlatRoundedLaw R": (lambda v: FlatRoundedLaw(1.0, v, 1.0), "R"),
    "PowerLaw A": (lambda v: PowerLaw(v, 2.0, 1.0), "A"),
    "PowerLaw n": (lambda v: PowerLaw(1.0, v, 1.0), "n"),
    "PowerLaw E_star": (lambda v: PowerLaw(1.0, 2.0, v), "E_star"),
}
NOT_ONE_NUMBER = {
    "an array": (np.array([1.0, 2.0]), r"must be one number, not an array of 2"),
    "a list of one": ([2.0], r"must be one number, not an array of 1"),
    "None": (None, r"is missing"),
    "text": ("2", r"must be a real number"),
    "a complex number": (2 + 0j, r"must be a real number"),
    "True": (True, r"must be a number, not True or False"),
    "nan": (float("nan"), r"must be finite"),
}


@pytest.mark.parametrize("value", list(NOT_ONE_NUMBER))
@pytest.mark.parametrize("law", list(LAW_BUILDERS))
def test_a_law_parameter_that_is_not_one_finite_number_is_refused_naming_it(law, value):
    """HertzLaw(np.array([1., 2.]), 1) ended in NumPy's "only 0-dimensional arrays can be
    converted"; None was "must be finite".  Each is an InputError naming the parameter."""
    build, name = LAW_BUILDERS[law]
    given_value, rule = NOT_ONE_NUMBER[value]
    with pytest.raises(InputError, match=rf"^{name}: {rule}") as raised:
        build(given_value)
    assert raised.value.parameter == name


def test_a_zero_dimensional_array_or_numpy_scalar_is_one_number():
    law = PowerLaw(np.array(0.5), np.float32(2.0), np.int64(1))
    assert (law.A, law.n, law.E_star) == (0.5, 2.0, 1.0)
    assert all(type(value) is float for value in (law.A, law.n, law.E_star))


@pytest.mark.parametrize(
    "P, a, parameter, rule",
    [
        (None, [1.0, 2.0, 3.0, 4.0], "P", r"is missing"),
        ([1.0, 2.0, 3.0, 4.0], None, "a", r"is missing"),
        ("abcd", [1.0, 2.0, 3.0, 4.0], "P", r"must be a real number"),
    ],
)
def test_a_table_law_without_its_points_is_refused_naming_them(P, a, parameter, rule):
    with pytest.raises(InputError, match=rf"^{parameter}: {rule}"):
        TableLaw(P, a)
