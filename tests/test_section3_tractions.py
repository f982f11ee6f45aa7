"""Section 3.4: the shear-traction difference, exact (47)-(48) and asymptotic (49), and the slip.

The oracles are the paper's equations transcribed by hand below: (47)-(48) piecewise in plain
NumPy, and (49) with the density (15) evaluated by mpmath principal-value quadrature (never the
closed form).  Inputs are drawn as arrays (``tests/sampling.py``: every corner of the input box,
then 50,000 random points) where the reference is NumPy, and by Hypothesis, a few dozen at a
time, where it is an mpmath quadrature; agreement is to 1e-12 of the natural scale of each
quantity (stated per test: the generated forms are sums of terms that partly cancel).
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from asymslip_gen.corrective_slip import stick_boundary
from asymslip_gen.slip_displacement import slip_on_loading
from asymslip_gen.tractions import (
    hertz_pressure,
    hertz_shear_traction_difference,
    shear_traction_difference,
)
from tests.sampling import assert_within, draw, log_uniform, uniform
from tests.strategies import real

DPS = 25  # ample for a 1e-12 comparison; principal values get twice this
EPS = np.finfo(float).eps


# --- the paper, transcribed by hand --------------------------------------------------------------


def eq29_half_width(P, R, E_star):
    """a^2 = 4 P R / (pi E*)."""
    return np.sqrt(4 * P * R / (np.pi * E_star))


def eq33_permanent_stick_load(P1, dP, lam, mu):
    """P_K = (P1 + P2)/2 - (Q2 - Q1)/(2 mu) with P2 = P1 + dP, Q2 - Q1 = lam dP (18)."""
    P2 = P1 + dP
    return (P1 + P2) / 2 - lam * dP / (2 * mu)


def eq48_pressure(x, P, R, E_star):
    """p(x, P) = 2P/(pi a^2) sqrt(a^2 - x^2) inside the contact |x| < a, 0 outside."""
    a = eq29_half_width(P, R, E_star)
    inside = np.abs(x) < a
    return np.where(inside, 2 * P / (np.pi * a**2) * np.sqrt(np.where(inside, a**2 - x**2, 0)), 0)


def edge_allowance(x, P, R, E_star):
    """Rounding allowance of p(x, P): sqrt(a^2 - x^2) with a radicand good to ~8 ulps of a^2.

    The square root has infinite slope at the contact edge, so a few ulps of a^2 in the
    radicand become sqrt(ulps) there; away from the edge this is a few ulps of p.
    """
    radicand, spread = (
        eq29_half_width(P, R, E_star) ** 2 - x**2,
        8 * EPS * (eq29_half_width(P, R, E_star) ** 2 + x**2),
    )
    upper, lower = np.maximum(0.0, radicand + spread), np.maximum(0.0, radicand - spread)
    return E_star / (2 * R) * (np.sqrt(upper) - np.sqrt(lower))


def eq47_traction_difference(x, P1, dP, P_K, mu, R, E_star):
    """The piecewise (47) for 0 <= x < a2, with p from (48)."""
    P2 = P1 + dP
    b = eq29_half_width(P_K, R, E_star)
    a1 = eq29_half_width(P1, R, E_star)

    def p(P):
        return eq48_pressure(x, P, R, E_star)

    return np.select(
        [x < b, x < a1],
        [mu * (p(P2) + p(P1) - 2 * p(P_K)), mu * (p(P2) + p(P1))],
        default=mu * p(P2),
    )


def eq15_density(t, c):
    """B^{1->2}(a2 - t) of (15), in mpmath, for b < t < a2."""
    A1 = c["mu"] * c["L_I1"] + c["L_II1"]
    total = c["mu"] * (c["L_I1"] + c["L_I2"]) + c["L_II1"] - c["L_II2"]
    inner = mpmath.sqrt(t - c["a1"]) if t > c["a1"] else 0
    return -2 * mpmath.sqrt(t - c["b"]) / c["E_star"] * total + 2 * A1 / c["E_star"] * inner


def eq17_stick_boundary(c):
    A1 = c["mu"] * c["L_I1"] + c["L_II1"]
    A2 = c["mu"] * c["L_I2"] - c["L_II2"]
    return (A2 * c["a2"] + A1 * c["a1"]) / (A2 + A1)


def eq49_by_quadrature(x: float, c: dict[str, float]) -> mpmath.mpf:
    """(49) with (15), the integral by mpmath (principal value when b < x < a2), 30 digits."""
    with mpmath.workdps(DPS):
        v = {key: mpmath.mpf(value) for key, value in c.items()}
        xv = mpmath.mpf(x)
        a1, a2, b = v["a1"], v["a2"], v["b"]

        def weighted(t):
            return mpmath.sqrt(a2 - t) * eq15_density(t, v)

        breaks = sorted({b, min(max(a1, b), a2), a2})
        if xv <= b:
            # At x = b a node may round onto t = b, where the integrand ~ 1/sqrt(t - b).
            integral_b_to_a2 = mpmath.quad(
                lambda t: 0 if t == xv else weighted(t) / (t - xv), breaks
            )
        else:
            with mpmath.workdps(2 * DPS):  # f(t) - f(x) cancels near the pole
                at_pole = weighted(xv)

                def regular(t):
                    # Tanh-sinh nodes can round onto the pole itself; the limit there is finite.
                    return 0 if t == xv else (weighted(t) - at_pole) / (t - xv)

                integral_b_to_a2 = mpmath.quad(regular, sorted({*breaks, xv})) + (
                    at_pole * mpmath.log((a2 - xv) / (xv - b))
                )
        inner = mpmath.sqrt(a1 - xv) if xv < a1 else 0
        # int_{a2}^{b} = -int_b^{a2}
        return (
            v["L_II2"] * mpmath.sqrt(a2 - xv)
            - v["L_II1"] * inner
            - v["E_star"] / (2 * mpmath.pi * mpmath.sqrt(a2 - xv)) * integral_b_to_a2
        )


def closed_form(x, c):
    return shear_traction_difference(
        x, c["b"], c["a1"], c["a2"], c["mu"], c["L_I1"], c["L_I2"], c["L_II1"], c["L_II2"]
    )


def term_scale(x, c):
    """Largest size of the terms of the closed form of (49) at x: the scale of its rounding."""
    K = c["mu"] * (c["L_I1"] + c["L_I2"]) + c["L_II1"] - c["L_II2"]
    A1 = c["mu"] * c["L_I1"] + c["L_II1"]
    A2 = c["mu"] * c["L_I2"] - c["L_II2"]
    edge = (abs(A1) * (c["a1"] - c["b"]) + abs(A2) * (c["a2"] - c["b"])) / 2
    return max(
        (abs(c["L_II2"]) + c["mu"] * c["L_I2"]) * math.sqrt(c["a2"] - x),
        (abs(c["L_II1"]) + c["mu"] * c["L_I1"]) * math.sqrt(max(0.0, c["a1"] - x)),
        abs(K) * math.sqrt(max(0.0, c["b"] - x)),
        edge / math.sqrt(c["a2"] - x),
    )


# --- random edge states ------------------------------------------------------------------------


@st.composite
def edge_state(draw: st.DrawFn) -> dict[str, float]:
    """a1 < a2, a stick boundary b <= a1 (not necessarily (17)), any multipliers."""
    a1 = draw(real(0.5, 20.0))
    da = a1 * draw(real(1e-3, 0.1))
    L_I1 = draw(real(0.1, 10.0))
    return {
        "a1": a1,
        "a2": a1 + da,
        "b": a1 - da * draw(real(0.0, 3.0)),
        "mu": draw(real(0.05, 1.0)),
        "L_I1": L_I1,
        "L_I2": L_I1 * draw(real(0.9, 1.1)),
        "L_II1": draw(real(-5.0, 5.0)),
        "L_II2": draw(real(-5.0, 5.0)),
        "E_star": draw(real(0.1, 100.0)),
    }


def position(c: dict[str, float], zone: str, fraction: float) -> float:
    """x in the stick zone (0 <= x < b), the slip zone inside a1, or outside a1."""
    if zone == "stick":
        return c["b"] * fraction
    if zone == "slip inside a1":
        return c["b"] + (c["a1"] - c["b"]) * fraction
    return c["a1"] + (c["a2"] - c["a1"]) * fraction


# --- (48) and (47) -------------------------------------------------------------------------------


def test_hertz_pressure_is_eq48_and_zero_outside_the_contact():
    c = draw(
        ratio=uniform(-2.0, 2.0),
        P=log_uniform(1.0, 1e3),
        R=log_uniform(0.1, 10.0),
        E_star=log_uniform(0.1, 10.0),
    )
    P, R, E_star = c["P"], c["R"], c["E_star"]
    x = c["ratio"] * eq29_half_width(P, R, E_star)
    expected = eq48_pressure(x, P, R, E_star)
    assert np.count_nonzero(expected == 0) > 1000  # both outside and inside were drawn
    assert_within(
        hertz_pressure(x, P, R, E_star),
        expected,
        rtol=1e-12,
        atol=edge_allowance(x, P, R, E_star),
        inputs=c,
    )


@pytest.mark.parametrize("zone", ["0 < x < b", "b < x < a1", "a1 < x < a2"])
def test_exact_difference_is_eq47_piecewise(zone):
    c = draw(
        fraction=uniform(0.0, 0.999),
        P1=log_uniform(1.0, 1e3),
        relative_dP=log_uniform(1e-3, 0.2),
        mu=log_uniform(0.05, 1.0),
        lam_over_mu=uniform(1.05, 5.0),
        R=log_uniform(0.1, 10.0),
        E_star=log_uniform(0.1, 10.0),
    )
    P1, mu, R, E_star = c["P1"], c["mu"], c["R"], c["E_star"]
    dP = c["relative_dP"] * P1
    P_K = eq33_permanent_stick_load(P1, dP, c["lam_over_mu"] * mu, mu)
    ends = [0.0, *(eq29_half_width(P, R, E_star) for P in (P_K, P1, P1 + dP))]
    index = ["0 < x < b", "b < x < a1", "a1 < x < a2"].index(zone)
    x = ends[index] + (ends[index + 1] - ends[index]) * c["fraction"]
    expected = eq47_traction_difference(x, P1, dP, P_K, mu, R, E_star)
    # (47) subtracts pressures of size p(0, P2): rounding is relative to that, plus the
    # square-root sensitivity of each pressure at its own edge.
    scale = 4 * mu * eq48_pressure(0.0, P1 + dP, R, E_star)
    edges = sum(
        weight * edge_allowance(x, P, R, E_star) for weight, P in ((1, P1 + dP), (1, P1), (2, P_K))
    )
    got = hertz_shear_traction_difference(x, P1, dP, P_K, mu, R, E_star)
    assert_within(got, expected, atol=1e-12 * scale + mu * edges, inputs=c)


def test_exact_difference_vanishes_beyond_the_contact_without_warnings():
    x = np.array([11.6, 20.0, -30.0])  # a2 = 11.56 for the Fig. 5 loads
    assert np.all(hertz_shear_traction_difference(x, 100.0, 5.0, 97.5, 0.1, 1.0, 1.0) == 0.0)


# --- (49): closed form against quadrature --------------------------------------------------------


# Slow (CI's `pytest -m slow`): an mpmath principal-value quadrature per example, about 0.05 s
# each.  The default run checks (49) against quadrature at fixed points below, in
# tests/test_fig5.py and in the accuracy harness.
@pytest.mark.slow
@pytest.mark.parametrize("zone", ["stick", "slip inside a1", "slip outside a1"])
@settings(max_examples=50, deadline=None)
@given(c=edge_state(), fraction=real(0.001, 0.99))
def test_closed_form_eq49_matches_quadrature_of_the_dislocation_integral(zone, c, fraction):
    x = position(c, zone, fraction)
    reference = eq49_by_quadrature(x, c)
    difference = abs(closed_form(x, c) - reference)
    assert difference <= 1e-12 * max(abs(reference), term_scale(x, c))


@pytest.mark.parametrize("x", [0.0, 5.0, 11.0, 11.2, 11.5])
def test_closed_form_eq49_matches_quadrature_in_fig5_like_state_to_1e12_relative(x):
    c = fig5_like_state(b_shift=-3e-5)
    reference = eq49_by_quadrature(x, c)
    assert abs(closed_form(x, c) - reference) <= 1e-12 * abs(reference)


def fig5_like_state(b_shift: float) -> dict[str, float]:
    """Hertz with R = E* = 1, mu = 0.1, lam = 0.2, P1 = 100, dP = 5; b = b17 + b_shift."""
    a1, a2 = eq29_half_width(100.0, 1, 1), eq29_half_width(105.0, 1, 1)
    L_I1, L_I2 = math.sqrt(a1 / 2), math.sqrt(a2 / 2)  # (31) with E* = R = 1
    c = {
        "a1": a1,
        "a2": a2,
        "mu": 0.1,
        "L_I1": L_I1,
        "L_I2": L_I2,
        "L_II1": 0.2 * L_I1,
        "L_II2": 0.2 * L_I2,
        "E_star": 1.0,
    }
    c["b"] = eq17_stick_boundary(c) + b_shift
    return c


def consistent_states(**more) -> dict[str, np.ndarray]:
    """A proportional cycle with lam > mu, so that b of (17) lies inside a1, and b = b17.

    Arrays, with the further inputs ``more`` drawn alongside.
    """
    c = draw(
        a1=log_uniform(0.5, 20.0),
        mu=log_uniform(0.05, 1.0),
        lam_over_mu=uniform(1.1, 4.0),
        L_I1=log_uniform(0.1, 10.0),
        multiplier_ratio=uniform(0.95, 1.05),
        relative_growth=log_uniform(1e-3, 0.1),
        **more,
    )
    lam = c["mu"] * c["lam_over_mu"]
    c["a2"] = c["a1"] * (1 + c["relative_growth"])
    c["L_I2"] = c["L_I1"] * c["multiplier_ratio"]
    c["L_II1"], c["L_II2"], c["E_star"] = lam * c["L_I1"], lam * c["L_I2"], 1.0
    c["b"] = stick_boundary(c["mu"], c["a1"], c["a2"], c["L_I1"], c["L_I2"], c["L_II1"], c["L_II2"])
    return c


def test_with_consistent_b_the_slip_zone_carries_mu_p2_plus_mu_p1():
    c = consistent_states(fraction=uniform(0.0, 0.99))
    x = c["b"] + (c["a2"] - c["b"]) * c["fraction"]
    # (8) and (11): q2 - q1 = mu p2 + mu p1 with the asymptotes (4).
    expected = c["mu"] * c["L_I2"] * np.sqrt(c["a2"] - x) + c["mu"] * c["L_I1"] * np.sqrt(
        np.maximum(0.0, c["a1"] - x)
    )
    # b17 itself is rounded to ~eps * a2; the edge term K (b - b17)/(2 sqrt(a2 - x)) turns that
    # rounding into the absolute allowance.
    K = c["mu"] * (c["L_I1"] + c["L_I2"]) + c["L_II1"] - c["L_II2"]
    assert_within(
        closed_form(x, c),
        expected,
        rtol=1e-12,
        atol=4e-16 * abs(K) * c["a2"] / np.sqrt(c["a2"] - x),
        inputs=c,
    )


@pytest.mark.parametrize("b_shift", [-1e-2, -3e-5, 2e-3])
@pytest.mark.parametrize("fraction", [0.05, 0.5, 0.95])
def test_other_b_adds_edge_term_K_times_b_minus_b17_over_2_sqrt_a2_minus_x(b_shift, fraction):
    c = fig5_like_state(b_shift)
    b17 = eq17_stick_boundary(c)  # (17) does not depend on the b stored in c
    x = c["b"] + (c["a2"] - c["b"]) * fraction
    K = c["mu"] * (c["L_I1"] + c["L_I2"]) + c["L_II1"] - c["L_II2"]
    with mpmath.workdps(DPS):
        slip_zone = c["mu"] * c["L_I2"] * mpmath.sqrt(c["a2"] - x) + c["mu"] * c[
            "L_I1"
        ] * mpmath.sqrt(max(0.0, c["a1"] - x))
        edge_term = (eq49_by_quadrature(x, c) - slip_zone) * 2 * mpmath.sqrt(c["a2"] - x)
        assert abs(edge_term - K * (c["b"] - b17)) < 1e-9 * abs(K * b_shift)


def test_valid_input_at_the_zone_boundaries_raises_no_warning():
    c = fig5_like_state(b_shift=-3e-5)
    x = np.array([-5.0, 0.0, c["b"], c["a1"], np.nextafter(c["a2"], 0)])
    assert np.all(np.isfinite(closed_form(x, c)))  # -W error turns any warning into a failure
    slip = slip_on_loading(
        x, c["b"], c["a1"], c["mu"], c["L_I1"], c["L_I2"], c["L_II1"], c["L_II2"], c["E_star"]
    )
    assert np.all(np.isfinite(slip))


# --- slip displacement ---------------------------------------------------------------------------


def slip(x, c):
    return slip_on_loading(
        x, c["b"], c["a1"], c["mu"], c["L_I1"], c["L_I2"], c["L_II1"], c["L_II2"], c["E_star"]
    )


# Slow (CI's `pytest -m slow`): an mpmath quadrature per example.  The default run checks the
# slip against quadrature in the accuracy harness (slip_on_loading).
@pytest.mark.slow
@pytest.mark.parametrize("zone", ["slip inside a1", "slip outside a1"])
@settings(max_examples=60, deadline=None)
@given(c=edge_state(), fraction=real(0.0, 1.0))
def test_slip_is_the_integral_of_eq15_from_the_stick_boundary(zone, c, fraction):
    x = position(c, zone, fraction)
    with mpmath.workdps(DPS):
        v = {key: mpmath.mpf(value) for key, value in c.items()}
        xv = mpmath.mpf(x)
        reference = mpmath.quad(
            lambda t: eq15_density(t, v), sorted({v["b"], min(v["a1"], xv), xv})
        )
    # The two terms of the closed form have size |coefficient| (x - c)^(3/2).
    K = c["mu"] * (c["L_I1"] + c["L_I2"]) + c["L_II1"] - c["L_II2"]
    A1 = c["mu"] * c["L_I1"] + c["L_II1"]
    scale = (abs(K) + abs(A1)) * (x - c["b"]) ** 1.5 / c["E_star"]
    assert abs(slip(x, c) - reference) <= 1e-12 * max(abs(reference), scale)


def test_slip_is_zero_in_the_stick_zone():
    c = draw(
        a1=log_uniform(0.5, 20.0),
        relative_growth=log_uniform(1e-3, 0.1),
        b_shift=uniform(0.0, 3.0),
        mu=log_uniform(0.05, 1.0),
        L_I1=log_uniform(0.1, 10.0),
        multiplier_ratio=uniform(0.9, 1.1),
        L_II1=uniform(-5.0, 5.0),
        L_II2=uniform(-5.0, 5.0),
        E_star=log_uniform(0.1, 100.0),
        fraction=uniform(0.0, 1.0),
    )
    da = c["a1"] * c["relative_growth"]  # the states of edge_state(), as arrays
    c.update(a2=c["a1"] + da, b=c["a1"] - da * c["b_shift"], L_I2=c["L_I1"] * c["multiplier_ratio"])
    assert_within(slip(c["b"] * c["fraction"], c), 0.0, inputs=c)
