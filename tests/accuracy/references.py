"""The paper's equations transcribed by hand in mpmath, and the registrations that use them.

Independent of the derivations: nothing here imports SymPy or the derived expressions.  Each
reference is the printed equation (or, where the paper is wrong, the corrected statement of
DESIGN.md) evaluated at the harness's working precision (50 digits) on the exact values of the
doubles the generated function receives.

To check a new generated function, add one ``register_quantity``; to run everything on a new
contact law, add one ``register_law``.  Problem values available to ``args`` (all doubles):

    law parameters (R, E_star for Hertz; c, R, E_star for the rounded flat; A, n, E_star and
    K = K(n) for the power law), mu, lam, eta, P1, dP, P2 (= P1 + dP rounded),
    a1, a2, da (= a2 - a1 from the exact law), L_I1, L_I2 (19), L_II1, L_II2 (21),
    dP_da1 (dP/da at a1), da_dP (a'(P1)), d2a_dP2 (a''(P1)), dL_I_dP (L_I'(P1)), dQ_da,
    dsigma_da (on the path), b (17), P_K (33), x_slip (a point of the slip zone b < x < a2),
    x_contact (a point of 0 < x < a2, log-uniform in the distance from the edge), and the cycle
    as a user states it: dP_cycle (= P2 - P1, exact), Q1, dQ, sigma1, dsigma (Q1 + dQ and
    sigma1 + dsigma exact).
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable
from dataclasses import dataclass

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


# --- Beyond the paper: the rounded flat and the power-law punch -------------------------------
#
# The plane-contact relation of a symmetric punch of profile h(x) (h' odd),
#     P(a) = (E*/2) int_{-a}^{a} x h'(x) / sqrt(a^2 - x^2) dx,
# and the pressure by inverting the half-plane contact equation, by quadrature; the published
# rounded-flat law typed by hand.  tests/test_contact_laws.py imports these too.


def flat_slope(t, c, R):
    """h'(t) of the rounded flat: 0 on the flat, (|t| - c)/R beyond, odd in t."""
    return mpmath.sign(t) * max(abs(t) - c, 0) / R


def power_slope(t, A, n):
    """h'(t) of h = A |t|^n."""
    return mpmath.sign(t) * n * A * abs(t) ** (n - 1)


def load_by_quadrature(slope, a, E_star, breaks=()):
    """P(a) = E* a int_0^1 s h'(a s) / sqrt(1 - s^2) ds (the even integrand, x = a s)."""
    a = mpmath.mpf(a)
    nodes = sorted({0, 1, *(mpmath.mpf(b) / a for b in breaks if 0 < b < a)})
    return E_star * a * mpmath.quad(lambda s: s * slope(a * s) / mpmath.sqrt(1 - s * s), nodes)


def load_slope_by_quadrature(slope, curvature, a, E_star, breaks=()):
    """dP/da = E* int_0^1 s (h'(a s) + a s h''(a s)) / sqrt(1 - s^2) ds."""
    a = mpmath.mpf(a)
    nodes = sorted({0, 1, *(mpmath.mpf(b) / a for b in breaks if 0 < b < a)})
    return E_star * mpmath.quad(
        lambda s: s * (slope(a * s) + a * s * curvature(a * s)) / mpmath.sqrt(1 - s * s), nodes
    )


def pressure_by_inversion(slope, a, x, E_star, breaks=()):
    """p(x) = (E*/(2 pi)) sqrt(a^2 - x^2) PV int_{-a}^{a} h'(t) dt / (sqrt(a^2 - t^2) (t - x)).

    The half-plane contact equation inverted bounded at both ends, |x| < a, for a symmetric
    punch (h' odd).  Folding t -> -t gives PV int_0^a 2 t h'(t) / ((t^2 - x^2) sqrt(a^2 - t^2));
    the folded weight itself has PV int_0^a dt / ((t^2 - x^2) sqrt(a^2 - t^2)) = 0 (the PV
    integral of 1/((t - x) sqrt(a^2 - t^2)) over (-a, a) vanishes), so t h'(t) may be replaced
    by t h'(t) - x h'(x), which removes the pole, and t = a sin(theta) removes the end
    singularities.  x and the kinks of h' (``breaks``, either sign) are interval ends.
    """
    a, x = mpmath.mpf(a), abs(mpmath.mpf(x))
    at_x = x * slope(x)

    def integrand(theta):
        t = a * mpmath.sin(theta)
        if t == x:  # a node rounded onto the removed pole; its weight is negligible
            return mpmath.mpf(0)
        return 2 * (t * slope(t) - at_x) / ((t - x) * (t + x))

    kinks = {mpmath.asin(abs(mpmath.mpf(b)) / a) for b in breaks if 0 < abs(b) < a}
    nodes = sorted({mpmath.mpf(0), pi / 2, mpmath.asin(x / a), *kinks})
    return E_star / (2 * pi) * mpmath.sqrt(a * a - x * x) * mpmath.quad(integrand, nodes)


def published_flat_load(a, c, R, E_star):
    """P = E* a^2 (pi - 2 phi0 - sin 2 phi0) / (4R), phi0 = arcsin(c/a) (Ciavarella et al.)."""
    phi0 = mpmath.asin(mpmath.mpf(c) / a)
    return E_star * a**2 * (mpmath.pi - 2 * phi0 - mpmath.sin(2 * phi0)) / (4 * R)


def flat_half_width_mp(P, c, R, E_star):
    """a(P) of the published law by mpmath's root finder (bisection-safe Anderson).

    The root lies in [max(c, a_H), c + a_H], a_H the Hertz half-width of the load (the flat
    carries at most the cylinder's load at the same half-width, at least that of the cylinder
    of half-width a - c); for c = 0 the bracket closes on a_H.  The law loses about
    1.5 log10(a/(a - c)) digits to cancellation as a -> c, so the root is found with 20 digits
    to spare.
    """
    with mpmath.workdps(mpmath.mp.dps + 20):
        P, c, R, E_star = map(mpmath.mpf, (P, c, R, E_star))
        hertz = mpmath.sqrt(4 * P * R / (mpmath.pi * E_star))
        low, high = max(c, hertz), c + hertz
        if low == high:
            return +hertz
        root = mpmath.findroot(
            lambda a: published_flat_load(a, c, R, E_star) - P, (low, high), solver="anderson"
        )
    return +root


def flat_load_slope_mp(a, c, R, E_star, order=1):
    """d^order P/da^order of the published law by mpmath.diff, with 20 digits to spare."""
    with mpmath.workdps(mpmath.mp.dps + 20):
        derivative = mpmath.diff(
            lambda s: published_flat_load(s, c, R, E_star), mpmath.mpf(a), order
        )
    return +derivative


def half_width_by_root(load, P):
    """a(P) of an increasing law ``load`` with P(0) = 0 by mpmath's root finder.

    Brackets the root between powers of two, then Anderson's bracketing method, with 20 digits
    to spare.
    """
    with mpmath.workdps(mpmath.mp.dps + 20):
        P, width = mpmath.mpf(P), mpmath.mpf(1)
        while load(width) < P:
            width *= 2
        while load(width / 2) > P:
            width /= 2
        root = mpmath.findroot(lambda a: load(a) - P, (width / 2, width), solver="anderson")
    return +root


@functools.cache
def _power_shape_factor(n, digits):
    with mpmath.workdps(digits):
        return n * mpmath.quad(lambda theta: mpmath.sin(theta) ** n, [0, pi / 2])


def power_shape_factor(n):
    """K(n) of P = K E* A a^n, by quadrature of the plane-contact relation.

    P(a) = E* a int_0^1 s h'(a s)/sqrt(1 - s^2) ds is homogeneous: for h = A |x|^n it is
    E* A a^n K with K = n int_0^1 s^n/sqrt(1 - s^2) ds = n int_0^(pi/2) sin^n(theta) dtheta
    (s = sin theta removes the end singularity).
    """
    return _power_shape_factor(mpmath.mpf(n), mpmath.mp.dps)


#: Centre of the drawn P1 range [1, 1e6]: the flat half-width c is drawn against the Hertz
#: half-width at this load.
FLAT_REFERENCE_LOAD = 1e3


def _flat_parameters(rng: np.random.Generator) -> dict[str, float]:
    """R, E* as for Hertz; c = 0 (Hertz) one time in ten, else c/a_H(1e3) log-uniform in
    [1e-2, 10], so that over P1 in [1, 1e6] the contact runs from nearly Hertzian
    (c/a1 ~ 3e-4) to nearly flat (1 - c/a1 ~ 4e-4; a - c ~ 0.89 (a_H/c)^(4/3) c)."""
    R, E_star = _log_uniform(rng, 1e-3, 1e1), _log_uniform(rng, 1e9, 4e11)
    hertz = math.sqrt(4 * FLAT_REFERENCE_LOAD * R / (math.pi * E_star))
    c = 0.0 if rng.uniform() < 0.1 else _log_uniform(rng, 1e-2, 1e1) * hertz
    return {"c": c, "R": R, "E_star": E_star}


register_law(
    LawCase(
        name="flat-rounded",
        parameters=_flat_parameters,
        half_width=lambda P, law: flat_half_width_mp(P, law["c"], law["R"], law["E_star"]),
        # d/da of the published law, by hand: E* a arccos(c/a) / R.
        load_slope=lambda a, law: law["E_star"] * a * mpmath.acos(law["c"] / a) / law["R"],
        # The chord sqrt(a^2 - c^2) and corner angle arccos(c/a) at a1, by their definitions.
        extras=lambda a, law: {
            "chord1": mpmath.sqrt(a * a - law["c"] ** 2),
            "angle1": mpmath.acos(law["c"] / a),
        },
    )
)

#: Exponents of the power-law punches: the wedge, non-integers on both sides of n = 3/2
#: (where L_I'(P) changes sign), the cylinder and steeper punches.  n = 3/2 itself is left
#: out: L_I' is exactly zero there, which the kernel returns but a mpmath.diff reference
#: (~1e-50) cannot, so the relative error would be 1 without meaning.
POWER_EXPONENTS = (1.0, 1.25, 1.75, 2.0, 2.5, 3.0, 3.7, 6.0)


def _power_parameters(rng: np.random.Generator) -> dict[str, float]:
    """n from POWER_EXPONENTS, A log-uniform in [1e-3, 1e2], E* as for Hertz, and K(n) (the
    generated kernels take it as an argument) from the quadrature, rounded once."""
    n = float(rng.choice(POWER_EXPONENTS))
    A, E_star = _log_uniform(rng, 1e-3, 1e2), _log_uniform(rng, 1e9, 4e11)
    with mpmath.workdps(50):
        K = float(power_shape_factor(n))
    return {"A": A, "n": n, "E_star": E_star, "K": K}


def power_law_half_width_mp(P, law):
    """a(P) of P = K E* A a^n, with the K the kernels receive, inverted by hand."""
    return (P / (law["K"] * law["E_star"] * law["A"])) ** (1 / law["n"])


def power_law_load_slope_mp(a, law):
    """dP/da of P = K E* A a^n, by hand."""
    return law["n"] * law["K"] * law["E_star"] * law["A"] * a ** (law["n"] - 1)


register_law(
    LawCase(
        name="power",
        parameters=_power_parameters,
        half_width=power_law_half_width_mp,
        load_slope=power_law_load_slope_mp,
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


def stick_boundary_denominator_17(mu, lam, eta, a1, a2, L_I1, L_I2):
    """mu (L_I1 + L_I2) + L_II1 - L_II2 of (17) with L_II from (21), as printed."""
    L_II1 = (lam + mpmath.pi * eta * a1 / 4) * L_I1
    L_II2 = (lam + mpmath.pi * eta * a2 / 4) * L_I2
    return mu * (L_I1 + L_I2) + L_II1 - L_II2


def slip_zone_width_22(mu, lam, eta, a1, da, L_I1, L_I2):
    """a1 - b of (22) with a2 = a1 + da: 50 digits keep ~38 after the cancellation at 1e-12."""
    return a1 - stick_boundary_22(mu, lam, eta, a1, a1 + da, L_I1, L_I2)


def dislocation_density_15(x, b, a1, mu, L_I1, L_I2, L_II1, L_II2, E_star):
    """(15), with H(x - a1) sqrt(x - a1) taken literally."""
    outer = mpmath.sqrt(x - a1) if x > a1 else 0
    return -2 * mpmath.sqrt(x - b) / E_star * (mu * (L_I1 + L_I2) + L_II1 - L_II2) + (
        2 * (mu * L_I1 + L_II1) / E_star * outer
    )


register_quantity(
    Quantity(
        "corrective_slip.stick_boundary",
        ("mu", "a1", "a2", "L_I1", "L_I2", "L_II1", "L_II2"),
        stick_boundary_17,
        ("17",),
    )
)
register_quantity(
    Quantity(
        "corrective_slip.stick_boundary_proportional",
        ("mu", "lam", "eta", "a1", "a2", "L_I1", "L_I2"),
        stick_boundary_22,
        ("22", "50"),
    )
)
register_quantity(
    Quantity(
        "corrective_slip.stick_boundary_denominator",
        ("mu", "lam", "eta", "a1", "a2", "L_I1", "L_I2"),
        stick_boundary_denominator_17,
        ("17", "21"),
    )
)


def width_17(mu, da, L_I1, L_I2, L_II1, L_II2):
    """a1 - b of (17) as printed, with a2 = a1 + da (exact at 50 digits)."""
    a1 = mpmath.mpf(1)  # (17) is translation-invariant: any a1
    a2 = a1 + da
    c1, c2 = mu * L_I1 + L_II1, mu * L_I2 - L_II2
    return a1 - (c2 * a2 + c1 * a1) / (c2 + c1)


register_quantity(
    Quantity(
        "corrective_slip.slip_zone_width_from_multipliers",
        ("mu", "da", "L_I1", "L_I2", "L_II1", "L_II2"),
        width_17,
        ("17",),
    )
)
register_quantity(
    Quantity(
        "corrective_slip.stick_boundary_denominator_from_multipliers",
        ("mu", "L_I1", "L_I2", "L_II1", "L_II2"),
        lambda mu, L_I1, L_I2, L_II1, L_II2: mu * (L_I1 + L_I2) + L_II1 - L_II2,
        ("17",),
    )
)
register_quantity(
    Quantity(
        "corrective_slip.slip_zone_width",
        ("mu", "lam", "eta", "a1", "da", "L_I1", "L_I2"),
        slip_zone_width_22,
        ("22",),
    )
)
register_quantity(
    Quantity(
        "corrective_slip.dislocation_density",
        ("x=x_slip", "b", "a1", "mu", "L_I1", "L_I2", "L_II1", "L_II2", "E_star"),
        dislocation_density_15,
        ("15",),
    )
)


# ---------------------------------------------------------------------------------------------
# Section 2.1: edge multipliers
# ---------------------------------------------------------------------------------------------


def normal_multiplier_19(a, dP_da):
    """(19): L_I = (1/pi) sqrt(2/a) dP/da."""
    return mpmath.sqrt(2 / mpmath.mpf(a)) * dP_da / pi


def shear_multiplier_20(a, dQ_da, dsigma_da):
    """(20)."""
    return mpmath.sqrt(2 / a) * dQ_da / pi + mpmath.sqrt(2 * a) * dsigma_da / 4


def shear_multiplier_21(lam, eta, a, L_I):
    """(21)."""
    return (lam + pi * eta * a / 4) * L_I


register_quantity(
    Quantity(
        "edge_multipliers.normal_edge_multiplier",
        ("a=a1", "dP_da=dP_da1"),
        normal_multiplier_19,
        ("19",),
    )
)
register_quantity(
    Quantity(
        "edge_multipliers.shear_edge_multiplier",
        ("a=a1", "dQ_da", "dsigma_da"),
        shear_multiplier_20,
        ("20",),
    )
)
register_quantity(
    Quantity(
        "edge_multipliers.shear_edge_multiplier_proportional",
        ("lam", "eta", "a=a1", "L_I=L_I1"),
        shear_multiplier_21,
        ("21",),
    )
)


# Beyond the paper: the edges of an asymmetric contact (derivations/asymmetric_edge_multipliers.py)
# as transcribed from its statements AS1-AS6.  The problem's values stand in for w and the
# slopes: the formulas are arithmetic, any positive width and slopes exercise them.
def shear_multiplier_asymmetric(lam, eta, w, da_dP):
    """AS3: L_II = 2 (lam + pi eta w/8) / (pi sqrt(w) a'(P))."""
    return 2 * (lam + pi * eta * w / 8) / (pi * mpmath.sqrt(w) * da_dP)


def normal_multiplier_asymmetric(w, dP_da, dMc_da):
    """AS1: L_I = (2/(pi sqrt w)) (dP/da + (4/w) dM_c/da)."""
    return 2 / (pi * mpmath.sqrt(w)) * (dP_da + 4 * dMc_da / w)


register_quantity(
    Quantity(
        "asymmetric_edges.shear_edge_multiplier_asymmetric",
        ("lam", "eta", "w=a1", "da_dP"),
        shear_multiplier_asymmetric,
        ("20", "21"),
    )
)
register_quantity(
    Quantity(
        "asymmetric_edges.normal_edge_multiplier_asymmetric",
        ("w=a2", "dP_da=dP_da1", "dMc_da=dP_da1"),
        normal_multiplier_asymmetric,
        ("19",),
    )
)
register_quantity(
    Quantity(
        "asymmetric_edges.edge_moment_factor",
        ("w=a1", "L_I=L_I1", "da_dP"),
        lambda w, L_I, da_dP: pi * mpmath.sqrt(w) * L_I * da_dP / 2,
        ("19", "21"),
    )
)
register_quantity(
    Quantity(
        "asymmetric_edges.edge_multiplier_balance",
        ("w=a2", "L_I_right=L_I1", "da_dP_right=da_dP", "L_I_left=L_I2", "da_dP_left=da_dP"),
        lambda w, L_I_right, da_dP_right, L_I_left, da_dP_left: pi
        * mpmath.sqrt(w)
        / 4
        * (L_I_right * da_dP_right + L_I_left * da_dP_left),
        ("19",),
    )
)


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


register_quantity(
    Quantity(
        "validity.contact_growth_measure",
        ("dP", "da_dP", "a1"),
        lambda dP, da_dP, a1: dP * da_dP / a1,
        ("24",),
    )
)
register_quantity(
    Quantity(
        "validity.relative_slip_zone_measure",
        ("mu", "lam", "eta", "a1", "da", "L_I1", "L_I2"),
        relative_slip_zone_25,
        ("25",),
    )
)
register_quantity(
    Quantity(
        "validity.multiplier_growth_measure",
        ("dP", "dL_I_dP", "L_I1"),
        lambda dP, dL_I_dP, L_I1: dP * abs(dL_I_dP) / L_I1,
        ("26",),
    )
)
register_quantity(
    Quantity(
        "validity.slip_zone_growth_measure",
        ("mu", "lam", "eta", "a1", "dP", "da_dP"),
        lambda mu, lam, eta, a1, dP, da_dP: dP
        * da_dP
        / a1
        * abs(first_order_bracket(mu, lam, eta, a1)),
        ("27",),
    )
)
register_quantity(
    Quantity(
        "validity.stick_ratio_first_order",
        ("mu", "lam", "eta", "a1", "dP", "da_dP"),
        lambda mu, lam, eta, a1, dP, da_dP: 1
        - dP * da_dP / (2 * a1) * first_order_bracket(mu, lam, eta, a1),
        ("28", "51"),
    )
)
register_quantity(
    Quantity(
        "validity.stick_ratio_first_order_from_multipliers",
        ("mu", "L_I1", "L_II1", "a1", "dP", "da_dP"),
        # The first-order term of (17): (28) with lam + pi eta a1/4 -> L_II1/L_I1.
        lambda mu, L_I1, L_II1, a1, dP, da_dP: 1
        - dP * da_dP / (2 * a1) * (L_II1 / (mu * L_I1) - 1),
        ("17", "28"),
    )
)
register_quantity(
    Quantity(
        "validity.slip_zone_growth_measure_from_multipliers",
        ("mu", "L_I1", "L_II1", "a1", "dP", "da_dP"),
        lambda mu, L_I1, L_II1, a1, dP, da_dP: dP * da_dP / a1 * abs(1 - L_II1 / (mu * L_I1)),
        ("17", "27"),
    )
)
register_quantity(
    Quantity(
        "validity.slip_zone_width_first_order",
        ("mu", "lam", "eta", "a1", "dP", "da_dP"),
        # a1 (1 - b/a1) with b/a1 from (28).
        lambda mu, lam, eta, a1, dP, da_dP: dP * da_dP / 2 * first_order_bracket(mu, lam, eta, a1),
        ("28",),
    )
)


# ---------------------------------------------------------------------------------------------
# Section 3: the Hertz law
# ---------------------------------------------------------------------------------------------


def _hertz(R, E_star):
    return {"R": R, "E_star": E_star}


def hertz_multiplier_31(P, R, E_star):
    """(31): L_I = (E*/R) sqrt(a/2) with a from (29)."""
    return E_star / R * mpmath.sqrt(hertz_half_width(P, _hertz(R, E_star)) / 2)


register_quantity(
    Quantity(
        "hertz.hertz_load",
        ("a=a1", "R", "E_star"),
        lambda a, R, E_star: pi * E_star * a**2 / (4 * R),
        ("29",),
        laws=("hertz",),
    )
)
register_quantity(
    Quantity(
        "hertz.hertz_load_slope",
        ("a=a1", "R", "E_star"),
        lambda a, R, E_star: hertz_load_slope(a, _hertz(R, E_star)),
        ("29",),
        laws=("hertz",),
    )
)
register_quantity(
    Quantity(
        "hertz.hertz_half_width",
        ("P=P1", "R", "E_star"),
        lambda P, R, E_star: hertz_half_width(P, _hertz(R, E_star)),
        ("29",),
        laws=("hertz",),
    )
)
register_quantity(
    Quantity(
        "hertz.hertz_normal_edge_multiplier",
        ("P=P1", "R", "E_star"),
        hertz_multiplier_31,
        ("31",),
        laws=("hertz",),
    )
)
register_quantity(
    Quantity(
        "hertz.hertz_normal_edge_multiplier_slope",
        ("P=P1", "R", "E_star"),
        # L_I'(P) = L_I / (4P), Section 3 below (31); differentiated here numerically at 50 digits.
        lambda P, R, E_star: mpmath.diff(lambda p: hertz_multiplier_31(p, R, E_star), P),
        ("31",),
        laws=("hertz",),
    )
)
register_quantity(
    Quantity(
        "hertz.hertz_half_width_growth",
        ("P1", "dP", "R", "E_star"),
        lambda P1, dP, R, E_star: hertz_half_width(P1 + dP, _hertz(R, E_star))
        - hertz_half_width(P1, _hertz(R, E_star)),
        ("29", "42"),
        laws=("hertz",),
    )
)


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
        mu,
        lam,
        eta,
        half_width(P1, R, E_star),
        growth(P1, dP, R, E_star),
        multiplier(P1, R, E_star),
        multiplier(P1 + dP, R, E_star),
    )


register_quantity(
    Quantity(
        "corrective_slip.slip_zone_width",
        ("mu", "lam", "eta", "P1", "dP", "R", "E_star"),
        hertz_slip_zone_width_end_to_end,
        ("22", "29", "31"),
        laws=("hertz",),
        label="hertz slip_zone_width, end to end from (P1, dP)",
        compose=generated_hertz_slip_zone_width,
    )
)


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


register_quantity(
    Quantity(
        "exact_solution.permanent_stick_load",
        ("P1", "dP", "lam", "mu"),
        permanent_stick_load_33,
        ("33",),
        laws=("hertz",),
    )
)
register_quantity(
    Quantity(
        "exact_solution.hertz_stick_boundary_exact",
        ("P1", "dP", "lam", "mu", "R", "E_star"),
        exact_stick_boundary_34,
        ("33", "34"),
        laws=("hertz",),
        where=_positive_stick_load,
    )
)
register_quantity(
    Quantity(
        "exact_solution.hertz_slip_zone_width_exact",
        ("P1", "dP", "lam", "mu", "R", "E_star"),
        lambda P1, dP, lam, mu, R, E_star: hertz_half_width(P1, _hertz(R, E_star))
        - exact_stick_boundary_34(P1, dP, lam, mu, R, E_star),
        ("34", "35"),
        laws=("hertz",),
        where=_positive_stick_load,
    )
)
register_quantity(
    Quantity(
        "corrective_stick.shear_intensity_rate",
        ("lam", "eta", "a=a1"),
        shear_intensity_rate_39,
        ("39",),
    )
)
register_quantity(
    Quantity(
        "corrective_stick.corrective_stick_slip_zone_width",
        ("mu", "lam", "eta", "a1", "da", "L_I1", "dP"),
        corrective_stick_width_40,
        ("40",),
    )
)
register_quantity(
    Quantity(
        "corrective_stick.hertz_stick_boundary_corrective_stick",
        ("P1", "dP", "lam", "eta", "mu", "R", "E_star"),
        corrective_stick_boundary_41,
        ("41",),
        laws=("hertz",),
    )
)
register_quantity(
    Quantity(
        "corrective_stick.hertz_slip_zone_width_corrective_stick",
        ("P1", "dP", "lam", "eta", "mu", "R", "E_star"),
        lambda P1, dP, lam, eta, mu, R, E_star: hertz_half_width(P1, _hertz(R, E_star))
        - corrective_stick_boundary_41(P1, dP, lam, eta, mu, R, E_star),
        ("41",),
        laws=("hertz",),
    )
)
register_quantity(
    Quantity(
        "method_agreement.hertz_slip_zone_width_first_order",
        ("P1", "dP", "lam", "eta", "mu", "R", "E_star"),
        # a1 (1 - b/a1) with b/a1 from (44).
        lambda P1, dP, lam, eta, mu, R, E_star: hertz_half_width(P1, _hertz(R, E_star))
        * (lam / mu + eta / mu * pi * hertz_half_width(P1, _hertz(R, E_star)) / 4 - 1)
        * dP
        / (4 * P1),
        ("36", "44", "45"),
        laws=("hertz",),
    )
)


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


register_quantity(
    Quantity(
        "method_agreement.corrective_slip_discrepancy_third_order",
        ("lam", "mu"),
        lambda lam, mu: _series_coefficient(_hertz_discrepancy("22", lam, mu), 3, 3),
        ("22", "34"),
        laws=("hertz",),
        every=3,
    )
)
register_quantity(
    Quantity(
        "method_agreement.corrective_stick_discrepancy_second_order",
        ("lam", "mu"),
        lambda lam, mu: _series_coefficient(_hertz_discrepancy("41", lam, mu), 2, 2),
        ("41", "34"),
        laws=("hertz",),
        every=3,
    )
)
register_quantity(
    Quantity(
        "method_agreement.corrective_stick_discrepancy_third_order",
        ("lam", "mu"),
        lambda lam, mu: _series_coefficient(_hertz_discrepancy("41", lam, mu), 3, 2),
        ("41", "34"),
        laws=("hertz",),
        every=3,
    )
)


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
        return mpmath.sqrt(a2 - t) * dislocation_density_15(
            t, b, a1, mu, L_I1, L_I2, L_II1, L_II2, E_star
        )

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


register_quantity(
    Quantity(
        "tractions.hertz_pressure",
        ("x=x_contact", "P=P2", "R", "E_star"),
        hertz_pressure_48,
        ("48",),
        laws=("hertz",),
    )
)
register_quantity(
    Quantity(
        "tractions.hertz_shear_traction_difference",
        ("x=x_contact", "P1", "dP", "P_K", "mu", "R", "E_star"),
        exact_traction_difference_47,
        ("47", "48"),
        laws=("hertz",),
        where=_stick_zone_inside,
    )
)


def multiplier_slope_along_loglog_fit(P, L_I, ds, d2s):
    """dL_I/dP by numerical differentiation of (19), with a(P) the local quadratic in log-log
    through (log P, log a) of slope ds and curvature d2s; log a is fixed by L_I itself."""
    u0 = mpmath.log(P)
    # (19) at u0: L_I = (1/pi) sqrt(2/a) P/(a s'), so a^(3/2) = sqrt(2) P/(pi L_I s').
    s0 = mpmath.log((mpmath.sqrt(2) * P / (pi * L_I * ds)) ** (mpmath.mpf(2) / 3))

    def multiplier(u):
        s = s0 + ds * (u - u0) + d2s * (u - u0) ** 2 / 2
        slope = ds + d2s * (u - u0)
        a, load = mpmath.exp(s), mpmath.exp(u)
        return mpmath.sqrt(2 / a) * load / (a * slope) / pi  # (19) with dP/da = P/(a s')

    return mpmath.diff(multiplier, u0) / P


register_quantity(
    Quantity(
        "table_law.normal_edge_multiplier_slope_loglog",
        ("P=P1", "L_I=L_I1", "ds=log_slope1", "d2s=log_curvature1"),
        multiplier_slope_along_loglog_fit,
        ("19", "26"),
    )
)


def jaeger_ciavarella_47(p2, p1, p_K, mu):
    """(47) in the three pressures, as the paper's piecewise form reads in every range."""
    return mu * (p2 + p1 - 2 * p_K)


# The general (47) is arithmetic on three pressures: any positive values exercise it, so the
# problem's own positive quantities stand in for them.
register_quantity(
    Quantity(
        "tractions.jaeger_ciavarella_traction_difference",
        ("p2=L_I2", "p1=L_I1", "p_K=a1", "mu"),
        jaeger_ciavarella_47,
        ("47",),
    )
)
register_quantity(
    Quantity(
        "tractions.shear_traction_difference",
        ("x=x_contact", "b", "a1", "a2", "mu", "L_I1", "L_I2", "L_II1", "L_II2"),
        traction_difference_49,
        ("49",),
        where=_slip_zone_inside_a1,
        every=4,
    )
)
register_quantity(
    Quantity(
        "slip_displacement.slip_on_loading",
        ("x=x_slip", "b", "a1", "mu", "L_I1", "L_I2", "L_II1", "L_II2", "E_star"),
        slip_on_loading_15,
        ("15",),
        where=_slip_zone_inside_a1,
        every=4,
    )
)


# ---------------------------------------------------------------------------------------------
# Beyond the paper: the rounded-flat punch (its law in place of (29), L_I by (19), p in place
# of (48)), against the published law, mpmath.diff and the inversion by quadrature
# ---------------------------------------------------------------------------------------------


def flat_multiplier_slope_mp(a, c, R, E_star):
    """dL_I/dP at half-width a: (dL_I/da) / (dP/da), with L_I(a) = (19) differentiated by the
    product rule, dL_I/da = sqrt(2/a) (P'' - P'/(2a)) / pi, and P', P'' by mpmath.diff."""
    first = flat_load_slope_mp(a, c, R, E_star)
    second = flat_load_slope_mp(a, c, R, E_star, order=2)
    return mpmath.sqrt(2 / a) * (second - first / (2 * a)) / (pi * first)


_FLAT = ("a=a1", "c", "R", "E_star")

register_quantity(
    Quantity(
        "flat_rounded.flat_rounded_load",
        _FLAT,
        published_flat_load,
        ("29",),
        laws=("flat-rounded",),
    )
)
register_quantity(
    Quantity(
        "flat_rounded.flat_rounded_load_slope",
        _FLAT,
        flat_load_slope_mp,
        ("29",),
        laws=("flat-rounded",),
    )
)
register_quantity(
    Quantity(
        "flat_rounded.flat_rounded_normal_edge_multiplier",
        _FLAT,
        lambda a, c, R, E_star: normal_multiplier_19(a, flat_load_slope_mp(a, c, R, E_star)),
        ("19",),
        laws=("flat-rounded",),
    )
)
register_quantity(
    Quantity(
        "flat_rounded.flat_rounded_normal_edge_multiplier_slope",
        _FLAT,
        flat_multiplier_slope_mp,
        ("19", "26"),
        laws=("flat-rounded",),
    )
)
# The same quantities from the chord and corner angle passed in: the references do not use
# them (they recompute everything from a), so a wrong chord or angle kernel, or a wrong use of
# them, shows up as a difference.
_AT_ANGLE = ("a=a1", "c", "R", "E_star", "psi=angle1")
register_quantity(
    Quantity(
        "flat_rounded.flat_rounded_chord",
        ("a=a1", "c"),
        lambda a, c: mpmath.sqrt(a * a - c * c),
        ("29",),
        laws=("flat-rounded",),
    )
)
register_quantity(
    Quantity(
        "flat_rounded.flat_rounded_corner_angle",
        ("D=chord1", "c"),
        lambda D, c: mpmath.atan2(D, c),
        ("29",),
        laws=("flat-rounded",),
    )
)
register_quantity(
    Quantity(
        "flat_rounded.flat_rounded_load_at_angle",
        (*_AT_ANGLE, "D=chord1"),
        lambda a, c, R, E_star, psi, D: published_flat_load(a, c, R, E_star),
        ("29",),
        laws=("flat-rounded",),
    )
)
register_quantity(
    Quantity(
        "flat_rounded.flat_rounded_load_slope_at_angle",
        _AT_ANGLE,
        lambda a, c, R, E_star, psi: flat_load_slope_mp(a, c, R, E_star),
        ("29",),
        laws=("flat-rounded",),
    )
)
register_quantity(
    Quantity(
        "flat_rounded.flat_rounded_normal_edge_multiplier_at_angle",
        _AT_ANGLE,
        lambda a, c, R, E_star, psi: normal_multiplier_19(a, flat_load_slope_mp(a, c, R, E_star)),
        ("19",),
        laws=("flat-rounded",),
    )
)
register_quantity(
    Quantity(
        "flat_rounded.flat_rounded_normal_edge_multiplier_slope_at_angle",
        (*_AT_ANGLE, "D=chord1"),
        lambda a, c, R, E_star, psi, D: flat_multiplier_slope_mp(a, c, R, E_star),
        ("19", "26"),
        laws=("flat-rounded",),
    )
)
register_quantity(
    Quantity(
        "flat_rounded.flat_rounded_pressure",
        ("x=x_contact", "a=a2", "c", "R", "E_star"),
        lambda x, a, c, R, E_star: pressure_by_inversion(
            lambda t: flat_slope(t, c, R), a, x, E_star, breaks=(c,)
        ),
        ("4", "48"),
        laws=("flat-rounded",),
        every=4,
        costly=True,
    )
)


# ---------------------------------------------------------------------------------------------
# Beyond the paper: the power-law punch h = A |x|^n.  K is an argument of the kernels; the
# harness feeds K(n) from the quadrature (power_shape_factor), so P = K E* A a^n below is the
# plane-contact relation.  Inverse and derivatives by root finding and mpmath.diff; the
# pressure by the inversion quadrature (independent of K and of the 2F1 form)
# ---------------------------------------------------------------------------------------------


def _power_load(n, A, E_star, K):
    return lambda a: K * E_star * A * a**n


def power_half_width_mp(P, n, A, E_star, K):
    return half_width_by_root(_power_load(n, A, E_star, K), P)


def power_multiplier_mp(P, n, A, E_star, K):
    """(19) at a = a(P), dP/da by mpmath.diff."""
    a = power_half_width_mp(P, n, A, E_star, K)
    return normal_multiplier_19(a, mpmath.diff(_power_load(n, A, E_star, K), a))


def power_multiplier_slope_mp(P, n, A, E_star, K):
    """dL_I/dP = sqrt(2/a) (P'' - P'/(2a)) / (pi P') at a = a(P) ((19), product rule)."""
    load = _power_load(n, A, E_star, K)
    a = power_half_width_mp(P, n, A, E_star, K)
    first, second = mpmath.diff(load, a), mpmath.diff(load, a, 2)
    return mpmath.sqrt(2 / a) * (second - first / (2 * a)) / (pi * first)


def wedge_pressure_published(x, a, A, E_star):
    """p = (E* A/pi) arccosh(a/|x|) under a wedge of slope A (Johnson, Contact Mechanics, 5.8)."""
    return E_star * A / pi * mpmath.acosh(a / abs(x))


def power_pressure_with_exact_2f1(x, a, n, A, E_star, K):
    """power_law_pressure fed the 2F1 factor at z = 1 - x^2/a^2 correctly rounded (mpmath).

    Isolates the kernel from the 2F1 implementation (SciPy's at run time).
    """
    from asymslip_gen.power_law import power_law_pressure

    with mpmath.workdps(40):
        factor = [
            float(mpmath.hyp2f1(1 - mpmath.mpf(n_) / 2, 1, 1.5, 1 - (mpmath.mpf(x_) / a_) ** 2))
            for x_, a_, n_ in zip(*np.broadcast_arrays(x, a, n), strict=True)
        ]
    return power_law_pressure(x, a, n, A, E_star, K, np.array(factor))


_POWER = ("n", "A", "E_star", "K")

register_quantity(
    Quantity(
        "power_law.power_law_load",
        ("a=a1", *_POWER),
        lambda a, n, A, E_star, K: _power_load(n, A, E_star, K)(a),
        ("29",),
        laws=("power",),
    )
)
register_quantity(
    Quantity(
        "power_law.power_law_load_slope",
        ("a=a1", *_POWER),
        lambda a, n, A, E_star, K: mpmath.diff(_power_load(n, A, E_star, K), a),
        ("29",),
        laws=("power",),
    )
)
register_quantity(
    Quantity(
        "power_law.power_law_half_width",
        ("P=P1", *_POWER),
        power_half_width_mp,
        ("29",),
        laws=("power",),
    )
)
register_quantity(
    Quantity(
        "power_law.power_law_half_width_growth",
        ("P1", "dP", *_POWER),
        lambda P1, dP, n, A, E_star, K: power_half_width_mp(P1 + dP, n, A, E_star, K)
        - power_half_width_mp(P1, n, A, E_star, K),
        ("23", "42"),
        laws=("power",),
    )
)
register_quantity(
    Quantity(
        "power_law.power_law_normal_edge_multiplier",
        ("P=P1", *_POWER),
        power_multiplier_mp,
        ("19",),
        laws=("power",),
    )
)
register_quantity(
    Quantity(
        "power_law.power_law_normal_edge_multiplier_slope",
        ("P=P1", *_POWER),
        power_multiplier_slope_mp,
        ("19", "26"),
        laws=("power",),
    )
)
register_quantity(
    Quantity(
        "power_law.power_law_hypergeometric_argument",
        ("x=x_contact", "a=a2"),
        lambda x, a: max(mpmath.mpf(0), 1 - (x / a) ** 2),
        ("48",),
        laws=("power",),
    )
)
register_quantity(
    Quantity(
        "power_law.power_law_pressure",
        ("x=x_contact", "a=a2", *_POWER),
        lambda x, a, n, A, E_star, K: pressure_by_inversion(
            lambda t: power_slope(t, A, n), a, x, E_star, breaks=(0,)
        ),
        ("4", "48"),
        laws=("power",),
        every=4,
        costly=True,
        compose=power_pressure_with_exact_2f1,
    )
)
register_quantity(
    Quantity(
        "power_law.wedge_pressure",
        ("x=x_contact", "a=a2", "A", "E_star"),
        wedge_pressure_published,
        ("4", "48"),
        laws=("power",),
        where=lambda values: values["n"] == 1.0,
    )
)


# ---------------------------------------------------------------------------------------------
# Beyond the paper: b(22) - a(P_K) = C dP^2 + O(dP^3) for a generic law (eta = 0).  The
# reference evaluates (22) and (33)-(34) on the local law a(P1 + h) = a1 + a' h + a'' h^2 / 2
# (C involves nothing beyond a''), L_I from (19), and takes the second difference at tiny dP.
# ---------------------------------------------------------------------------------------------


def _gap_coefficient(mu, lam, a1, da_dP, d2a_dP2, multiplier):
    """C = (g(h) + g(-h)) / (2 h^2) + O(h^2), g(dP) = b(22) - a(P_K).

    The odd terms (a first-order disagreement included) cancel in the sum; with
    h = 1e-(digits/2) a1/a' the dP^4 term is below 1e-digits relative.  g is a difference of
    two half-widths that agree to O(h), so it is evaluated with 2 digits + 20.
    """
    digits = mpmath.mp.dps
    with mpmath.workdps(2 * digits + 20):
        step = mpmath.mpf(10) ** -(digits // 2) * a1 / da_dP

        def local_half_width(h):
            return a1 + da_dP * h + d2a_dP2 * h**2 / 2

        def gap(dP):
            b = stick_boundary_22(
                mu, lam, 0, a1, local_half_width(dP), multiplier(0), multiplier(dP)
            )
            return b - local_half_width(permanent_stick_load_33(0, dP, lam, mu))  # (33)

        coefficient = (gap(step) + gap(-step)) / (2 * step**2)
    return +coefficient


def second_order_gap_from_curvature(mu, lam, a1, da_dP, d2a_dP2):
    """C with L_I(P1 + h) = (19) at a(P1 + h), dP/da = 1/a'(P1 + h)."""
    return _gap_coefficient(
        mu,
        lam,
        a1,
        da_dP,
        d2a_dP2,
        lambda h: normal_multiplier_19(
            a1 + da_dP * h + d2a_dP2 * h**2 / 2, 1 / (da_dP + d2a_dP2 * h)
        ),
    )


def second_order_gap_from_multiplier(mu, lam, a1, da_dP, L_I1, dL_I_dP):
    """C with L_I(P1 + h) = L_I1 + L_I' h (all (22) needs at dP^2) and a'' from (19):
    L_I = sqrt(2/a)/(pi a') gives L_I'/L_I = -a'/(2a) - a''/a' (product rule)."""
    curvature = -da_dP * (dL_I_dP / L_I1 + da_dP / (2 * a1))
    return _gap_coefficient(mu, lam, a1, da_dP, curvature, lambda h: L_I1 + dL_I_dP * h)


register_quantity(
    Quantity(
        "generic_law.second_order_stick_boundary_gap",
        ("mu", "lam", "a1", "da_dP", "d2a_dP2"),
        second_order_gap_from_curvature,
        ("22", "28", "33"),
    )
)
register_quantity(
    Quantity(
        "generic_law.second_order_stick_boundary_gap_from_multiplier",
        ("mu", "lam", "a1", "da_dP", "L_I1", "dL_I_dP"),
        second_order_gap_from_multiplier,
        ("22", "26", "33"),
    )
)


# ---------------------------------------------------------------------------------------------
# Beyond the paper: the second-order width (derivations/second_order_slip_zone.py states it,
# X-b2): a1 - b = a'(r - 1) dP/2 + [-a''(1 - r)^2/8 + a'^2 Phi/(32 a1)] dP^2, transcribed
# here by hand; E = W2 minus the dP^2 coefficient of the width of (22), by a second difference
# of (22) on the local law (as for the generic-law gap above).
# ---------------------------------------------------------------------------------------------


def _second_coefficient(mu, lam, eta, a1, da_dP, d2a_dP2, other_edge):
    r = (lam + pi * eta * a1 / 4) / mu
    rho, tau = lam / mu, pi * eta * a1 / (4 * mu)
    same = 4 * tau * (2 - 2 * rho - tau)
    opposite = 2 + 8 * tau - 2 * rho**2 - 4 * rho * tau - 6 * tau**2
    phi = same if other_edge > 0 else opposite
    return -d2a_dP2 * (1 - r) ** 2 / 8 + da_dP**2 * phi / (32 * a1)


def _width_second_order(mu, lam, eta, a1, da_dP, d2a_dP2, dP, other_edge):
    first = da_dP * ((lam + pi * eta * a1 / 4) / mu - 1) / 2
    return first * dP + _second_coefficient(mu, lam, eta, a1, da_dP, d2a_dP2, other_edge) * dP**2


def _curvature_19(a1, da_dP, L_I1, dL_I_dP):
    return -da_dP * (dL_I_dP / L_I1 + da_dP / (2 * a1))


def _paper_error(mu, lam, eta, a1, da_dP, d2a_dP2, other_edge):
    digits = mpmath.mp.dps
    with mpmath.workdps(2 * digits + 20):
        step = mpmath.mpf(10) ** -(digits // 2) * a1 / da_dP

        def width_22(h):
            a2 = a1 + da_dP * h + d2a_dP2 * h**2 / 2
            b = stick_boundary_22(
                mu,
                lam,
                eta,
                a1,
                a2,
                normal_multiplier_19(a1, 1 / da_dP),
                normal_multiplier_19(a2, 1 / (da_dP + d2a_dP2 * h)),
            )
            return a1 - b

        paper = (width_22(step) + width_22(-step)) / (2 * step**2)
        coefficient = _second_coefficient(mu, lam, eta, a1, da_dP, d2a_dP2, other_edge) - paper
    return +coefficient


_SECOND = ("mu", "lam", "eta", "a1", "da_dP", "d2a_dP2")
register_quantity(
    Quantity(
        "second_order.slip_zone_width_second_order",
        (*_SECOND, "dP", "other_edge"),
        _width_second_order,
        ("22", "28"),
    )
)
register_quantity(
    Quantity(
        "second_order.stick_boundary_second_order",
        (*_SECOND, "dP", "other_edge"),
        lambda a1, **k: a1 - _width_second_order(a1=a1, **k),
        ("22", "28"),
    )
)
register_quantity(
    Quantity(
        "second_order.slip_zone_width_second_coefficient",
        (*_SECOND, "other_edge"),
        _second_coefficient,
        ("28",),
    )
)
register_quantity(
    Quantity(
        "second_order.paper_stick_boundary_error",
        (*_SECOND, "other_edge"),
        _paper_error,
        ("22",),
    )
)
register_quantity(
    Quantity(
        "second_order.slip_zone_width_second_order_from_multiplier",
        ("mu", "lam", "eta", "a1", "da_dP", "L_I1", "dL_I_dP", "dP", "other_edge"),
        lambda L_I1, dL_I_dP, a1, da_dP, **k: _width_second_order(
            a1=a1, da_dP=da_dP, d2a_dP2=_curvature_19(a1, da_dP, L_I1, dL_I_dP), **k
        ),
        ("19", "22", "28"),
    )
)
register_quantity(
    Quantity(
        "second_order.slip_zone_width_second_order_dimensionless",
        ("lam_mu", "eta_a1_mu", "growth", "multiplier", "multiplier_slope", "other_edge"),
        # The width in units of a1 with mu = 1 and dP = 1: its groups stand for lam, eta, a',
        # L_I1 and L_I' (the generated doc).
        lambda lam_mu, eta_a1_mu, growth, multiplier, multiplier_slope, other_edge: (
            _width_second_order(
                mu=1,
                lam=lam_mu,
                eta=eta_a1_mu,
                a1=1,
                da_dP=growth,
                d2a_dP2=_curvature_19(1, growth, multiplier, multiplier_slope),
                dP=1,
                other_edge=other_edge,
            )
        ),
        ("19", "22", "28"),
    )
)
register_quantity(
    Quantity(
        "second_order.paper_stick_boundary_error_from_multiplier",
        ("mu", "lam", "eta", "a1", "da_dP", "L_I1", "dL_I_dP", "other_edge"),
        lambda L_I1, dL_I_dP, a1, da_dP, **k: _paper_error(
            a1=a1, da_dP=da_dP, d2a_dP2=_curvature_19(a1, da_dP, L_I1, dL_I_dP), **k
        ),
        ("19", "22"),
    )
)


# ---------------------------------------------------------------------------------------------
# End to end: asymslip.slip_zone(law, LoadCycle(...), mu) for each built-in law, as users call
# it, against the same quantities built at 50 digits from the law's P(a) alone: a(P) by
# mpmath's root finder, dP/da by mpmath.diff, L_I by (19), b by (22) and b_exact = a(P_K) by
# (33)-(34).  Like the API (derivations/edge_symmetry.py), the edge slips forwards when
# lam + pi eta a2/4 > mu, backwards (formulas on -lam, -eta) when it is < -mu, and not at all
# otherwise (b = a1, width 0, P_K = P1).
# ---------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class ApiLaw:
    """A built-in law as the API builds it and as the reference states it."""

    name: str  # the LawCase whose problems apply
    make: Callable[..., object]  # the public law class, called with the parameters
    parameters: tuple[str, ...]  # its keyword arguments (= problem keys)
    load: Callable[..., Callable]  # parameters -> P(a) in mpmath, by hand
    half_width: Callable[..., Callable]  # parameters -> a(P), by mpmath's root finder
    kernels: dict[str, str]  # result field -> the generated function it ends in


def _make_flat_law(**parameters):
    from asymslip.laws.flat_rounded import FlatRoundedLaw

    return FlatRoundedLaw(**parameters)


def _make_power_law(**parameters):
    from asymslip.laws.power import PowerLaw

    return PowerLaw(**parameters)


def _make_hertz_law(**parameters):
    from asymslip import HertzLaw

    return HertzLaw(**parameters)


API_LAWS = {
    law.name: law
    for law in (
        ApiLaw(
            "hertz",
            _make_hertz_law,
            ("R", "E_star"),
            lambda R, E_star: lambda a: pi * E_star * a**2 / (4 * R),  # (29)
            lambda R, E_star: lambda P: half_width_by_root(
                lambda a: pi * E_star * a**2 / (4 * R), P
            ),
            {
                "a1": "hertz.hertz_half_width",
                "a2": "hertz.hertz_half_width_growth",
                "L_I": "hertz.hertz_normal_edge_multiplier",
            },
        ),
        ApiLaw(
            "flat-rounded",
            _make_flat_law,
            ("c", "R", "E_star"),
            lambda c, R, E_star: lambda a: published_flat_load(a, c, R, E_star),
            lambda c, R, E_star: lambda P: flat_half_width_mp(P, c, R, E_star),
            # a(P) inverts flat_rounded_load; a2 - a1 integrates 1/flat_rounded_load_slope.
            {
                "a1": "flat_rounded.flat_rounded_load",
                "a2": "flat_rounded.flat_rounded_load_slope",
                "L_I": "flat_rounded.flat_rounded_normal_edge_multiplier",
            },
        ),
        ApiLaw(
            "power",
            _make_power_law,
            ("A", "n", "E_star"),
            lambda A, n, E_star: _power_load(n, A, E_star, power_shape_factor(n)),
            lambda A, n, E_star: lambda P: half_width_by_root(
                _power_load(n, A, E_star, power_shape_factor(n)), P
            ),
            {
                "a1": "power_law.power_law_half_width",
                "a2": "power_law.power_law_half_width_growth",
                "L_I": "power_law.power_law_normal_edge_multiplier",
            },
        ),
    )
}


@functools.cache
def _law_exact(law_name, digits, P, parameters):
    """a(P) by root finding and L_I(P) by (19) with dP/da by mpmath.diff, at ``digits``."""
    spec = API_LAWS[law_name]
    with mpmath.workdps(digits):
        a = spec.half_width(**dict(parameters))(P)
        return a, normal_multiplier_19(a, mpmath.diff(spec.load(**dict(parameters)), a))


@functools.cache
def _slip_zone_exact(law_name, digits, mu, P1, dP, dQ, dsigma, parameters):
    """The API's quantities at ``digits`` (+20 inside) for P2 = P1 + dP, lam = dQ/dP,
    eta = dsigma/dP.  Cached: the quantities and their condition numbers share it."""
    with mpmath.workdps(digits + 20):
        (a1, L_I1), (a2, L_I2) = (
            _law_exact(law_name, digits + 20, P, parameters) for P in (P1, P1 + dP)
        )
        lam, eta = dQ / dP, dsigma / dP

        def direction_of(edge_lam):  # forward, backward or no slip, in the edge's own frame
            slope = edge_lam + pi * eta * a2 / 4
            return 1 if slope > mu else -1 if slope < -mu else 0

        direction, other = direction_of(lam), direction_of(-lam)  # the right edge, the left
        if direction == 0:
            b22, width, P_K = a1, mpmath.mpf(0), P1
        else:
            lam, eta = direction * lam, direction * eta
            b22 = stick_boundary_22(mu, lam, eta, a1, a2, L_I1, L_I2)
            P_K = permanent_stick_load_33(P1, dP, lam, mu)
            # The headline, b to second order (X-b2): a' and a'' of the law by mpmath.diff of
            # its P(a); the other edge slips the same way globally when the own-frame
            # directions differ in sign (its frame is mirrored), +1 where it does not slip.
            spec = API_LAWS[law_name]
            load = spec.load(**dict(parameters))
            first, second = mpmath.diff(load, a1), mpmath.diff(load, a1, 2)
            same_way = 1 if other == 0 else -direction * other
            width = _width_second_order(
                mu, lam, eta, a1, 1 / first, -second / first**3, dP, same_way
            )
        exact = {
            "a1": a1,
            "a2": a2,
            "L_I1": L_I1,
            "L_I2": L_I2,
            "b": a1 - width,
            "slip_zone_width": width,
            "b_paper": b22,
            "b_exact": None if dsigma else _law_exact(law_name, digits + 20, P_K, parameters)[0],
        }
    return {key: value if value is None else +value for key, value in exact.items()}


#: How a field is checked: on the drawn cycle; with sigma2 = sigma1 (eta = 0, where b_exact
#: exists); with the shear and tension changes reversed (Q, sigma -> -Q, -sigma: lam, eta ->
#: -lam, -eta), which makes the edge slip backwards and exercises the API's mirrored formulas.
VARIANTS = {"drawn": "", "eta = 0": "", "reversed": ", backward slip"}


def _slip_zone_reference(law_name, field, variant):
    spec = API_LAWS[law_name]

    def reference(mu, P1, dP, Q1, dQ, sigma1, dsigma=None, **parameters):
        # Q1 and sigma1 enter the API only through the exact differences dQ and dsigma.
        del Q1, sigma1
        if variant == "eta = 0":
            dsigma = mpmath.mpf(0)
        elif variant == "reversed":
            dQ, dsigma = -dQ, -dsigma
        values = tuple((name, parameters[name]) for name in spec.parameters)
        return _slip_zone_exact(law_name, mpmath.mp.dps, mu, P1, dP, dQ, dsigma, values)[field]

    return reference


@functools.cache
def _slip_zone_computed(law_name, variant, mu, P1, dP, Q1, dQ, sigma1, dsigma, parameters):
    from asymslip import LoadCycle, slip_zone

    # P1 + dP == P2, Q1 + dQ == Q2 and sigma1 + dsigma == sigma2 exactly (drawn so).
    states = [P1, Q1, P1 + dP, Q1 + dQ, sigma1, sigma1 if variant == "eta = 0" else sigma1 + dsigma]
    if variant == "reversed":
        states[1], states[3], states[4], states[5] = -states[1], -states[3], -states[4], -states[5]
    return slip_zone(API_LAWS[law_name].make(**dict(parameters)), LoadCycle(*states), mu)


def _slip_zone_api(law_name, field, variant):
    spec = API_LAWS[law_name]

    def compose(mu, P1, dP, Q1, dQ, sigma1, dsigma=None, **parameters):
        columns = [mu, P1, dP, Q1, dQ, sigma1, dsigma if dsigma is not None else sigma1]
        columns += [parameters[name] for name in spec.parameters]
        values = []
        for row in zip(*(np.asarray(column, dtype=np.float64) for column in columns), strict=True):
            cycle = tuple(map(float, row[:7]))
            named = tuple(zip(spec.parameters, map(float, row[7:]), strict=True))
            result = _slip_zone_computed(law_name, variant, *cycle, named)
            values.append(getattr(result, field))
        return np.array(values, dtype=np.float64)

    return compose


def register_slip_zone_quantities(law_name: str) -> None:
    """The API results of one built-in law, each against its 50-digit reference."""
    spec = API_LAWS[law_name]
    paper = "corrective_slip.stick_boundary_proportional"
    width = "second_order.slip_zone_width_second_order_from_multiplier"
    checks = [
        ("a1", spec.kernels["a1"], "drawn", ("29",)),
        ("a2", spec.kernels["a2"], "drawn", ("23",)),
        ("L_I1", spec.kernels["L_I"], "drawn", ("19",)),
        ("L_I2", spec.kernels["L_I"], "drawn", ("19",)),
        ("b", width, "drawn", ("22", "28")),
        ("slip_zone_width", width, "drawn", ("22", "28")),
        ("b_paper", paper, "drawn", ("22",)),
        ("b_exact", spec.kernels["a1"], "eta = 0", ("33", "34")),
        ("b", width, "reversed", ("22", "28")),
        ("slip_zone_width", width, "reversed", ("22", "28")),
        ("b_paper", paper, "reversed", ("22",)),
    ]
    cycle = ("mu", "P1", "dP=dP_cycle", "Q1", "dQ", "sigma1", "dsigma")
    for field, kernel, variant, equations in checks:
        args = cycle[:-1] if variant == "eta = 0" else cycle
        register_quantity(
            Quantity(
                kernel,
                (*args, *spec.parameters),
                _slip_zone_reference(law_name, field, variant),
                equations,
                laws=(law_name,),
                label=f"slip_zone({law_name}).{field}{VARIANTS[variant]}",
                compose=_slip_zone_api(law_name, field, variant),
                costly=True,
            )
        )


for _name in API_LAWS:
    register_slip_zone_quantities(_name)


# ---------------------------------------------------------------------------------------------
# The reference solver (derivations/solver_influence.py and the laws' profiles).  The profiles
# transcribed from the laws' definitions; the influence kernels from the Flamant point-force
# relations of two similar half-planes (Johnson, Contact Mechanics, (2.19), (2.25), 1/E* =
# 2 (1 - nu^2)/E): ds/dx = +(2/(pi E*)) q/(x - t) for the relative slip, dw/dx = -(2/(pi E*))
# p/(x - t) for the gap opening, integrated to logarithms and over one element by mpmath
# quadrature; the tension strain (1 - nu^2) sigma/E = sigma/(2 E*).  A grid of 500 elements
# over the contact half-width a2 is laid so that the drawn x_contact picks the offset k.
# ---------------------------------------------------------------------------------------------

register_quantity(
    Quantity(
        "hertz.hertz_profile",
        ("x=x_contact", "R"),
        lambda x, R: x**2 / (2 * R),
        ("29",),
        laws=("hertz",),
    )
)
register_quantity(
    Quantity(
        "flat_rounded.flat_rounded_profile",
        ("x=x_contact", "c", "R"),
        lambda x, c, R: max(0, abs(x) - c) ** 2 / (2 * R),
        ("29",),
        laws=("flat-rounded",),
    )
)
register_quantity(
    Quantity(
        "power_law.power_law_profile",
        ("x=x_contact", "n", "A"),
        lambda x, n, A: A * abs(x) ** n,
        ("29",),
        laws=("power",),
    )
)

_SOLVER_ELEMENTS = 500


def _solver_grid(x, a):
    """Offset k (an integer), element width h and reference length ell of the test grid."""
    h = a / _SOLVER_ELEMENTS
    return np.round(x / h), h, 2.2 * a


def _log_kernel_over_element(x, a, E_star, sign):
    """sign (2/(pi E*)) int over the element of ln(|x_i - t|/ell) dt, by quadrature."""
    k, h, ell = (mpmath.mpf(float(v)) for v in _solver_grid(float(x), float(a)))
    lower, upper = (k - mpmath.mpf(1) / 2) * h, (k + mpmath.mpf(1) / 2) * h
    points = [lower, 0, upper] if lower < 0 < upper else [lower, upper]
    return sign * 2 / (pi * E_star) * mpmath.quad(lambda u: mpmath.log(abs(u) / ell), points)


def _kernel_on_grid(name):
    def compose(x, a, E_star):
        from asymslip_gen import solver_influence

        k, h, ell = _solver_grid(x, a)
        return getattr(solver_influence, name)(k, h, ell, E_star)

    return compose


register_quantity(
    Quantity(
        "solver_influence.relative_slip_influence",
        ("x=x_contact", "a=a2", "E_star"),
        lambda x, a, E_star: _log_kernel_over_element(x, a, E_star, +1),
        ("F-3", "F-5"),
        laws=("hertz",),
        compose=_kernel_on_grid("relative_slip_influence"),
        costly=True,
    )
)
register_quantity(
    Quantity(
        "solver_influence.gap_opening_influence",
        ("x=x_contact", "a=a2", "E_star"),
        lambda x, a, E_star: _log_kernel_over_element(x, a, E_star, -1),
        ("F-3", "F-5"),
        laws=("hertz",),
        compose=_kernel_on_grid("gap_opening_influence"),
        costly=True,
    )
)
register_quantity(
    Quantity(
        "solver_influence.tension_relative_displacement",
        ("x=x_contact", "sigma=eta", "E_star"),
        lambda x, sigma, E_star: (1 - mpmath.mpf("0.3") ** 2)
        * sigma
        * x
        / (2 * (1 - mpmath.mpf("0.3") ** 2) * E_star),  # (1 - nu^2) sigma x / E, any nu
        ("F-4",),
    )
)


# ---------------------------------------------------------------------------------------------
# The laboratory match (derivations/lab_transfer.py): from (8), (11), (21), (29), (31), (19)


def _hertz_matched_half_width(L_I1, L_I2, da):
    """(31): L_I2/L_I1 = sqrt(a2/a1) with a2 = a1 + da, solved for a1."""
    return da / ((L_I2 / L_I1) ** 2 - 1)


def _matched_tension_slope(da, L_I1, L_I2, L_II1, L_II2):
    """(21) at both states: L_II/L_I = lam + pi eta a/4, so eta = 4 (r2 - r1)/(pi da)."""
    return 4 * (L_II2 / L_I2 - L_II1 / L_I1) / (mpmath.pi * da)


def _flat_multiplier_unit_radius(a, c, E_star):
    """(19) with the published rounded-flat law at R = 1 (L_I scales as 1/R)."""
    return normal_multiplier_19(a, flat_load_slope_mp(a, c, 1, E_star))


register_quantity(
    Quantity(
        "lab_transfer.peak_shear_change",
        ("mu", "L_I1", "L_I2", "w=width", "da"),
        lambda mu, L_I1, L_I2, w, da: mu * (L_I1 * mpmath.sqrt(w) + L_I2 * mpmath.sqrt(w + da)),
        ("8", "11"),
        where=lambda values: values["b"] < values["a1"],
    )
)
register_quantity(
    Quantity(
        "lab_transfer.hertz_matched_half_width",
        ("L_I1", "L_I2", "da"),
        _hertz_matched_half_width,
        ("31",),
        laws=("hertz",),
    )
)
register_quantity(
    Quantity(
        "lab_transfer.hertz_matched_radius",
        ("E_star", "L_I1", "a1"),
        lambda E_star, L_I1, a1: E_star * mpmath.sqrt(a1 / 2) / L_I1,  # (31) for R
        ("31",),
        laws=("hertz",),
    )
)
register_quantity(
    Quantity(
        "lab_transfer.matched_tension_slope",
        ("da", "L_I1", "L_I2", "L_II1", "L_II2"),
        _matched_tension_slope,
        ("21",),
    )
)
register_quantity(
    Quantity(
        "lab_transfer.matched_shear_slope",
        ("a1", "da", "L_I1", "L_I2", "L_II1", "L_II2"),
        lambda a1, da, L_I1, L_I2, L_II1, L_II2: L_II1 / L_I1
        - mpmath.pi * _matched_tension_slope(da, L_I1, L_I2, L_II1, L_II2) * a1 / 4,
        ("21",),
    )
)
register_quantity(
    Quantity(
        "lab_transfer.flat_rounded_matched_radius",
        ("a=a1", "c", "E_star", "L_I=L_I1"),
        lambda a, c, E_star, L_I: _flat_multiplier_unit_radius(a, c, E_star) / L_I,
        ("19",),
        laws=("flat-rounded",),
    )
)
register_quantity(
    Quantity(
        "lab_transfer.flat_rounded_multiplier_ratio",
        ("a1", "a2", "c"),
        lambda a1, a2, c: _flat_multiplier_unit_radius(a2, c, 1)
        / _flat_multiplier_unit_radius(a1, c, 1),
        ("19",),
        laws=("flat-rounded",),
    )
)


# ---------------------------------------------------------------------------------------------
# The error map's axes (derivations/edge_drive.py): (21) at state 1, L_II1/(mu L_I1) =
# lam/mu + pi eta a1/(4 mu), whose tension term is tau, transcribed; eta from tau by solving
# the same line by hand.
# ---------------------------------------------------------------------------------------------

register_quantity(
    Quantity(
        "edge_drive.tension_share",
        ("eta", "a1", "mu"),
        lambda eta, a1, mu: pi * eta * a1 / (4 * mu),
        ("21", "28"),
    )
)
register_quantity(
    Quantity(
        "edge_drive.tension_slope_for_share",
        ("tau=lam", "a1", "mu"),
        lambda tau, a1, mu: 4 * mu * tau / (pi * a1),
        ("21", "28"),
    )
)


# The slip direction (derivations/edge_symmetry.py, E3): forward where L_II2 > mu L_I2,
# backward where L_II2 < -mu L_I2, none otherwise, as the module docstring states it.
register_quantity(
    Quantity(
        "edge_symmetry.slip_direction",
        ("mu", "L_I2", "L_II2"),
        lambda mu, L_I2, L_II2: mpmath.mpf(
            1 if L_II2 > mu * L_I2 else -1 if L_II2 < -mu * L_I2 else 0
        ),
        ("8", "11"),
    )
)

# The stated accuracies (derivations/stated_accuracy.py), as its docstring states them.
register_quantity(
    Quantity(
        "stated_accuracy.stick_boundary_accuracy",
        ("relative_growth", "width"),
        lambda relative_growth, width: relative_growth**2 * abs(width),
        ("28",),
    )
)
register_quantity(
    Quantity(
        "stated_accuracy.paper_stick_boundary_accuracy",
        ("relative_growth", "width"),
        lambda relative_growth, width: 2 * relative_growth**2 * abs(width),
        ("22",),
    )
)
register_quantity(
    Quantity(
        "stated_accuracy.stick_boundary_accuracy_first_order",
        ("relative_growth", "width"),
        lambda relative_growth, width: 2 * relative_growth * abs(width),
        ("28", "40"),
    )
)
register_quantity(
    Quantity(
        "stated_accuracy.disagreement_limit",
        # Any non-negative lengths and a small rounding share: the problem's da, a2 - b.
        ("accuracy=da", "other_accuracy=width", "a1", "rounding=relative_growth"),
        lambda accuracy, other_accuracy, a1, rounding: accuracy + other_accuracy + rounding * a1,
        ("22", "28", "40"),
        where=lambda values: values["width"] >= 0,
    )
)
