"""(22) against the Jaeger-Ciavarella stick zone a(P_K) of (33) on power laws, by mpmath.

Everything here is transcribed by hand: the power law a = (P/k)^(1/n), L_I from (19), (22) and
(28) with eta = 0, and P_K from (33).  The dP^2 coefficient of b(22) - a(P_K) is extracted by
Richardson extrapolation of (b - a(P_K))/dP^2 at 50 digits and compared with the generated
coefficient.
"""

from __future__ import annotations

import mpmath
import numpy as np
import pytest
from hypothesis import given, settings

from asymslip_gen.generic_law import (
    second_order_stick_boundary_gap,
    second_order_stick_boundary_gap_from_multiplier,
)
from tests.strategies import real


def half_width(P, n, k):
    """Power law P = k a^n (k = K E* A), inverted."""
    return (P / k) ** (1 / mpmath.mpf(n))


def eq19(P, n, k):
    """(19): L_I = (1/pi) sqrt(2/a) dP/da, with dP/da = n k a^(n-1) = n P/a."""
    a = half_width(P, n, k)
    return mpmath.sqrt(2 / a) * (n * P / a) / mpmath.pi


def eq22(mu, lam, a1, a2, L_I1, L_I2):
    """(22) with eta = 0 (lam/mu formed in mpmath: a rounded double would not cancel at O(dP))."""
    ratio = mpmath.mpf(lam) / mpmath.mpf(mu)
    bracket2, bracket1 = 1 - ratio, 1 + ratio
    return (bracket2 * L_I2 * a2 + bracket1 * L_I1 * a1) / (bracket2 * L_I2 + bracket1 * L_I1)


def eq28(mu, lam, a1, dP, da_dP):
    """(28) with eta = 0: b/a1 to first order."""
    return 1 - dP * da_dP / (2 * a1) * (mpmath.mpf(lam) / mpmath.mpf(mu) - 1)


def eq33(P1, dP, lam, mu):
    """(33) on the proportional path: P2 = P1 + dP, Q2 - Q1 = lam dP."""
    return P1 + dP / 2 - mpmath.mpf(lam) * dP / (2 * mpmath.mpf(mu))


def gap(P1, dP, mu, lam, n, k):
    """b(22) - a(P_K) for the power law."""
    b = eq22(
        mu,
        lam,
        half_width(P1, n, k),
        half_width(P1 + dP, n, k),
        eq19(P1, n, k),
        eq19(P1 + dP, n, k),
    )
    return b - half_width(eq33(P1, dP, lam, mu), n, k)


def richardson_second_order(function, step):
    """lim_{h->0} function(h)/h^2 for function = C h^2 + D h^3 + E h^4 + ..., error O(step^3)."""
    q = [function(step / 2**j) / (step / 2**j) ** 2 for j in range(3)]
    first = [2 * q[j + 1] - q[j] for j in range(2)]  # removes D h
    return (4 * first[1] - first[0]) / 3  # removes E h^2


def derivatives(P1, n, k):
    """a(P1), a'(P1), a''(P1) by mpmath's numerical differentiation."""
    a = half_width(P1, n, k)
    return (
        a,
        mpmath.diff(lambda P: half_width(P, n, k), P1),
        mpmath.diff(lambda P: half_width(P, n, k), P1, 2),
    )


CASES = [(1.0, 0.3, 0.5), (1.5, 0.2, -0.1), (3.0, 0.5, 1.2), (5.0, 0.4, 0.9)]  # (n, mu, lam)


@pytest.mark.parametrize("n, mu, lam", CASES)
def test_second_order_gap_matches_richardson_extrapolation_on_power_laws(n, mu, lam):
    P1, k = mpmath.mpf(7), mpmath.mpf("2.5")
    with mpmath.workdps(50):
        reference = richardson_second_order(lambda h: gap(P1, h, mu, lam, n, k), P1 * 1e-5)
        a1, slope, curvature = derivatives(P1, n, k)
    computed = second_order_stick_boundary_gap(mu, lam, float(a1), float(slope), float(curvature))
    assert abs(computed - reference) < 1e-13 * abs(reference)


def test_second_order_gap_vanishes_for_hertz_where_a_squared_is_affine():
    P1, k, mu, lam = mpmath.mpf(7), mpmath.mpf("2.5"), 0.3, 0.5
    with mpmath.workdps(50):
        reference = richardson_second_order(lambda h: gap(P1, h, mu, lam, 2, k), P1 * 1e-5)
        a1, slope, curvature = derivatives(P1, 2, k)
        wedge = richardson_second_order(lambda h: gap(P1, h, mu, lam, 1, k), P1 * 1e-5)
    computed = second_order_stick_boundary_gap(mu, lam, float(a1), float(slope), float(curvature))
    # Zero (to the O(h^3) extrapolation error), against the wedge's coefficient at that load.
    assert abs(reference) < 1e-13 * abs(wedge)
    assert abs(computed) < 1e-14 * abs(wedge)


@pytest.mark.parametrize("n, mu, lam", CASES)
def test_eq22_eq28_and_a_of_P_K_agree_to_first_order(n, mu, lam):
    P1, k = mpmath.mpf(7), mpmath.mpf("2.5")
    with mpmath.workdps(50):
        a1, slope, _ = derivatives(P1, n, k)
        for h in (P1 * 1e-5, P1 * 1e-6):
            b28 = a1 * eq28(mu, lam, a1, h, slope)
            exact = half_width(eq33(P1, h, lam, mu), n, k)
            b22 = exact + gap(P1, h, mu, lam, n, k)
            # The first-order change (b28 - a1) is of order h a'; the differences are O(h^2).
            first_order_change = abs(b28 - a1)
            assert abs(b22 - b28) < 10 * (h / P1) * first_order_change
            assert abs(exact - b28) < 10 * (h / P1) * first_order_change


@settings(max_examples=40, deadline=None)
@given(n=real(1.0, 6.0), mu=real(0.05, 1.5), lam=real(-3.0, 3.0), P1=real(0.1, 100.0))
def test_gap_from_the_multiplier_slope_equals_gap_from_the_curvature(n, mu, lam, P1):
    k = mpmath.mpf(3)
    with mpmath.workdps(30):
        P = mpmath.mpf(P1)
        a1, slope, curvature = derivatives(P, n, k)
        L_I1 = eq19(P, n, k)
        L_I_slope = mpmath.diff(lambda load: eq19(load, n, k), P)
    from_curvature = second_order_stick_boundary_gap(
        mu, lam, float(a1), float(slope), float(curvature)
    )
    from_multiplier = second_order_stick_boundary_gap_from_multiplier(
        mu, lam, float(a1), float(slope), float(L_I1), float(L_I_slope)
    )
    scale = abs(1 - lam**2 / mu**2) * float(slope) ** 2 / float(a1)  # size of each term
    assert abs(from_curvature - from_multiplier) <= 1e-12 * scale


def test_gap_changes_sign_with_n_minus_2_for_lam_beyond_mu():
    # lam > mu (the paper's case): the coefficient has the sign of (2 - n) (1 - lam^2/mu^2)...
    mu, lam, P1, k = 0.3, 0.6, mpmath.mpf(5), mpmath.mpf(1)
    signs = []
    for n in (1.0, 3.0):
        with mpmath.workdps(30):
            a1, slope, curvature = derivatives(P1, n, k)
        signs.append(
            np.sign(
                second_order_stick_boundary_gap(mu, lam, float(a1), float(slope), float(curvature))
            )
        )
    # ... which is positive for the wedge (n = 1) and negative for n = 3.
    assert signs == [1.0, -1.0]
