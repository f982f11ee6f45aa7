"""Eqs. (29)-(32): the Hertz contact law derived from the cylinder profile, and its multipliers.

The law comes from the plane-contact relation for a symmetric incomplete profile h(x),
    P(a) = (E*/2) int_{-a}^{a} x h'(x) / sqrt(a^2 - x^2) dx,
applied to h = x^2 / (2 R).  L_I then follows from (19).  Because a^2 is affine in P, the
growth a2 - a1 is written as (a2^2 - a1^2) / (a2 + a1): a product and quotient of positive
terms, with no cancellation however small dP/P1 is.
"""

from __future__ import annotations

import functools

import sympy

from asymslip.codegen import Argument, Derivation

from ._glossary import P1, a, dP, dP_da
from .section2_calibrations import normal_multiplier

x = sympy.Symbol("x", real=True)
R = sympy.Symbol("R", positive=True)
E_star = sympy.Symbol("E_star", positive=True)
P = sympy.Symbol("P", positive=True)

RADIUS = Argument(R, "Radius of the cylinder, R > 0 [length].")
MODULUS = Argument(E_star, "Plane-strain contact modulus E* > 0 [force/length^2].")
LOAD = Argument(P, "Normal load per unit length, P > 0 [force/length].")
LOAD1 = Argument(P1, "Normal load at load state 1, P1 > 0 [force/length].")
LOAD_CHANGE = Argument(dP, "Normal-load change P2 - P1 > 0 [force/length].")


def load_from_profile(profile: sympy.Expr) -> sympy.Expr:
    """P(a) of a symmetric incomplete contact with gap profile h(x)."""
    integrand = x * sympy.diff(profile, x) / sympy.sqrt(a**2 - x**2)
    return sympy.simplify(E_star / 2 * sympy.integrate(integrand, (x, -a, a)))


def hertz_profile() -> sympy.Expr:
    """The cylinder's gap profile h(x) = x^2/(2R), the starting point of (29)."""
    return x**2 / (2 * R)


@functools.cache
def hertz_load() -> sympy.Expr:
    """(29) as P(a)."""
    return load_from_profile(hertz_profile())


@functools.cache
def hertz_half_width() -> sympy.Expr:
    """(29) inverted: a(P), the positive root."""
    roots = sympy.solve(sympy.Eq(hertz_load(), P), a)
    (root,) = [r for r in roots if r.is_positive]
    return root


@functools.cache
def hertz_multiplier() -> sympy.Expr:
    """(31): L_I from (19) with dP/da of the Hertz law, in terms of P."""
    slope = sympy.diff(hertz_load(), a)
    return sympy.simplify(normal_multiplier().subs(dP_da, slope).subs(a, hertz_half_width()))


@functools.cache
def hertz_growth() -> sympy.Expr:
    """a(P1 + dP) - a(P1) without cancellation: (a2^2 - a1^2) / (a2 + a1)."""
    a1 = hertz_half_width().subs(P, P1)
    a2 = hertz_half_width().subs(P, P1 + dP)
    difference_of_squares = sympy.simplify(sympy.expand(a2**2 - a1**2))
    assert difference_of_squares.has(dP) and not difference_of_squares.has(P1), (
        "a^2 must be affine in P for this rationalised form"
    )
    return difference_of_squares / (a2 + a1)


def derive() -> Derivation:
    d = Derivation(__file__)
    d.describe_module(
        "hertz",
        "Section 3 of the paper: the Hertzian (cylinder) contact law and its edge multiplier.",
    )
    with d.equation("29", "Hertz contact law from the cylinder profile") as eq:
        eq.matches_paper(
            hertz_half_width() ** 2,
            4 * P * R / (sympy.pi * E_star),
            how="P(a) = (E*/2) int x h'(x)/sqrt(a^2 - x^2) dx with h = x^2/2R, inverted",
            printed=r"a^2=\frac{4PR}{\pi E^*}",
        )
    with d.equation("31", "Hertz normal edge multiplier") as eq:
        eq.matches_paper(
            hertz_multiplier(),
            E_star / R * sympy.sqrt(hertz_half_width() / 2),
            how="(19) with dP/da of (29)",
            printed=r"L_I=\frac{E^*}{R}\sqrt{\frac{a}{2}}=\frac{2P}{\pi}\sqrt{\frac{2}{a^3}}",
        )
        eq.holds(
            hertz_multiplier() - 2 * P / sympy.pi * sympy.sqrt(2 / hertz_half_width() ** 3),
            how="and equals the second printed form (2P/pi) sqrt(2/a^3)",
        )
    with d.equation("30", "Hertz: small contact growth means dP/P1 << 1") as eq:
        slope = sympy.diff(hertz_half_width(), P)
        eq.holds(
            slope - hertz_half_width() / (2 * P),
            how="a'(P) = a/(2P), so (24) is dP/(2P1) at worst",
        )
        eq.holds(
            sympy.diff(hertz_multiplier(), P) - hertz_multiplier() / (4 * P),
            how="L_I'(P) = L_I/(4P), so (26) is dP/(4P1) and holds whenever (30) does",
        )
    with d.equation("32", "Hertz validity conditions") as eq:
        eq.holds(
            sympy.diff(hertz_half_width(), P) * P / hertz_half_width() - sympy.Rational(1, 2),
            how="(24) and (27) with a'(P) a-independent ratio 1/2 reduce to dP/P1 and "
            "dP/P1 |1 - lam/mu| (eta = 0)",
        )
    d.emit(
        name="hertz_profile",
        args=(
            Argument(x, "Position along the interface from the contact centre [length]."),
            RADIUS,
        ),
        expr=hertz_profile(),
        equations=("29",),
        summary="Gap profile h(x) = x^2/(2R) of the cylinder, from which (29) is derived.",
        doc="The initial gap between the cylinder and the half-plane (the parabolic, half-plane "
        "approximation of the circle); the reference solver's normal problem starts from it.",
        module="hertz",
        returns="h [length].",
    )
    d.emit(
        name="hertz_load",
        args=(Argument(a, "Contact half-width a > 0 [length]."), RADIUS, MODULUS),
        expr=hertz_load(),
        equations=("29",),
        summary="Normal load P(a) of the Hertzian (cylinder) contact of half-width a.",
        doc="From the plane-contact relation for the profile h = x^2/(2R).",
        module="hertz",
        returns="P [force/length].",
    )
    d.emit(
        name="hertz_load_slope",
        args=(Argument(a, "Contact half-width a > 0 [length]."), RADIUS, MODULUS),
        expr=sympy.diff(hertz_load(), a),
        equations=("29",),
        summary="Slope dP/da of the Hertzian contact law.",
        doc="Derivative of (29) as P(a); positive, so the law is increasing.",
        module="hertz",
        returns="dP/da [force/length^2].",
    )
    d.emit(
        name="hertz_half_width",
        args=(LOAD, RADIUS, MODULUS),
        expr=hertz_half_width(),
        equations=("29",),
        summary="Contact half-width a(P) of the Hertzian contact.",
        doc="The positive root of (29).",
        module="hertz",
        returns="a [length].",
    )
    d.emit(
        name="hertz_normal_edge_multiplier",
        args=(LOAD, RADIUS, MODULUS),
        expr=hertz_multiplier(),
        equations=("19", "31"),
        summary="Normal edge multiplier L_I of the Hertzian contact at load P.",
        doc="(19) applied to the Hertz law (29).",
        module="hertz",
        returns="L_I [force/length^(5/2)].",
    )
    d.emit(
        name="hertz_normal_edge_multiplier_slope",
        args=(LOAD, RADIUS, MODULUS),
        expr=sympy.simplify(sympy.diff(hertz_multiplier(), P)),
        equations=("30",),
        summary="Slope dL_I/dP of the Hertzian normal edge multiplier (= L_I / 4P).",
        doc="Derivative of (31) with respect to the load; enters the validity measure (26).",
        module="hertz",
        returns="dL_I/dP.",
    )
    d.emit(
        name="hertz_half_width_growth",
        args=(LOAD1, LOAD_CHANGE, RADIUS, MODULUS),
        expr=hertz_growth(),
        equations=("29", "42"),
        summary="Growth a(P1 + dP) - a(P1) of the Hertzian contact, without cancellation.",
        doc="Written as (a2^2 - a1^2)/(a2 + a1) = 4 R dP / (pi E* (a1 + a2)), which keeps full "
        "relative precision for any dP/P1 > 0.",
        module="hertz",
        returns="a2 - a1 [length].",
    )
    return d
