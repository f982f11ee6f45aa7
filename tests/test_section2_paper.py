"""Section 2: every generated function equals the paper's equation as transcribed by hand.

Inputs are drawn at random over valid, well-conditioned ranges; agreement is to rtol 1e-12.
"""

from __future__ import annotations

import numpy as np
from hypothesis import assume, given, settings

import asymslip_gen as gen
from tests import strategies as s
from tests.transcription import section2 as paper

RTOL = 1e-12
many = settings(max_examples=2000, deadline=None)


def well_conditioned(c: dict[str, float]) -> bool:
    """The denominator of (17)/(22) is not a near-cancellation of larger terms."""
    A = c["L_I2"] * (c["mu"] - c["lam"] - np.pi * c["eta"] * c["a2"] / 4)
    C = c["L_I1"] * (c["mu"] + c["lam"] + np.pi * c["eta"] * c["a1"] / 4)
    return abs(A + C) > 0.05 * (abs(A) + abs(C)) and abs(A) > 1e-3 * abs(C)


@many
@given(s.proportional_cycle(), s.real(-5, 5), s.real(-5, 5))
def test_stick_boundary_is_eq17(c, L_II1, L_II2):
    A1 = c["mu"] * c["L_I1"] + L_II1
    A2 = c["mu"] * c["L_I2"] - L_II2
    assume(abs(A1 + A2) > 0.05 * (abs(A1) + abs(A2)))
    args = (c["mu"], c["a1"], c["a2"], c["L_I1"], c["L_I2"], L_II1, L_II2)
    np.testing.assert_allclose(gen.stick_boundary(*args), paper.eq17(*args), rtol=RTOL)


@many
@given(s.proportional_cycle())
def test_stick_boundary_proportional_is_eq22(c):
    assume(well_conditioned(c))
    args = (c["mu"], c["lam"], c["eta"], c["a1"], c["a2"], c["L_I1"], c["L_I2"])
    np.testing.assert_allclose(gen.stick_boundary_proportional(*args), paper.eq22(*args), rtol=RTOL)


@many
@given(s.proportional_cycle())
def test_eq22_is_eq17_with_calibration_eq21(c):
    L_II1 = paper.eq21(c["lam"], c["eta"], c["a1"], c["L_I1"])
    L_II2 = paper.eq21(c["lam"], c["eta"], c["a2"], c["L_I2"])
    assume(well_conditioned(c))
    from_17 = gen.stick_boundary(c["mu"], c["a1"], c["a2"], c["L_I1"], c["L_I2"], L_II1, L_II2)
    from_22 = gen.stick_boundary_proportional(
        c["mu"], c["lam"], c["eta"], c["a1"], c["a2"], c["L_I1"], c["L_I2"]
    )
    np.testing.assert_allclose(from_17, from_22, rtol=RTOL)


@many
@given(s.proportional_cycle())
def test_slip_zone_width_is_a1_minus_b_by_corrected_eq25(c):
    assume(well_conditioned(c))
    width = gen.slip_zone_width(c["mu"], c["lam"], c["eta"], c["a1"], c["da"], c["L_I1"], c["L_I2"])
    relative = paper.eq25_corrected(
        c["mu"], c["lam"], c["eta"], c["a1"], c["a2"], c["L_I1"], c["L_I2"], da=c["da"]
    )
    np.testing.assert_allclose(width, -c["a1"] * relative, rtol=RTOL)


@many
@given(s.proportional_cycle(), s.real(-5, 5), s.real(-5, 5), s.modulus,
       s.real(0.0, 1.0))
def test_dislocation_density_is_eq15_across_the_slip_zone(c, L_II1, L_II2, E_star, where):
    b = c["a1"] - c["da"]  # a slip zone reaching inside a1, as in Fig. 5
    x = b + where * (c["a2"] - b)
    args = (x, b, c["a1"], c["mu"], c["L_I1"], c["L_I2"], L_II1, L_II2, E_star)
    expected = paper.eq15(*args)
    scale = (abs(c["mu"]) * (c["L_I1"] + c["L_I2"]) + abs(L_II1) + abs(L_II2)) / E_star * np.sqrt(
        c["a2"] - b
    )
    np.testing.assert_allclose(gen.dislocation_density(*args), expected, rtol=RTOL,
                               atol=RTOL * scale)


def test_dislocation_density_vanishes_in_the_stick_zone():
    x = np.linspace(-1.0, 0.9, 50)  # b = 0.9
    density = gen.dislocation_density(x, 0.9, 0.95, 0.3, 1.0, 1.1, 0.5, 0.55, 2.0)
    assert np.all(density == 0.0)


@many
@given(s.half_width, s.real(0.01, 100), s.real(-100, 100), s.real(-10, 10), s.lam,
       s.eta)
def test_edge_multipliers_are_eq19_eq20_eq21(a, dP_da, dQ_da, dsigma_da, lam, eta):
    L_I = gen.normal_edge_multiplier(a, dP_da)
    np.testing.assert_allclose(L_I, paper.eq19(a, dP_da), rtol=RTOL)
    expected_20 = paper.eq20(a, dQ_da, dsigma_da)
    scale = abs(np.sqrt(2 / a) * dQ_da / np.pi) + abs(np.sqrt(2 * a) * dsigma_da / 4)
    np.testing.assert_allclose(gen.shear_edge_multiplier(a, dQ_da, dsigma_da), expected_20,
                               rtol=RTOL, atol=RTOL * scale)
    np.testing.assert_allclose(
        gen.shear_edge_multiplier_proportional(lam, eta, a, L_I),
        paper.eq21(lam, eta, a, L_I),
        rtol=RTOL,
        atol=RTOL * (abs(lam) + abs(np.pi * eta * a / 4)) * L_I,
    )


@many
@given(s.proportional_cycle(), s.real(1e-3, 10), s.real(1e-3, 10), s.real(-1, 1))
def test_validity_measures_are_eq24_to_eq27(c, dP, da_dP, dL_I_dP):
    args25 = (c["mu"], c["lam"], c["eta"], c["a1"], c["da"], c["L_I1"], c["L_I2"])
    assume(well_conditioned(c))
    np.testing.assert_allclose(gen.contact_growth_measure(dP, da_dP, c["a1"]),
                               paper.eq24(dP, da_dP, c["a1"]), rtol=RTOL)
    np.testing.assert_allclose(
        gen.relative_slip_zone_measure(*args25),
        abs(paper.eq25_corrected(c["mu"], c["lam"], c["eta"], c["a1"], c["a2"], c["L_I1"],
                                 c["L_I2"], da=c["da"])),
        rtol=RTOL,
    )
    np.testing.assert_allclose(gen.multiplier_growth_measure(dP, dL_I_dP, c["L_I1"]),
                               abs(paper.eq26(dP, dL_I_dP, c["L_I1"])), rtol=RTOL)
    measure27 = paper.eq27(c["mu"], c["lam"], c["eta"], c["a1"], dP, da_dP)
    np.testing.assert_allclose(
        gen.slip_zone_growth_measure(c["mu"], c["lam"], c["eta"], c["a1"], dP, da_dP),
        measure27, rtol=1e-11, atol=1e-13 * dP * da_dP / c["a1"] * (1 + abs(c["lam"]) / c["mu"]),
    )


@many
@given(s.proportional_cycle(), s.real(1e-6, 10), s.real(1e-6, 1))
def test_first_order_stick_ratio_is_eq28(c, dP, da_dP):
    args = (c["mu"], c["lam"], c["eta"], c["a1"], dP, da_dP)
    # (28) is 1 - X with X a sum of terms that can cancel (lam/mu - 1 near lam = mu): the
    # transcription's rounding error is set by the size of the terms, not of the result.
    terms = dP * da_dP / (2 * c["a1"]) * (
        abs(c["lam"] / c["mu"]) + abs(np.pi * c["a1"] / 4 * c["eta"] / c["mu"]) + 1
    )
    np.testing.assert_allclose(gen.stick_ratio_first_order(*args), paper.eq28(*args), rtol=RTOL,
                               atol=4e-16 * (1 + terms))  # fmt: skip
    width = gen.slip_zone_width_first_order(*args)
    np.testing.assert_allclose(width, c["a1"] * (1 - paper.eq28(*args)), rtol=RTOL,
                               atol=4e-16 * c["a1"] * (1 + terms))  # fmt: skip


def test_eq28_is_the_first_order_limit_of_eq22_for_hertz():
    """Along the Hertz law, (22) approaches (28) with an error of order dP^2."""
    R = E_star = 1.0
    mu, lam = 0.1, 0.2
    P1 = 100.0
    errors = []
    for dP in (1e-1, 1e-2):
        a1, a2 = (np.sqrt(4 * P * R / (np.pi * E_star)) for P in (P1, P1 + dP))
        L_I1, L_I2 = (E_star / R * np.sqrt(a / 2) for a in (a1, a2))
        b = gen.stick_boundary_proportional(mu, lam, 0.0, a1, a2, L_I1, L_I2)
        ratio = gen.stick_ratio_first_order(mu, lam, 0.0, a1, dP, a1 / (2 * P1))
        errors.append(abs(b / a1 - ratio))
    assert errors[0] / errors[1] > 90  # second order: a tenth of dP, a hundredth of the error
