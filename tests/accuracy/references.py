"""The paper's equations transcribed by hand in mpmath, and the registrations that use them.

Independent of the derivations: nothing here imports SymPy or the derived expressions.  Each
reference is the printed equation (or, where the paper is wrong, the corrected statement of
DESIGN.md) evaluated at the harness's working precision (50 digits) on the exact values of the
doubles the generated function receives.

To check a new generated function, add one ``register_quantity``; to run everything on a new
contact law, add one ``register_law``.  Problem values available to ``args`` (all doubles):

    law parameters (R, E_star for Hertz), mu, lam, eta, P1, dP, P2 (= P1 + dP rounded),
    a1, a2, da (= a2 - a1 from the exact law), L_I1, L_I2 (19), L_II1, L_II2 (21),
    dP_da1 (dP/da at a1), da_dP (a'(P1)), dL_I_dP (L_I'(P1)), dQ_da, dsigma_da (on the path),
    b (17), P_K (33), x_slip (a point of the slip zone b < x < a2), x_contact (a point of
    0 < x < a2, log-uniform in the distance from the edge).
"""

from __future__ import annotations

import mpmath
import numpy as np

from .registry import LawCase, Quantity, register_law, register_quantity

pi = mpmath.pi


def _log_uniform(rng: np.random.Generator, low: float, high: float) -> float:
    return float(10.0 ** rng.uniform(np.log10(low), np.log10(high)))


# ---------------------------------------------------------------------------------------------
# Contact laws
# ---------------------------------------------------------------------------------------------


def hertz_half_width(P, law):
    """(29): a^2 = 4 P R / (pi E*)."""
    return mpmath.sqrt(4 * P * law["R"] / (pi * law["E_star"]))


def hertz_load_slope(a, law):
    """dP/da of (29): P = pi E* a^2 / (4 R)."""
    return pi * law["E_star"] * a / (2 * law["R"])


register_law(
    LawCase(
        name="hertz",
        parameters=lambda rng: {
            "R": _log_uniform(rng, 1e-3, 1e1),
            "E_star": _log_uniform(rng, 1e9, 4e11),
        },
        half_width=hertz_half_width,
        load_slope=hertz_load_slope,
    )
)


# ---------------------------------------------------------------------------------------------
# Section 2: stick boundary, slip zone, dislocation density
# ---------------------------------------------------------------------------------------------


def brackets(mu, lam, eta, a1, a2):
    """The brackets of (22): (1 + lam/mu + pi a1 eta/(4 mu)), (1 - lam/mu - pi a2 eta/(4 mu))."""
    return (1 + lam / mu + pi * a1 / 4 * eta / mu, 1 - lam / mu - pi * a2 / 4 * eta / mu)


def stick_boundary_17(mu, a1, a2, L_I1, L_I2, L_II1, L_II2):
    """(17)."""
    c2, c1 = mu * L_I2 - L_II2, mu * L_I1 + L_II1
    return (c2 * a2 + c1 * a1) / (c2 + c1)


def stick_boundary_22(mu, lam, eta, a1, a2, L_I1, L_I2):
    """(22) (= (50))."""
    first, second = brackets(mu, lam, eta, a1, a2)
    return (second * L_I2 * a2 + first * L_I1 * a1) / (second * L_I2 + first * L_I1)


def slip_zone_width_22(mu, lam, eta, a1, da, L_I1, L_I2):
    """a1 - b of (22) with a2 = a1 + da: 50 digits keep ~38 after the cancellation at 1e-12."""
    return a1 - stick_boundary_22(mu, lam, eta, a1, a1 + da, L_I1, L_I2)


def dislocation_density_15(x, b, a1, mu, L_I1, L_I2, L_II1, L_II2, E_star):
    """(15), with H(x - a1) sqrt(x - a1) taken literally."""
    outer = mpmath.sqrt(x - a1) if x > a1 else 0
    return -2 * mpmath.sqrt(x - b) / E_star * (mu * (L_I1 + L_I2) + L_II1 - L_II2) + (
        2 * (mu * L_I1 + L_II1) / E_star * outer
    )


register_quantity(Quantity(
    "corrective_slip.stick_boundary",
    ("mu", "a1", "a2", "L_I1", "L_I2", "L_II1", "L_II2"),
    stick_boundary_17, ("17",),
))  # fmt: skip
register_quantity(Quantity(
    "corrective_slip.stick_boundary_proportional",
    ("mu", "lam", "eta", "a1", "a2", "L_I1", "L_I2"),
    stick_boundary_22, ("22", "50"),
))  # fmt: skip
register_quantity(Quantity(
    "corrective_slip.slip_zone_width",
    ("mu", "lam", "eta", "a1", "da", "L_I1", "L_I2"),
    slip_zone_width_22, ("22",),
))  # fmt: skip
register_quantity(Quantity(
    "corrective_slip.dislocation_density",
    ("x=x_slip", "b", "a1", "mu", "L_I1", "L_I2", "L_II1", "L_II2", "E_star"),
    dislocation_density_15, ("15",),
))  # fmt: skip


# ---------------------------------------------------------------------------------------------
# Section 2.1: edge multipliers
# ---------------------------------------------------------------------------------------------


def normal_multiplier_19(a, dP_da):
    """(19)."""
    return mpmath.sqrt(2 / a) * dP_da / pi


def shear_multiplier_20(a, dQ_da, dsigma_da):
    """(20)."""
    return mpmath.sqrt(2 / a) * dQ_da / pi + mpmath.sqrt(2 * a) * dsigma_da / 4


def shear_multiplier_21(lam, eta, a, L_I):
    """(21)."""
    return (lam + pi * eta * a / 4) * L_I


register_quantity(Quantity(
    "edge_multipliers.normal_edge_multiplier", ("a=a1", "dP_da=dP_da1"),
    normal_multiplier_19, ("19",),
))  # fmt: skip
register_quantity(Quantity(
    "edge_multipliers.shear_edge_multiplier", ("a=a1", "dQ_da", "dsigma_da"),
    shear_multiplier_20, ("20",),
))  # fmt: skip
register_quantity(Quantity(
    "edge_multipliers.shear_edge_multiplier_proportional", ("lam", "eta", "a=a1", "L_I=L_I1"),
    shear_multiplier_21, ("21",),
))  # fmt: skip


# ---------------------------------------------------------------------------------------------
# Section 2.2: validity measures and first-order forms
# ---------------------------------------------------------------------------------------------


def relative_slip_zone_25(mu, lam, eta, a1, da, L_I1, L_I2):
    """|b - a1| / a1 by the corrected (25): ((a2 - a1)/a1) (1 + C/A)^-1 (see DESIGN.md errata)."""
    first, second = brackets(mu, lam, eta, a1, a1 + da)
    return abs(da / a1 / (1 + first * L_I1 / (second * L_I2)))


def first_order_bracket(mu, lam, eta, a1):
    """(lam/mu + pi a1 eta/(4 mu) - 1), the bracket of (28)."""
    return lam / mu + pi * a1 / 4 * eta / mu - 1


register_quantity(Quantity(
    "validity.contact_growth_measure", ("dP", "da_dP", "a1"),
    lambda dP, da_dP, a1: dP * da_dP / a1, ("24",),
))  # fmt: skip
register_quantity(Quantity(
    "validity.relative_slip_zone_measure", ("mu", "lam", "eta", "a1", "da", "L_I1", "L_I2"),
    relative_slip_zone_25, ("25",),
))  # fmt: skip
register_quantity(Quantity(
    "validity.multiplier_growth_measure", ("dP", "dL_I_dP", "L_I1"),
    lambda dP, dL_I_dP, L_I1: dP * abs(dL_I_dP) / L_I1, ("26",),
))  # fmt: skip
register_quantity(Quantity(
    "validity.slip_zone_growth_measure", ("mu", "lam", "eta", "a1", "dP", "da_dP"),
    lambda mu, lam, eta, a1, dP, da_dP: dP * da_dP / a1
    * abs(first_order_bracket(mu, lam, eta, a1)),
    ("27",),
))  # fmt: skip
register_quantity(Quantity(
    "validity.stick_ratio_first_order", ("mu", "lam", "eta", "a1", "dP", "da_dP"),
    lambda mu, lam, eta, a1, dP, da_dP: 1 - dP * da_dP / (2 * a1) * first_order_bracket(
        mu, lam, eta, a1),
    ("28", "51"),
))  # fmt: skip
register_quantity(Quantity(
    "validity.slip_zone_width_first_order", ("mu", "lam", "eta", "a1", "dP", "da_dP"),
    # a1 (1 - b/a1) with b/a1 from (28).
    lambda mu, lam, eta, a1, dP, da_dP: dP * da_dP / 2 * first_order_bracket(mu, lam, eta, a1),
    ("28",),
))  # fmt: skip


# ---------------------------------------------------------------------------------------------
# Section 3: the Hertz law
# ---------------------------------------------------------------------------------------------


def _hertz(R, E_star):
    return {"R": R, "E_star": E_star}


def hertz_multiplier_31(P, R, E_star):
    """(31): L_I = (E*/R) sqrt(a/2) with a from (29)."""
    return E_star / R * mpmath.sqrt(hertz_half_width(P, _hertz(R, E_star)) / 2)


register_quantity(Quantity(
    "hertz.hertz_load", ("a=a1", "R", "E_star"),
    lambda a, R, E_star: pi * E_star * a**2 / (4 * R), ("29",), laws=("hertz",),
))  # fmt: skip
register_quantity(Quantity(
    "hertz.hertz_load_slope", ("a=a1", "R", "E_star"),
    lambda a, R, E_star: hertz_load_slope(a, _hertz(R, E_star)), ("29",), laws=("hertz",),
))  # fmt: skip
register_quantity(Quantity(
    "hertz.hertz_half_width", ("P=P1", "R", "E_star"),
    lambda P, R, E_star: hertz_half_width(P, _hertz(R, E_star)), ("29",), laws=("hertz",),
))  # fmt: skip
register_quantity(Quantity(
    "hertz.hertz_normal_edge_multiplier", ("P=P1", "R", "E_star"),
    hertz_multiplier_31, ("31",), laws=("hertz",),
))  # fmt: skip
register_quantity(Quantity(
    "hertz.hertz_normal_edge_multiplier_slope", ("P=P1", "R", "E_star"),
    # L_I'(P) = L_I / (4P), Section 3 below (31); differentiated here numerically at 50 digits.
    lambda P, R, E_star: mpmath.diff(lambda p: hertz_multiplier_31(p, R, E_star), P),
    ("31",), laws=("hertz",),
))  # fmt: skip
register_quantity(Quantity(
    "hertz.hertz_half_width_growth", ("P1", "dP", "R", "E_star"),
    lambda P1, dP, R, E_star: hertz_half_width(P1 + dP, _hertz(R, E_star))
    - hertz_half_width(P1, _hertz(R, E_star)),
    ("29", "42"), laws=("hertz",),
))  # fmt: skip


def hertz_slip_zone_width_end_to_end(mu, lam, eta, P1, dP, R, E_star):
    """a1 - b of (22) for Hertz straight from the loads, every intermediate exact."""
    law = _hertz(R, E_star)
    a1, a2 = hertz_half_width(P1, law), hertz_half_width(P1 + dP, law)
    L_I1, L_I2 = hertz_multiplier_31(P1, R, E_star), hertz_multiplier_31(P1 + dP, R, E_star)
    return a1 - stick_boundary_22(mu, lam, eta, a1, a2, L_I1, L_I2)


def generated_hertz_slip_zone_width(mu, lam, eta, P1, dP, R, E_star):
    """The same chain through the generated kernels only (what a caller would write)."""
    from asymslip_gen.corrective_slip import slip_zone_width
    from asymslip_gen.hertz import (
        hertz_half_width as half_width,
    )
    from asymslip_gen.hertz import (
        hertz_half_width_growth as growth,
    )
    from asymslip_gen.hertz import (
        hertz_normal_edge_multiplier as multiplier,
    )

    return slip_zone_width(
        mu, lam, eta, half_width(P1, R, E_star), growth(P1, dP, R, E_star),
        multiplier(P1, R, E_star), multiplier(P1 + dP, R, E_star),
    )  # fmt: skip


register_quantity(Quantity(
    "corrective_slip.slip_zone_width", ("mu", "lam", "eta", "P1", "dP", "R", "E_star"),
    hertz_slip_zone_width_end_to_end, ("22", "29", "31"), laws=("hertz",),
    label="hertz slip_zone_width, end to end from (P1, dP)",
    compose=generated_hertz_slip_zone_width,
))  # fmt: skip


# ---------------------------------------------------------------------------------------------
# Section 3.1-3.3: exact solution, corrective stick, agreement of the methods (Hertz, eta = 0
# where the paper sets it)
# ---------------------------------------------------------------------------------------------


def permanent_stick_load_33(P1, dP, lam, mu):
    """(33) with P2 = P1 + dP and Q2 - Q1 = lam dP."""
    return (P1 + (P1 + dP)) / 2 - lam * dP / (2 * mu)


def exact_stick_boundary_34(P1, dP, lam, mu, R, E_star):
    """b = a(P_K), (29) at (33)."""
    return hertz_half_width(permanent_stick_load_33(P1, dP, lam, mu), _hertz(R, E_star))


def shear_intensity_rate_39(lam, eta, a):
    """(39)."""
    return lam / (pi * mpmath.sqrt(2 * a)) + eta / 4 * mpmath.sqrt(a / 2)


def corrective_stick_width_40(mu, lam, eta, a1, da, L_I1, dP):
    """(40): d1 = dK_II/(mu L_I) - da/2 with dK_II = dP (39) at a1, L_I = L_I1."""
    return dP * shear_intensity_rate_39(lam, eta, a1) / (mu * L_I1) - da / 2


def corrective_stick_boundary_41(P1, dP, lam, eta, mu, R, E_star):
    """(41) with a1 = a(P1), a2 = a(P1 + dP) from (29)."""
    law = _hertz(R, E_star)
    a1, a2 = hertz_half_width(P1, law), hertz_half_width(P1 + dP, law)
    return a1 - dP * R / (pi * mu * E_star * a1) * (lam + pi * eta * a1 / 4) + (a2 - a1) / 2


def _positive_stick_load(values) -> bool:
    return values["P1"] + values["dP"] * (values["mu"] - values["lam"]) / (2 * values["mu"]) > 0


register_quantity(Quantity(
    "exact_solution.permanent_stick_load", ("P1", "dP", "lam", "mu"),
    permanent_stick_load_33, ("33",), laws=("hertz",),
))  # fmt: skip
register_quantity(Quantity(
    "exact_solution.hertz_stick_boundary_exact", ("P1", "dP", "lam", "mu", "R", "E_star"),
    exact_stick_boundary_34, ("33", "34"), laws=("hertz",), where=_positive_stick_load,
))  # fmt: skip
register_quantity(Quantity(
    "exact_solution.hertz_slip_zone_width_exact", ("P1", "dP", "lam", "mu", "R", "E_star"),
    lambda P1, dP, lam, mu, R, E_star: hertz_half_width(P1, _hertz(R, E_star))
    - exact_stick_boundary_34(P1, dP, lam, mu, R, E_star),
    ("34", "35"), laws=("hertz",), where=_positive_stick_load,
))  # fmt: skip
register_quantity(Quantity(
    "corrective_stick.shear_intensity_rate", ("lam", "eta", "a=a1"),
    shear_intensity_rate_39, ("39",),
))  # fmt: skip
register_quantity(Quantity(
    "corrective_stick.corrective_stick_slip_zone_width",
    ("mu", "lam", "eta", "a1", "da", "L_I1", "dP"),
    corrective_stick_width_40, ("40",),
))  # fmt: skip
register_quantity(Quantity(
    "corrective_stick.hertz_stick_boundary_corrective_stick",
    ("P1", "dP", "lam", "eta", "mu", "R", "E_star"),
    corrective_stick_boundary_41, ("41",), laws=("hertz",),
))  # fmt: skip
register_quantity(Quantity(
    "corrective_stick.hertz_slip_zone_width_corrective_stick",
    ("P1", "dP", "lam", "eta", "mu", "R", "E_star"),
    lambda P1, dP, lam, eta, mu, R, E_star: hertz_half_width(P1, _hertz(R, E_star))
    - corrective_stick_boundary_41(P1, dP, lam, eta, mu, R, E_star),
    ("41",), laws=("hertz",),
))  # fmt: skip
register_quantity(Quantity(
    "method_agreement.hertz_slip_zone_width_first_order",
    ("P1", "dP", "lam", "eta", "mu", "R", "E_star"),
    # a1 (1 - b/a1) with b/a1 from (44).
    lambda P1, dP, lam, eta, mu, R, E_star: hertz_half_width(P1, _hertz(R, E_star))
    * (lam / mu + eta / mu * pi * hertz_half_width(P1, _hertz(R, E_star)) / 4 - 1) * dP / (4 * P1),
    ("36", "44", "45"), laws=("hertz",),
))  # fmt: skip


def _series_coefficient(function, order: int, lowest: int) -> mpmath.mpf:
    """Coefficient of eps^order of ``function(eps)`` whose series starts at eps^lowest.

    Fits c_lowest .. c_(lowest+3) (and two more terms) to samples at eps = j h, j = 1..6, at
    raised precision: the truncation error is about h^(6 - (order - lowest)) relative.
    """
    terms = 6
    with mpmath.workdps(mpmath.mp.dps * 4):
        h = mpmath.mpf(10) ** -(mpmath.mp.dps // 6 + 2)
        rows = [[(j * h) ** (lowest + k) for k in range(terms)] for j in range(1, terms + 1)]
        values = [function(j * h) for j in range(1, terms + 1)]
        coefficients = mpmath.lu_solve(mpmath.matrix(rows), mpmath.matrix(values))
        return +coefficients[order - lowest]


def _hertz_discrepancy(boundary: str, lam, mu):
    """eps -> (b_method - b_exact)/a1 for Hertz with eta = 0 and eps = dP/P1 (scale-free)."""

    def discrepancy(eps):
        P1, R, E_star, dP = mpmath.mpf(1), mpmath.mpf(1), mpmath.mpf(1), eps
        law = _hertz(R, E_star)
        a1, a2 = hertz_half_width(P1, law), hertz_half_width(P1 + dP, law)
        if boundary == "22":
            L_I1 = hertz_multiplier_31(P1, R, E_star)
            L_I2 = hertz_multiplier_31(P1 + dP, R, E_star)
            b = stick_boundary_22(mu, lam, 0, a1, a2, L_I1, L_I2)
        else:
            b = corrective_stick_boundary_41(P1, dP, lam, 0, mu, R, E_star)
        return (b - exact_stick_boundary_34(P1, dP, lam, mu, R, E_star)) / a1

    return discrepancy


register_quantity(Quantity(
    "method_agreement.corrective_slip_discrepancy_third_order", ("lam", "mu"),
    lambda lam, mu: _series_coefficient(_hertz_discrepancy("22", lam, mu), 3, 3),
    ("22", "34"), laws=("hertz",), every=3,
))  # fmt: skip
register_quantity(Quantity(
    "method_agreement.corrective_stick_discrepancy_second_order", ("lam", "mu"),
    lambda lam, mu: _series_coefficient(_hertz_discrepancy("41", lam, mu), 2, 2),
    ("41", "34"), laws=("hertz",), every=3,
))  # fmt: skip
register_quantity(Quantity(
    "method_agreement.corrective_stick_discrepancy_third_order", ("lam", "mu"),
    lambda lam, mu: _series_coefficient(_hertz_discrepancy("41", lam, mu), 3, 2),
    ("41", "34"), laws=("hertz",), every=3,
))  # fmt: skip


# ---------------------------------------------------------------------------------------------
# Section 3.4: pressures, the exact (47) and asymptotic (49) traction differences, slip
# ---------------------------------------------------------------------------------------------


def hertz_pressure_48(x, P, R, E_star):
    """(48): p = 2P/(pi a^2) sqrt(a^2 - x^2) inside the contact, zero outside."""
    a = hertz_half_width(P, _hertz(R, E_star))
    return 2 * P / (pi * a**2) * mpmath.sqrt(a**2 - x**2) if abs(x) < a else mpmath.mpf(0)


def exact_traction_difference_47(x, P1, dP, P_K, mu, R, E_star):
    """(47), range by range, with b = a(P_K) and the pressures (48) (the paper's P_k is P_K)."""
    law = _hertz(R, E_star)
    b, a1 = hertz_half_width(P_K, law), hertz_half_width(P1, law)
    p2, p1 = hertz_pressure_48(x, P1 + dP, R, E_star), hertz_pressure_48(x, P1, R, E_star)
    if 0 <= x < b:
        return mu * (p2 + p1 - 2 * hertz_pressure_48(x, P_K, R, E_star))
    if b <= x < a1:
        return mu * (p2 + p1)
    return mu * p2


def traction_difference_49(x, b, a1, a2, mu, L_I1, L_I2, L_II1, L_II2):
    """(49) with B from (15): the dislocation integral by 50-digit principal-value quadrature.

    E* multiplies the integral in (1) and divides B in (15), so it is set to 1 here.
    PV int_b^a2 w(t)/(t - x) dt, w(t) = sqrt(a2 - t) B(t), is the integral of the bounded
    (w(t) - w(x))/(t - x) plus w(x) log((a2 - x)/(x - b)); breakpoints at b, a1, x, a2 put the
    square-root kinks of w on interval ends, where tanh-sinh quadrature keeps full precision.
    """
    E_star = 1

    def weighted(t):
        return mpmath.sqrt(a2 - t) * dislocation_density_15(t, b, a1, mu, L_I1, L_I2, L_II1, L_II2,
                                                            E_star)  # fmt: skip

    if b < x < a2:
        at_pole = weighted(x)
        breaks = sorted({b, a1, x, a2})
        # A node can round onto the pole itself; its weight is negligible at this precision.
        regular = mpmath.quad(
            lambda t: (weighted(t) - at_pole) / (t - x) if t != x else mpmath.mpf(0), breaks
        )
        integral = regular + at_pole * mpmath.log((a2 - x) / (x - b))
    else:
        integral = mpmath.quad(lambda t: weighted(t) / (t - x), sorted({b, a1, a2}))
    edge = L_II2 * mpmath.sqrt(a2 - x) - (L_II1 * mpmath.sqrt(a1 - x) if x < a1 else 0)
    # int_{a2}^{b} = -int_b^{a2}.
    return edge - E_star / (2 * pi * mpmath.sqrt(a2 - x)) * integral


def slip_on_loading_15(x, b, a1, mu, L_I1, L_I2, L_II1, L_II2, E_star):
    """int_b^x of the density (15), by quadrature (zero in the stick zone x <= b)."""
    if x <= b:
        return mpmath.mpf(0)
    breaks = sorted({b, x} | ({a1} if b < a1 < x else set()))
    return mpmath.quad(
        lambda t: dislocation_density_15(t, b, a1, mu, L_I1, L_I2, L_II1, L_II2, E_star), breaks
    )


def _slip_zone_inside_a1(values) -> bool:
    """b <= a1: the slip zone reaches into the load-state-1 contact (the case of Figs. 4-5)."""
    return values["b"] <= values["a1"]


def _stick_zone_inside(values) -> bool:
    """0 < P_K < P1: the permanent stick zone lies inside a1 (lam > mu)."""
    return 0 < values["P_K"] < values["P1"]


register_quantity(Quantity(
    "tractions.hertz_pressure", ("x=x_contact", "P=P2", "R", "E_star"),
    hertz_pressure_48, ("48",), laws=("hertz",),
))  # fmt: skip
register_quantity(Quantity(
    "tractions.hertz_shear_traction_difference",
    ("x=x_contact", "P1", "dP", "P_K", "mu", "R", "E_star"),
    exact_traction_difference_47, ("47", "48"), laws=("hertz",), where=_stick_zone_inside,
))  # fmt: skip
register_quantity(Quantity(
    "tractions.shear_traction_difference",
    ("x=x_contact", "b", "a1", "a2", "mu", "L_I1", "L_I2", "L_II1", "L_II2"),
    traction_difference_49, ("49",), where=_slip_zone_inside_a1, every=4,
))  # fmt: skip
register_quantity(Quantity(
    "slip_displacement.slip_on_loading",
    ("x=x_slip", "b", "a1", "mu", "L_I1", "L_I2", "L_II1", "L_II2", "E_star"),
    slip_on_loading_15, ("15",), where=_slip_zone_inside_a1, every=4,
))  # fmt: skip
