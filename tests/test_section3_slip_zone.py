"""Section 3.1-3.3: the Hertzian slip zone by the exact solution, corrective stick and slip.

The oracle is the paper itself: Eqs. (29), (31), (33)-(36), (39)-(45) and (22) are transcribed
by hand below in plain NumPy (``paper_*`` functions), independently of the SymPy derivations,
and compared with the generated kernels.  Where a hand transcription would subtract nearly
equal numbers (a2 - a1, a1 - b), it is rationalised by hand with (29) and says so.  Precision
claims and the higher-order discrepancies beyond the paper are checked against mpmath at 50
digits, from the paper's formulas written out again in mpmath.  Property tests draw their
inputs as arrays (``tests/sampling.py``: every corner of the input box, then 50,000 random
points) and evaluate each kernel once on all of them.
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest

from asymslip_gen.corrective_slip import stick_boundary_proportional
from asymslip_gen.corrective_stick import (
    corrective_stick_slip_zone_width,
    hertz_slip_zone_width_corrective_stick,
    hertz_stick_boundary_corrective_stick,
    shear_intensity_rate,
)
from asymslip_gen.exact_solution import (
    hertz_slip_zone_width_exact,
    hertz_stick_boundary_exact,
    permanent_stick_load,
)
from asymslip_gen.hertz import hertz_half_width, hertz_normal_edge_multiplier
from asymslip_gen.method_agreement import (
    corrective_slip_discrepancy_third_order,
    corrective_stick_discrepancy_second_order,
    corrective_stick_discrepancy_third_order,
    hertz_slip_zone_width_first_order,
)
from tests.sampling import assert_within, draw, log_uniform, uniform

RTOL = 1e-12
PI = math.pi

# ---------------------------------------------------------------- the paper, by hand (NumPy)


def paper_29_half_width(P, R, E):
    """(29): a^2 = 4 P R / (pi E*)."""
    return np.sqrt(4 * P * R / (PI * E))


def paper_29_growth(P1, dP, R, E):
    """a2 - a1 from (29), rationalised by hand: (a2^2 - a1^2)/(a2 + a1)."""
    a1, a2 = paper_29_half_width(P1, R, E), paper_29_half_width(P1 + dP, R, E)
    return (4 * dP * R / (PI * E)) / (a1 + a2)


def paper_31_multiplier(a, R, E):
    """(31): L_I = (E*/R) sqrt(a/2)."""
    return E / R * np.sqrt(a / 2)


def paper_33_permanent_stick_load(P1, P2, Q1, Q2, mu):
    """(33): P_K = (P1 + P2)/2 - (Q2 - Q1)/(2 mu)."""
    return (P1 + P2) / 2 - (Q2 - Q1) / (2 * mu)


def paper_34_stick_boundary(P1, P2, Q1, Q2, mu, R, E):
    """(34): b^2 = (2R/(pi E*)) (P1 + P2 - (Q2 - Q1)/mu)."""
    return np.sqrt(2 * R / (PI * E) * (P1 + P2 - (Q2 - Q1) / mu))


def paper_35_stick_boundary(P1, dP, lam, mu, R, E):
    """(35): b^2 = a1^2 (1 + dP (mu - lam)/(2 mu P1))."""
    a1 = paper_29_half_width(P1, R, E)
    return a1 * np.sqrt(1 + dP / (2 * mu * P1) * (mu - lam))


def paper_35_slip_zone_width(P1, dP, lam, mu, R, E):
    """a1 - b from (35), rationalised by hand: a1^2 dP (lam - mu)/(2 mu P1) / (a1 + b)."""
    a1 = paper_29_half_width(P1, R, E)
    b = paper_35_stick_boundary(P1, dP, lam, mu, R, E)
    return a1**2 * dP * (lam - mu) / (2 * mu * P1) / (a1 + b)


def paper_36_stick_ratio(P1, dP, lam, mu):
    """(36): b/a1 = 1 - (lam/mu - 1) dP/(4 P1)."""
    return 1 - (lam / mu - 1) * dP / (4 * P1)


def paper_39_intensity_rate(lam, eta, a):
    """(39): Delta K_II / Delta P = lam/(pi sqrt(2a)) + (eta/4) sqrt(a/2)."""
    return lam / (PI * np.sqrt(2 * a)) + eta / 4 * np.sqrt(a / 2)


def paper_40_width(mu, lam, eta, a1, da, L_I1, dP):
    """(40): d1 = Delta K_II/(mu L_I) - Delta a/2, with Delta K_II = dP (39) at a1."""
    return dP * paper_39_intensity_rate(lam, eta, a1) / (mu * L_I1) - da / 2


def size_of_40_terms(mu, lam, eta, a1, da, L_I1, dP):
    """Sum of the magnitudes of the terms of (40): the scale of its rounding errors."""
    rate = abs(lam) / (PI * np.sqrt(2 * a1)) + abs(eta) / 4 * np.sqrt(a1 / 2)
    return dP * rate / (mu * L_I1) + da / 2


def paper_41_stick_boundary(P1, dP, lam, eta, mu, R, E):
    """(41): b = a1 - dP R/(pi mu E* a1) (lam + pi eta a1/4) + (a2 - a1)/2."""
    a1 = paper_29_half_width(P1, R, E)
    growth = paper_29_growth(P1, dP, R, E)
    return a1 - dP * R / (PI * mu * E * a1) * (lam + PI * eta * a1 / 4) + growth / 2


def paper_41_width(P1, dP, lam, eta, mu, R, E):
    """a1 - b from (41): dP R (lam + pi eta a1/4)/(pi mu E* a1) - (a2 - a1)/2."""
    a1 = paper_29_half_width(P1, R, E)
    growth = paper_29_growth(P1, dP, R, E)
    return dP * R / (PI * mu * E * a1) * (lam + PI * eta * a1 / 4) - growth / 2


def size_of_41_terms(P1, dP, lam, eta, mu, R, E):
    """Sum of the magnitudes of the terms of a1 - b in (41): the scale of rounding errors."""
    a1 = paper_29_half_width(P1, R, E)
    growth = paper_29_growth(P1, dP, R, E)
    return dP * R / (PI * mu * E * a1) * (abs(lam) + PI * abs(eta) * a1 / 4) + growth / 2


def paper_42_half_width(P1, dP, R, E):
    """(42): a2 ~ a1 (1 + 2 R dP/(pi E* a1^2))."""
    a1 = paper_29_half_width(P1, R, E)
    return a1 * (1 + 2 * R * dP / (PI * E * a1**2))


def paper_43_stick_boundary(P1, dP, lam, eta, mu, R, E):
    """(43): b ~ (a1/2)(2 + 2 R dP/(pi E* a1^2)) - dP R/(pi a1 mu E*) (lam + pi eta a1/4)."""
    a1 = paper_29_half_width(P1, R, E)
    return a1 / 2 * (2 + 2 * R * dP / (PI * E * a1**2)) - dP * R / (PI * a1 * mu * E) * (
        lam + PI * eta * a1 / 4
    )


def paper_44_slip_zone_width(P1, dP, lam, eta, mu, R, E):
    """(44) as a width: a1 - b = a1 (lam/mu + (eta/mu) pi a1/4 - 1) dP/(4 P1)."""
    a1 = paper_29_half_width(P1, R, E)
    return a1 * (lam / mu + eta / mu * PI * a1 / 4 - 1) * dP / (4 * P1)


def paper_45_stick_ratio(P1, dP, lam, mu):
    """(45): b/a1 = 1 - (lam/mu - 1) dP/(4 P1)."""
    return 1 - (lam / mu - 1) * dP / (4 * P1)


def paper_22_stick_boundary(mu, lam, eta, a1, a2, L1, L2):
    """(22) with the brackets (1 -+ lam/mu -+ pi a_i eta/(4 mu))."""
    A = (1 - lam / mu - PI * a2 / 4 * eta / mu) * L2
    C = (1 + lam / mu + PI * a1 / 4 * eta / mu) * L1
    return (A * a2 + C * a1) / (A + C)


# ---------------------------------------------------------------- valid inputs

# The paper's case is lam >= mu: forward slip at the right-hand edge during loading, b <= a1.
# dP/P1 <= 0.2 keeps (32) reasonable and P_K = P1 (1 - eps (r - 1)/2) > 0 for r <= 6.
LOAD = log_uniform(1e-2, 1e4)  # P1
RELATIVE_CHANGE = log_uniform(1e-6, 0.2)  # eps = dP/P1
FRICTION = log_uniform(0.05, 1.0)  # mu
SLOPE_RATIO = uniform(1.0, 6.0)  # r = lam/mu
RADIUS = log_uniform(1e-2, 1e3)  # R
MODULUS = log_uniform(1e-2, 1e3)  # E*
TENSION_TERM = uniform(-1.0, 3.0)  # t = pi eta a1 / (4 mu)

# The Hertzian cycles of Section 3, with and without bulk tension.
HERTZ_CYCLE = {
    "P1": LOAD,
    "eps": RELATIVE_CHANGE,
    "mu": FRICTION,
    "r": SLOPE_RATIO,
    "R": RADIUS,
    "E": MODULUS,
}
TENSION_CYCLE = {**HERTZ_CYCLE, "t": TENSION_TERM}


def hertz_cycles(ranges=HERTZ_CYCLE, **changed):
    """Samples of ``ranges`` (entries replaced by ``changed``), with dP = eps P1 and lam = r mu,
    and with eta = 4 mu t/(pi a1) when a tension term t is drawn."""
    c = draw(**{**ranges, **changed})
    c["dP"], c["lam"] = c["eps"] * c["P1"], c["r"] * c["mu"]
    if "t" in c:
        c["eta"] = _eta(c["t"], c["mu"], paper_29_half_width(c["P1"], c["R"], c["E"]))
    return c


def _eta(t, mu, a1):
    return 4 * mu * t / (PI * a1)


def _close(actual, expected, rtol=RTOL):
    assert actual == pytest.approx(expected, rel=rtol, abs=0), (actual, expected)


def _args(c, names):
    return tuple(c[name] for name in names.split())


# ---------------------------------------------------------------- Section 3.1: exact solution


def test_permanent_stick_load_is_eq33_on_the_proportional_path():
    c = hertz_cycles(
        {
            "P1": LOAD,
            "eps": RELATIVE_CHANGE,
            "mu": FRICTION,
            "r": SLOPE_RATIO,
            "q1": uniform(-1.0, 1.0),
        }
    )
    P1, dP, lam, mu = _args(c, "P1 dP lam mu")
    Q1 = c["q1"] * mu * P1  # state 1 below sliding, |Q1| <= mu P1
    expected = paper_33_permanent_stick_load(P1, P1 + dP, Q1, Q1 + lam * dP, mu)
    assert_within(permanent_stick_load(P1, dP, lam, mu), expected, rtol=RTOL, inputs=c)


def test_exact_stick_boundary_is_eq34():
    c = hertz_cycles()
    P1, dP, lam, mu, R, E = _args(c, "P1 dP lam mu R E")
    expected = paper_34_stick_boundary(P1, P1 + dP, 0.0, lam * dP, mu, R, E)
    assert_within(hertz_stick_boundary_exact(P1, dP, lam, mu, R, E), expected, rtol=RTOL, inputs=c)


def test_eq35_is_exact_not_an_approximation_at_large_load_change():
    # Erratum: the paper obtains (35) "using the approximations (32)"; at dP/P1 up to 0.5 the
    # hand-transcribed (35) still equals (34) to rounding.
    c = hertz_cycles(eps=uniform(0.2, 0.5), r=uniform(1.0, 3.0))
    P1, dP, lam, mu, R, E = _args(c, "P1 dP lam mu R E")
    from_34 = paper_34_stick_boundary(P1, P1 + dP, 0.0, lam * dP, mu, R, E)
    assert_within(paper_35_stick_boundary(P1, dP, lam, mu, R, E), from_34, rtol=1e-13, inputs=c)


def test_exact_slip_zone_width_is_eq35():
    c = hertz_cycles()
    args = _args(c, "P1 dP lam mu R E")
    assert_within(
        hertz_slip_zone_width_exact(*args), paper_35_slip_zone_width(*args), rtol=RTOL, inputs=c
    )


@pytest.mark.parametrize("lam", [0.1000001, 0.2, 0.35, 1.0])
def test_exact_slip_zone_width_keeps_1e12_precision_at_dP_over_P1_1e10(lam):
    P1, dP, mu, R, E = 100.0, 1e-8, 0.1, 1.0, 1.0  # dP/P1 = 1e-10
    with mpmath.workdps(50):
        m = {k: mpmath.mpf(v) for k, v in dict(P1=P1, dP=dP, lam=lam, mu=mu, R=R, E=E).items()}
        load_K = m["P1"] + m["dP"] * (m["mu"] - m["lam"]) / (2 * m["mu"])  # (33)
        scale = 4 * m["R"] / (mpmath.pi * m["E"])  # (29)
        reference = mpmath.sqrt(scale * m["P1"]) - mpmath.sqrt(scale * load_K)
        width = hertz_slip_zone_width_exact(P1, dP, lam, mu, R, E)
        error = abs((mpmath.mpf(float(width)) - reference) / reference)
    print(f"lam={lam}: a1 - b = {float(reference):.16e}, relative error {float(error):.1e}")
    assert error < 1e-12


@pytest.mark.parametrize("eps", [1e-4, 1e-6, 1e-8])
def test_eq36_is_the_first_order_term_of_the_exact_slip_zone(eps):
    P1, mu, lam, R, E = 100.0, 0.1, 0.2, 1.0, 1.0
    dP = eps * P1
    a1 = paper_29_half_width(P1, R, E)
    first_order_width = a1 * (lam / mu - 1) * dP / (4 * P1)  # a1 (1 - (36))
    exact = hertz_slip_zone_width_exact(P1, dP, lam, mu, R, E)
    relative = abs(exact / first_order_width - 1)
    print(f"eps={eps:g}: |exact/(36) - 1| = {relative:.2e}")
    # Next term of sqrt(1 + eps (1 - r)/2) is relative eps (r - 1)/8 = eps/8 here.
    assert relative == pytest.approx(eps / 8, rel=1e-2)


# ---------------------------------------------------------------- Section 3.2: corrective stick


def test_shear_intensity_rate_is_eq39():
    c = draw(mu=FRICTION, r=SLOPE_RATIO, t=TENSION_TERM, a=log_uniform(1e-2, 1e2))
    a, lam = c["a"], c["r"] * c["mu"]
    eta = _eta(c["t"], c["mu"], a)
    # The two terms of (39) cancel when lam + pi eta a/4 = 0: rounding is relative to them.
    scale = abs(lam) / (PI * np.sqrt(2 * a)) + abs(eta) / 4 * np.sqrt(a / 2)
    assert_within(
        shear_intensity_rate(lam, eta, a),
        paper_39_intensity_rate(lam, eta, a),
        atol=RTOL * scale,
        inputs=c,
    )


def test_corrective_stick_width_is_eq40():
    c = draw(
        mu=FRICTION,
        r=SLOPE_RATIO,
        t=TENSION_TERM,
        a1=log_uniform(1e-2, 1e2),
        da_ratio=log_uniform(1e-6, 0.1),
        L_I1=log_uniform(1e-2, 1e3),
        dP=log_uniform(1e-6, 1e2),
    )
    mu, a1, L_I1, dP = _args(c, "mu a1 L_I1 dP")
    lam, eta, da = c["r"] * mu, _eta(c["t"], mu, a1), c["da_ratio"] * a1
    width = corrective_stick_slip_zone_width(mu, lam, eta, a1, da, L_I1, dP)
    # The terms of (40) may cancel (d1 = 0 is a valid answer): rounding is relative to them.
    scale = size_of_40_terms(mu, lam, eta, a1, da, L_I1, dP)
    assert_within(
        width, paper_40_width(mu, lam, eta, a1, da, L_I1, dP), atol=RTOL * scale, inputs=c
    )


def test_hertz_corrective_stick_boundary_is_eq41():
    c = hertz_cycles(TENSION_CYCLE)
    args = _args(c, "P1 dP lam eta mu R E")
    assert_within(
        hertz_stick_boundary_corrective_stick(*args),
        paper_41_stick_boundary(*args),
        rtol=RTOL,
        inputs=c,
    )


def test_hertz_corrective_stick_width_is_eq41():
    c = hertz_cycles(TENSION_CYCLE)
    args = _args(c, "P1 dP lam eta mu R E")
    # The two terms of a1 - b may cancel: rounding is relative to their size.
    assert_within(
        hertz_slip_zone_width_corrective_stick(*args),
        paper_41_width(*args),
        atol=RTOL * size_of_41_terms(*args),
        inputs=c,
    )


def test_hertz_corrective_stick_width_is_generic_eq40_with_eq31():
    c = hertz_cycles(TENSION_CYCLE)
    P1, dP, lam, eta, mu, R, E = _args(c, "P1 dP lam eta mu R E")
    a1 = paper_29_half_width(P1, R, E)
    generic = corrective_stick_slip_zone_width(
        mu, lam, eta, a1, paper_29_growth(P1, dP, R, E), paper_31_multiplier(a1, R, E), dP
    )
    hertz = hertz_slip_zone_width_corrective_stick(P1, dP, lam, eta, mu, R, E)
    assert_within(
        hertz, generic, atol=RTOL * size_of_41_terms(P1, dP, lam, eta, mu, R, E), inputs=c
    )


def test_hertz_corrective_stick_width_keeps_precision_at_lam_equal_mu():
    # At lam = mu, eta = 0 the two O(dP) terms of (41) cancel and a1 - b is O(dP^2).
    P1, dP, mu, R, E = 100.0, 1e-8, 0.1, 1.0, 1.0
    with mpmath.workdps(50):
        P1m, dPm, mum = mpmath.mpf(P1), mpmath.mpf(dP), mpmath.mpf(mu)
        a1 = mpmath.sqrt(4 * P1m / mpmath.pi)
        a2 = mpmath.sqrt(4 * (P1m + dPm) / mpmath.pi)
        reference = dPm / (mpmath.pi * mum * a1) * mum - (a2 - a1) / 2  # (41), lam = mu
        width = hertz_slip_zone_width_corrective_stick(P1, dP, mu, 0.0, mu, R, E)
        error = abs((mpmath.mpf(float(width)) - reference) / reference)
    print(f"a1 - b = {float(reference):.16e} (O(dP^2)), relative error {float(error):.1e}")
    assert error < 1e-12


@pytest.mark.parametrize("eps", [1e-2, 1e-3])
def test_eq42_is_the_hertz_growth_to_first_order(eps):
    P1, R, E = 100.0, 1.0, 1.0
    a1 = paper_29_half_width(P1, R, E)
    error = (paper_42_half_width(P1, eps * P1, R, E) - hertz_half_width(P1 + eps * P1, R, E)) / a1
    print(f"eps={eps:g}: ((42) - a(P1 + dP))/a1 = {error:.4e}, eps^2/8 = {eps**2 / 8:.4e}")
    # a1 sqrt(1 + eps) = a1 (1 + eps/2 - eps^2/8 + ...): (42) drops the eps^2/8.
    assert error == pytest.approx(eps**2 / 8, rel=eps)


@pytest.mark.parametrize("eps", [1e-2, 1e-3])
def test_eq43_is_eq41_with_the_first_order_growth(eps):
    P1, mu, lam, R, E = 100.0, 0.1, 0.2, 1.0, 1.0
    a1 = paper_29_half_width(P1, R, E)
    eta = _eta(0.5, mu, a1)
    full = hertz_stick_boundary_corrective_stick(P1, eps * P1, lam, eta, mu, R, E)
    error = (paper_43_stick_boundary(P1, eps * P1, lam, eta, mu, R, E) - full) / a1
    print(f"eps={eps:g}: ((43) - (41))/a1 = {error:.4e}, eps^2/16 = {eps**2 / 16:.4e}")
    # Half the error of (42): (43) replaces (a2 - a1)/2 by its first-order term.
    assert error == pytest.approx(eps**2 / 16, rel=eps)


@pytest.mark.parametrize("eps", [1e-4, 1e-6])
def test_eq44_is_the_first_order_term_of_eq41_with_tension(eps):
    P1, mu, lam, R, E = 100.0, 0.1, 0.2, 1.0, 1.0
    a1 = paper_29_half_width(P1, R, E)
    eta = _eta(0.5, mu, a1)
    dP = eps * P1
    full = hertz_slip_zone_width_corrective_stick(P1, dP, lam, eta, mu, R, E)
    relative = abs(full / paper_44_slip_zone_width(P1, dP, lam, eta, mu, R, E) - 1)
    print(f"eps={eps:g}: |(41)/(44) - 1| = {relative:.2e}")
    assert relative < 2 * eps


def test_first_order_width_is_eq44():
    c = hertz_cycles(TENSION_CYCLE)
    P1, dP, lam, eta, mu, R, E = args = _args(c, "P1 dP lam eta mu R E")
    # (lam/mu + t - 1) may vanish: rounding is relative to the size of its terms.
    scale = paper_29_half_width(P1, R, E) * (lam / mu + abs(c["t"]) + 1) * dP / (4 * P1)
    assert_within(
        hertz_slip_zone_width_first_order(*args),
        paper_44_slip_zone_width(*args),
        atol=RTOL * scale,
        inputs=c,
    )


# ---------------------------------------------------------------- Section 3.3: corrective slip


def test_first_order_width_is_eq45_at_eta_zero():
    c = hertz_cycles(r=uniform(1.01, 6.0))
    P1, dP, lam, mu, R, E = _args(c, "P1 dP lam mu R E")
    a1 = paper_29_half_width(P1, R, E)
    ratio = hertz_slip_zone_width_first_order(P1, dP, lam, 0.0, mu, R, E) / a1
    # (45) is a ratio near 1 formed by hand: compare to a few units in the last place of 1.
    assert_within(1 - ratio, paper_45_stick_ratio(P1, dP, lam, mu), atol=1e-15, inputs=c)


def test_eq45_equals_eq36_and_eq44_at_eta_zero():
    P1, dP, mu, lam, R, E = 100.0, 5.0, 0.1, 0.2, 1.0, 1.0
    a1 = paper_29_half_width(P1, R, E)
    from_44 = 1 - paper_44_slip_zone_width(P1, dP, lam, 0.0, mu, R, E) / a1
    values = [paper_45_stick_ratio(P1, dP, lam, mu), paper_36_stick_ratio(P1, dP, lam, mu), from_44]
    print(f"(45), (36), (44) at Fig. 5: {values}")
    assert values[0] == values[1] == pytest.approx(values[2], rel=1e-15)


# ---------------------------------------------------------------- Fig. 5 parameters

FIG5 = dict(P1=100.0, dP=5.0, mu=0.1, lam=0.2, R=1.0, E=1.0)


def _fig5_generated():
    P1, dP, mu, lam, R, E = (FIG5[k] for k in ("P1", "dP", "mu", "lam", "R", "E"))
    a1, a2 = hertz_half_width(P1, R, E), hertz_half_width(P1 + dP, R, E)
    L1, L2 = hertz_normal_edge_multiplier(P1, R, E), hertz_normal_edge_multiplier(P1 + dP, R, E)
    return {
        "a1": a1,
        "a2": a2,
        "b exact (33)-(35)": hertz_stick_boundary_exact(P1, dP, lam, mu, R, E),
        "b (22)": stick_boundary_proportional(mu, lam, 0.0, a1, a2, L1, L2),
        "b first order (45)": a1 - hertz_slip_zone_width_first_order(P1, dP, lam, 0.0, mu, R, E),
        "b corrective stick (41)": hertz_stick_boundary_corrective_stick(
            P1, dP, lam, 0.0, mu, R, E
        ),
    }


def _fig5_by_hand():
    P1, dP, mu, lam, R, E = (FIG5[k] for k in ("P1", "dP", "mu", "lam", "R", "E"))
    a1, a2 = paper_29_half_width(P1, R, E), paper_29_half_width(P1 + dP, R, E)
    L1, L2 = paper_31_multiplier(a1, R, E), paper_31_multiplier(a2, R, E)
    return {
        "a1": a1,
        "a2": a2,
        "b exact (33)-(35)": paper_35_stick_boundary(P1, dP, lam, mu, R, E),
        "b (22)": paper_22_stick_boundary(mu, lam, 0.0, a1, a2, L1, L2),
        "b first order (45)": a1 * paper_45_stick_ratio(P1, dP, lam, mu),
        "b corrective stick (41)": paper_41_stick_boundary(P1, dP, lam, 0.0, mu, R, E),
    }


def test_fig5_slip_zone_numbers_match_the_hand_transcription():
    generated, by_hand = _fig5_generated(), _fig5_by_hand()
    for name, value in generated.items():
        print(f"{name:>24}: {float(value):.15f}  (hand {by_hand[name]:.15f})")
    for name, value in generated.items():
        _close(value, by_hand[name])


def test_fig5_corrective_slip_error_is_the_third_order_term():
    values, eps, r = _fig5_by_hand(), FIG5["dP"] / FIG5["P1"], FIG5["lam"] / FIG5["mu"]
    error = (values["b (22)"] - values["b exact (33)-(35)"]) / values["a1"]
    predicted = corrective_slip_discrepancy_third_order(FIG5["lam"], FIG5["mu"]) * eps**3
    print(f"(b22 - b_exact)/a1 = {error:.4e}, c3 eps^3 = {predicted:.4e} (r = {r})")
    # The next term is O(eps^4): 5 % of the eps^3 term at eps = 0.05 is ample.
    assert error == pytest.approx(predicted, rel=0.05)


def test_fig5_corrective_stick_error_is_the_second_order_term():
    values, eps = _fig5_by_hand(), FIG5["dP"] / FIG5["P1"]
    error = (values["b corrective stick (41)"] - values["b exact (33)-(35)"]) / values["a1"]
    c2 = corrective_stick_discrepancy_second_order(FIG5["lam"], FIG5["mu"])
    c3 = corrective_stick_discrepancy_third_order(FIG5["lam"], FIG5["mu"])
    predicted = c2 * eps**2 + c3 * eps**3
    print(f"(b41 - b_exact)/a1 = {error:.5e}, c2 eps^2 + c3 eps^3 = {predicted:.5e}")
    assert error == pytest.approx(predicted, rel=0.01)


# ---------------------------------------------------------------- beyond the paper: mpmath Taylor

SLOPES = [(0.2, 0.1), (0.35, 0.3), (1.7, 0.5), (0.1, 0.1), (0.9, 0.2)]  # (lam, mu)


def _mp_ratios(lam, mu):
    """b/a1 of the exact (35), corrective slip (22) and corrective stick (41) at eta = 0.

    Written out again in mpmath with P1 = R = E* = 1 (the ratios depend on eps = dP/P1 only).
    """
    lam, mu = mpmath.mpf(lam), mpmath.mpf(mu)

    def half_width(P):  # (29)
        return mpmath.sqrt(4 * P / mpmath.pi)

    def multiplier(P):  # (31) with R = E* = 1
        return mpmath.sqrt(half_width(P) / 2)

    def exact(eps):  # (35)
        return mpmath.sqrt(1 + eps * (mu - lam) / (2 * mu))

    def corrective_slip(eps):  # (22), eta = 0
        a1, a2 = half_width(1), half_width(1 + eps)
        A, C = (1 - lam / mu) * multiplier(1 + eps), (1 + lam / mu) * multiplier(1)
        return (A * a2 + C * a1) / (A + C) / a1

    def corrective_stick(eps):  # (41), eta = 0
        a1, a2 = half_width(1), half_width(1 + eps)
        return (a1 - eps / (mpmath.pi * mu * a1) * lam + (a2 - a1) / 2) / a1

    return exact, corrective_slip, corrective_stick


def _mp_discrepancy_coefficients(lam, mu, method):
    """Taylor coefficients in eps of b_method/a1 - b_exact/a1, at 50 digits."""
    with mpmath.workdps(50):
        exact, slip, stick = _mp_ratios(lam, mu)
        chosen = {"slip": slip, "stick": stick}[method]
        return mpmath.taylor(lambda e: chosen(e) - exact(e), 0, 3)


@pytest.mark.parametrize(("lam", "mu"), SLOPES)
def test_corrective_slip_agrees_with_exact_through_second_order(lam, mu):
    coefficients = _mp_discrepancy_coefficients(lam, mu, "slip")
    print(
        f"lam={lam}, mu={mu}: eps^0..2 coefficients {[mpmath.nstr(c, 3) for c in coefficients[:3]]}"
    )
    assert all(abs(c) < mpmath.mpf(10) ** -30 for c in coefficients[:3])


@pytest.mark.parametrize(("lam", "mu"), SLOPES)
def test_corrective_slip_third_order_discrepancy_matches_mpmath(lam, mu):
    reference = float(_mp_discrepancy_coefficients(lam, mu, "slip")[3])
    value = corrective_slip_discrepancy_third_order(lam, mu)
    print(f"lam={lam}, mu={mu}: c3 = {value:.17g}, mpmath {reference:.17g}")
    if reference == 0:  # r = 1: the series of (22) and the exact solution agree to eps^3
        assert abs(value) < 1e-15
    else:
        _close(value, reference)


@pytest.mark.parametrize(("lam", "mu"), SLOPES)
def test_corrective_stick_second_order_discrepancy_matches_mpmath(lam, mu):
    reference = float(_mp_discrepancy_coefficients(lam, mu, "stick")[2])
    value = corrective_stick_discrepancy_second_order(lam, mu)
    print(f"lam={lam}, mu={mu}: c2 = {value:.17g}, mpmath {reference:.17g}")
    _close(value, reference)


@pytest.mark.parametrize(("lam", "mu"), SLOPES)
def test_corrective_stick_third_order_discrepancy_matches_mpmath(lam, mu):
    reference = float(_mp_discrepancy_coefficients(lam, mu, "stick")[3])
    value = corrective_stick_discrepancy_third_order(lam, mu)
    print(f"lam={lam}, mu={mu}: c3 = {value:.17g}, mpmath {reference:.17g}")
    _close(value, reference)


def test_corrective_stick_differs_from_exact_at_second_order_for_fig5():
    coefficients = _mp_discrepancy_coefficients(0.2, 0.1, "stick")
    print(f"eps^0..3 coefficients: {[mpmath.nstr(c, 8) for c in coefficients]}")
    assert abs(coefficients[0]) < 1e-30 and abs(coefficients[1]) < 1e-30
    assert abs(coefficients[2]) > 1e-3  # -1/32 at r = 2
