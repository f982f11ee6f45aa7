"""Section 2: every generated function equals the paper's equation as transcribed by hand.

Inputs are drawn over valid, well-conditioned ranges (``tests/sampling.py``: every corner of
the box, then 50,000 random points, evaluated as arrays in one call); agreement is to rtol
1e-12, with an absolute allowance where a formula's terms may cancel (stated per test).
"""

from __future__ import annotations

import numpy as np

import asymslip_gen as gen
from tests.sampling import assert_within, draw, log_uniform, select, uniform
from tests.transcription import section2 as paper

RTOL = 1e-12

# A small-growth proportional cycle: (mu, lam, eta, a1, a2 = a1 + da, L_I1, L_I2).
CYCLE = {
    "mu": log_uniform(0.05, 1.5),
    "lam": uniform(-3.0, 3.0),
    "eta": uniform(-0.05, 0.05),  # [1/length]; pi eta a/4 of order 0.1 for a ~ 1-10
    "a1": log_uniform(0.1, 10.0),
    "relative_growth": log_uniform(1e-8, 0.1),
    "L_I1": log_uniform(0.1, 10.0),
    "multiplier_ratio": uniform(0.9, 1.1),
}


def cycles(**more) -> dict[str, np.ndarray]:
    """Cycles (with ``da``, ``a2``, ``L_I2`` formed) and the further inputs ``more``."""
    c = draw(**CYCLE, **more)
    c["da"] = c["a1"] * c["relative_growth"]
    c["a2"] = c["a1"] + c["da"]
    c["L_I2"] = c["L_I1"] * c["multiplier_ratio"]
    return c


def well_conditioned(c: dict[str, np.ndarray]) -> np.ndarray:
    """The denominator of (17)/(22) is not a near-cancellation of larger terms."""
    A = c["L_I2"] * (c["mu"] - c["lam"] - np.pi * c["eta"] * c["a2"] / 4)
    C = c["L_I1"] * (c["mu"] + c["lam"] + np.pi * c["eta"] * c["a1"] / 4)
    return (abs(A + C) > 0.05 * (abs(A) + abs(C))) & (abs(A) > 1e-3 * abs(C))


def well_conditioned_cycles(**more) -> dict[str, np.ndarray]:
    c = cycles(**more)
    return select(c, well_conditioned(c))


def proportional(c):
    return tuple(c[k] for k in ("mu", "lam", "eta", "a1", "a2", "L_I1", "L_I2"))


def test_stick_boundary_is_eq17():
    c = cycles(L_II1=uniform(-5, 5), L_II2=uniform(-5, 5))
    A1 = c["mu"] * c["L_I1"] + c["L_II1"]
    A2 = c["mu"] * c["L_I2"] - c["L_II2"]
    c = select(c, abs(A1 + A2) > 0.05 * (abs(A1) + abs(A2)))
    args = tuple(c[k] for k in ("mu", "a1", "a2", "L_I1", "L_I2", "L_II1", "L_II2"))
    assert_within(gen.stick_boundary(*args), paper.eq17(*args), rtol=RTOL, inputs=c)


def test_stick_boundary_proportional_is_eq22():
    c = well_conditioned_cycles()
    args = proportional(c)
    assert_within(gen.stick_boundary_proportional(*args), paper.eq22(*args), rtol=RTOL, inputs=c)


def test_eq22_is_eq17_with_calibration_eq21():
    c = well_conditioned_cycles()
    L_II1 = paper.eq21(c["lam"], c["eta"], c["a1"], c["L_I1"])
    L_II2 = paper.eq21(c["lam"], c["eta"], c["a2"], c["L_I2"])
    from_17 = gen.stick_boundary(c["mu"], c["a1"], c["a2"], c["L_I1"], c["L_I2"], L_II1, L_II2)
    from_22 = gen.stick_boundary_proportional(*proportional(c))
    assert_within(from_17, from_22, rtol=RTOL, inputs=c)


def test_slip_zone_width_is_a1_minus_b_by_corrected_eq25():
    c = well_conditioned_cycles()
    width = gen.slip_zone_width(c["mu"], c["lam"], c["eta"], c["a1"], c["da"], c["L_I1"], c["L_I2"])
    relative = paper.eq25_corrected(*proportional(c), da=c["da"])
    assert_within(width, -c["a1"] * relative, rtol=RTOL, inputs=c)


def test_dislocation_density_is_eq15_across_the_slip_zone():
    c = cycles(
        L_II1=uniform(-5, 5),
        L_II2=uniform(-5, 5),
        E_star=log_uniform(0.1, 1e3),
        where=uniform(0.0, 1.0),
    )
    b = c["a1"] - c["da"]  # a slip zone reaching inside a1, as in Fig. 5
    x = b + c["where"] * (c["a2"] - b)
    args = (x, b, c["a1"], c["mu"], c["L_I1"], c["L_I2"], c["L_II1"], c["L_II2"], c["E_star"])
    # (15) is a sum of two square-root terms of either sign: rounding is relative to them.
    scale = (
        (c["mu"] * (c["L_I1"] + c["L_I2"]) + abs(c["L_II1"]) + abs(c["L_II2"]))
        / c["E_star"]
        * np.sqrt(c["a2"] - b)
    )
    assert_within(
        gen.dislocation_density(*args), paper.eq15(*args), rtol=RTOL, atol=RTOL * scale, inputs=c
    )


def test_dislocation_density_vanishes_in_the_stick_zone():
    x = np.linspace(-1.0, 0.9, 50)  # b = 0.9
    density = gen.dislocation_density(x, 0.9, 0.95, 0.3, 1.0, 1.1, 0.5, 0.55, 2.0)
    assert np.all(density == 0.0)


def test_edge_multipliers_are_eq19_eq20_eq21():
    c = draw(
        a=log_uniform(0.1, 10.0),
        dP_da=log_uniform(0.01, 100),
        dQ_da=uniform(-100, 100),
        dsigma_da=uniform(-10, 10),
        lam=uniform(-3.0, 3.0),
        eta=uniform(-0.05, 0.05),
    )
    a = c["a"]
    L_I = gen.normal_edge_multiplier(a, c["dP_da"])
    assert_within(L_I, paper.eq19(a, c["dP_da"]), rtol=RTOL, inputs=c, what="(19)")
    # (20) and (21) are sums of two terms that may cancel: rounding is relative to their size.
    scale_20 = abs(np.sqrt(2 / a) * c["dQ_da"] / np.pi) + abs(np.sqrt(2 * a) * c["dsigma_da"] / 4)
    assert_within(
        gen.shear_edge_multiplier(a, c["dQ_da"], c["dsigma_da"]),
        paper.eq20(a, c["dQ_da"], c["dsigma_da"]),
        rtol=RTOL,
        atol=RTOL * scale_20,
        inputs=c,
        what="(20)",
    )
    scale_21 = (abs(c["lam"]) + abs(np.pi * c["eta"] * a / 4)) * L_I
    assert_within(
        gen.shear_edge_multiplier_proportional(c["lam"], c["eta"], a, L_I),
        paper.eq21(c["lam"], c["eta"], a, L_I),
        rtol=RTOL,
        atol=RTOL * scale_21,
        inputs=c,
        what="(21)",
    )


def test_validity_measures_are_eq24_to_eq27():
    c = well_conditioned_cycles(
        dP=log_uniform(1e-3, 10), da_dP=log_uniform(1e-3, 10), dL_I_dP=uniform(-1, 1)
    )
    mu, lam, eta, a1, dP, da_dP = (c[k] for k in ("mu", "lam", "eta", "a1", "dP", "da_dP"))
    assert_within(
        gen.contact_growth_measure(dP, da_dP, a1),
        paper.eq24(dP, da_dP, a1),
        rtol=RTOL,
        inputs=c,
        what="(24)",
    )
    assert_within(
        gen.relative_slip_zone_measure(mu, lam, eta, a1, c["da"], c["L_I1"], c["L_I2"]),
        abs(paper.eq25_corrected(*proportional(c), da=c["da"])),
        rtol=RTOL,
        inputs=c,
        what="(25)",
    )
    assert_within(
        gen.multiplier_growth_measure(dP, c["dL_I_dP"], c["L_I1"]),
        abs(paper.eq26(dP, c["dL_I_dP"], c["L_I1"])),
        rtol=RTOL,
        inputs=c,
        what="(26)",
    )
    # |1 - lam/mu - pi eta a1/(4 mu)| may cancel: rounding is relative to its terms.
    assert_within(
        gen.slip_zone_growth_measure(mu, lam, eta, a1, dP, da_dP),
        paper.eq27(mu, lam, eta, a1, dP, da_dP),
        rtol=RTOL,
        atol=1e-13 * dP * da_dP / a1 * (1 + abs(lam) / mu),
        inputs=c,
        what="(27)",
    )


def test_first_order_stick_ratio_is_eq28():
    c = cycles(dP=log_uniform(1e-6, 10), da_dP=log_uniform(1e-6, 1))
    args = tuple(c[k] for k in ("mu", "lam", "eta", "a1", "dP", "da_dP"))
    # (28) is 1 - X with X a sum of terms that can cancel (lam/mu - 1 near lam = mu): the
    # transcription's rounding error is set by the size of the terms, not of the result.
    terms = (
        c["dP"]
        * c["da_dP"]
        / (2 * c["a1"])
        * (abs(c["lam"] / c["mu"]) + abs(np.pi * c["a1"] / 4 * c["eta"] / c["mu"]) + 1)
    )
    assert_within(
        gen.stick_ratio_first_order(*args),
        paper.eq28(*args),
        rtol=RTOL,
        atol=4e-16 * (1 + terms),
        inputs=c,
        what="(28)",
    )
    assert_within(
        gen.slip_zone_width_first_order(*args),
        c["a1"] * (1 - paper.eq28(*args)),
        rtol=RTOL,
        atol=4e-16 * c["a1"] * (1 + terms),
        inputs=c,
        what="a1 (1 - (28))",
    )


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
