"""Eqs. (19)-(22) and (50): edge multipliers from a generic contact law, and the stick boundary.

The contact law is an undefined function P(a).  The pressure is built as Mossakovskii's
incremental superposition of flat-punch solutions,
    p(x) = (1/pi) int_x^a P'(c) dc / sqrt(c^2 - x^2),
and the full-stick shear traction likewise from bonded-strip solutions under increments of
shear force dQ and differential bulk tension dsigma,
    q(x) = int_x^a [Q'(c)/pi + sigma'(c) x/4] dc / sqrt(c^2 - x^2).
Substituting c = x + (a - x) v and letting a - x -> 0 gives the first-order edge asymptotes (4),
(5) and their multipliers (19), (20).
"""

from __future__ import annotations

import functools

import sympy

from asymslip.codegen import Derivation

from ._glossary import (
    L_I,
    L_I1,
    L_I2,
    L_II1,
    L_II2,
    a,
    a1,
    a2,
    arguments,
    da,
    dP_da,
    dQ_da,
    dsigma_da,
    eta,
    lam,
    mu,
)
from .section2_consistency import (
    coefficient1,
    coefficient2,
    load_coefficients,
    stick_boundary_in_coefficients,
)

delta, v, c = sympy.symbols("delta v c", positive=True)  # delta = a - x
load_slope = sympy.Function("Pprime")  # P'(a) of an arbitrary contact law
shear_slope = sympy.Function("Qprime")
tension_slope = sympy.Function("sigmaprime")


def _edge_expansion(kernel_numerator) -> tuple[sympy.Expr, sympy.Expr]:
    """(leading multiplier, next-order coefficient) of int_x^a N(c, x) dc/sqrt(c^2 - x^2).

    ``kernel_numerator(c, x)`` is the superposed increment.  The integral equals
    sqrt(delta) * int_0^1 N / sqrt(v (2 x + delta v)) dv with x = a - delta, c = x + delta v.
    """
    x_ = a - delta
    integrand = kernel_numerator(x_ + delta * v, x_) / sympy.sqrt(v * (2 * x_ + delta * v))
    expansion = sympy.series(integrand, delta, 0, 2).removeO()
    leading = sympy.integrate(expansion.coeff(delta, 0), (v, 0, 1))
    following = sympy.integrate(expansion.coeff(delta, 1), (v, 0, 1))
    return sympy.simplify(leading), sympy.simplify(following)


@functools.cache
def normal_multiplier() -> sympy.Expr:
    """(19): L_I in terms of dP/da."""
    leading, _ = _edge_expansion(lambda c_, x_: load_slope(c_) / sympy.pi)
    return leading.subs(load_slope(a), dP_da)


@functools.cache
def shear_multiplier() -> sympy.Expr:
    """(20): L_II in terms of dQ/da and dsigma/da."""
    leading, _ = _edge_expansion(
        lambda c_, x_: shear_slope(c_) / sympy.pi + tension_slope(c_) * x_ / 4
    )
    return leading.subs({shear_slope(a): dQ_da, tension_slope(a): dsigma_da})


@functools.cache
def shear_multiplier_proportional() -> sympy.Expr:
    """(21): L_II on the proportional path dQ = lam dP, dsigma = eta dP, in terms of L_I."""
    on_path = shear_multiplier().subs({dQ_da: lam * dP_da, dsigma_da: eta * dP_da})
    ratio = sympy.simplify(on_path / normal_multiplier())
    return ratio * L_I


def proportional_coefficients(growth: sympy.Expr | None = None) -> dict:
    """C1, C2 of (17) with L_II,i = (lam + pi eta a_i / 4) L_I,i from (21), factored.

    With ``growth``, a2 is written a1 + growth.
    """
    top = a2 if growth is None else a1 + growth
    at_state = {
        L_II1: shear_multiplier_proportional().subs({L_I: L_I1, a: a1}),
        L_II2: shear_multiplier_proportional().subs({L_I: L_I2, a: top}),
    }
    return {
        symbol: sympy.factor(value.subs(at_state).subs(a2, top))
        for symbol, value in load_coefficients().items()
    }


@functools.cache
def stick_boundary_proportional() -> sympy.Expr:
    """(22): (17) with L_II,i = (lam + pi eta a_i / 4) L_I,i."""
    return stick_boundary_in_coefficients().subs(proportional_coefficients())


@functools.cache
def stick_boundary_denominator() -> sympy.Expr:
    """C1 + C2, the denominator of (17) and (22), on the proportional path."""
    _, denominator = sympy.fraction(stick_boundary_in_coefficients())
    assert denominator == coefficient1 + coefficient2
    return denominator.subs(proportional_coefficients())


@functools.cache
def slip_zone_width_in_coefficients() -> sympy.Expr:
    """a1 - b from (17) with a2 = a1 + da: -C2 da / (C1 + C2), da an exact factor."""
    width = sympy.factor(a1 - stick_boundary_in_coefficients().subs(a2, a1 + da))
    numerator, _ = sympy.fraction(width)
    assert sympy.Mul.make_args(numerator).count(da) == 1, "da must factor out of a1 - b"
    assert width.free_symbols == {coefficient1, coefficient2, da}
    return width


@functools.cache
def slip_zone_width() -> sympy.Expr:
    """The width on the proportional path, (22)."""
    return slip_zone_width_in_coefficients().subs(proportional_coefficients(growth=da))


@functools.cache
def slip_zone_width_from_multipliers() -> sympy.Expr:
    """The width of (17) in the four multipliers themselves, for edges whose L_II does not
    follow (21) (an asymmetric contact's, derivations/asymmetric_edge_multipliers.py)."""
    return slip_zone_width_in_coefficients().subs(load_coefficients())


@functools.cache
def stick_boundary_denominator_from_multipliers() -> sympy.Expr:
    """C1 + C2 in the four multipliers."""
    _, denominator = sympy.fraction(stick_boundary_in_coefficients())
    return denominator.subs(load_coefficients())


def _paper_bracket(sign: int, a_i: sympy.Expr) -> sympy.Expr:
    return 1 + sign * (lam / mu + sympy.pi * a_i / 4 * eta / mu)


def derive() -> Derivation:
    d = Derivation(__file__)
    d.describe_module(
        "edge_multipliers",
        "Section 2.1 of the paper: calibrations of the contact-edge multipliers L_I and L_II "
        "from the contact law and the load path.",
    )
    with d.equation("19", "Normal edge multiplier L_I from the contact law") as eq:
        eq.matches_paper(
            normal_multiplier(),
            sympy.sqrt(2 / a) * dP_da / sympy.pi,
            how="Mossakovskii superposition of flat punches expanded as a - x -> 0",
            printed=r"L_I=\frac{1}{\pi}\sqrt{\frac{2}{a}}\frac{dP}{da}",
        )
    with d.equation("4", "Square-root edge asymptote of the contact pressure") as eq:
        # Check of the building block and of (4) on a law with a known pressure: Hertz,
        # P = pi E* a^2 / (4 R), whose pressure is (E*/2R) sqrt(a^2 - x^2).
        modulus, radius = sympy.symbols("E_star R", positive=True)
        x_ = sympy.Symbol("x", positive=True)
        superposed = (
            sympy.integrate(
                sympy.pi * modulus * c / (2 * radius) / sympy.sqrt(c**2 - x_**2), (c, x_, a)
            )
            / sympy.pi
        )
        eq.holds(
            superposed - modulus / (2 * radius) * sympy.sqrt(a**2 - x_**2),
            how="the superposition integral reproduces the Hertz pressure for P = pi E* a^2/4R",
        )
        hertz_multiplier = normal_multiplier().subs(dP_da, sympy.pi * modulus * a / (2 * radius))
        edge_ratio = sympy.limit(superposed.subs(x_, a - delta) / sympy.sqrt(delta), delta, 0)
        eq.holds(
            edge_ratio - hertz_multiplier,
            how="and p / sqrt(a - x) -> L_I of (19) as x -> a",
            derived=hertz_multiplier,
        )
    with d.equation("20", "Shear edge multiplier L_II under full stick") as eq:
        eq.matches_paper(
            shear_multiplier(),
            sympy.sqrt(2 / a) * dQ_da / sympy.pi + sympy.sqrt(2 * a) * dsigma_da / 4,
            how="bonded-strip solutions for dQ and dsigma superposed and expanded as a - x -> 0",
            printed=r"L_{II}=\frac{1}{\pi}\sqrt{\frac{2}{a}}\frac{dQ}{da}"
            r"+\frac14\sqrt{2a}\frac{d\sigma}{da}",
        )
    with d.equation("21", "L_II on the proportional load path") as eq:
        eq.matches_paper(
            shear_multiplier_proportional(),
            (lam + sympy.pi * eta * a / 4) * L_I,
            how="(20) with dQ = lam dP, dsigma = eta dP, divided by (19)",
            printed=r"L_{II}=\left(\lambda+\frac{\pi\eta a}{4}\right)L_I",
        )
    paper_22 = (_paper_bracket(-1, a2) * L_I2 * a2 + _paper_bracket(+1, a1) * L_I1 * a1) / (
        _paper_bracket(-1, a2) * L_I2 + _paper_bracket(+1, a1) * L_I1
    )
    printed_22 = (
        r"\frac{\left(1-\frac{\lambda}{\mu}-\frac{\pi a_2}{4}\frac{\eta}{\mu}\right)L_{I,2}a_2"
        r"+\left(1+\frac{\lambda}{\mu}+\frac{\pi a_1}{4}\frac{\eta}{\mu}\right)L_{I,1}a_1}"
        r"{\left(1-\frac{\lambda}{\mu}-\frac{\pi a_2}{4}\frac{\eta}{\mu}\right)L_{I,2}"
        r"+\left(1+\frac{\lambda}{\mu}+\frac{\pi a_1}{4}\frac{\eta}{\mu}\right)L_{I,1}}"
    )
    for number, title in [
        ("22", "Stick boundary on a proportional path"),
        ("50", "Stick boundary (conclusion, repeats (22))"),
    ]:
        with d.equation(number, title) as eq:
            eq.matches_paper(
                stick_boundary_proportional(),
                paper_22,
                how="(17) with (19) and (21) substituted",
                printed=printed_22,
            )

    d.emit(
        name="normal_edge_multiplier",
        args=arguments(a, dP_da),
        expr=normal_multiplier(),
        equations=("19",),
        summary="Normal edge multiplier L_I of the contact pressure p = L_I sqrt(a - x).",
        doc="From the slope dP/da of any incomplete-contact law, by Mossakovskii's incremental "
        "superposition of flat-punch pressures.",
        module="edge_multipliers",
        returns="L_I [force/length^(5/2)].",
    )
    d.emit(
        name="shear_edge_multiplier",
        args=arguments(a, dQ_da, dsigma_da),
        expr=shear_multiplier(),
        equations=("20",),
        summary="Full-stick shear edge multiplier L_II at the right-hand edge.",
        doc="From the slopes of shear force and differential bulk tension with contact size, "
        "by superposing bonded-strip solutions.",
        module="edge_multipliers",
        returns="L_II [force/length^(5/2)].",
    )
    d.emit(
        name="shear_edge_multiplier_proportional",
        args=arguments(lam, eta, a, L_I),
        expr=shear_multiplier_proportional(),
        equations=("21",),
        summary="Shear edge multiplier L_II on the proportional load path.",
        doc="L_II = (lam + pi eta a / 4) L_I when Q and sigma vary in proportion to P.",
        module="edge_multipliers",
        returns="L_II [force/length^(5/2)].",
    )
    d.emit(
        name="stick_boundary_proportional",
        args=arguments(mu, lam, eta, a1, a2, L_I1, L_I2),
        expr=stick_boundary_proportional(),
        equations=("22", "50"),
        summary="Stick-slip boundary b on a proportional load path.",
        doc="(17) with the calibrations (19) and (21).  Valid under the conditions of Section "
        "2.2 (see the validity measures).  b < a1 needs L_II2 > mu L_I2, i.e. roughly "
        "lam + pi eta a2 / 4 > mu.",
        module="corrective_slip",
        returns="Stick boundary b, same units as a1.",
    )
    d.emit(
        name="stick_boundary_denominator",
        args=arguments(mu, lam, eta, a1, a2, L_I1, L_I2),
        expr=stick_boundary_denominator(),
        equations=("17", "22"),
        summary="Denominator mu (L_I1 + L_I2) + L_II1 - L_II2 of (17) on a proportional path.",
        doc="(17) has no root where it vanishes; the validating API refuses such input.  "
        "Positive for a steady partial-slip state.",
        module="corrective_slip",
        returns="C1 + C2 [force/length^(5/2)].",
    )
    d.emit(
        name="slip_zone_width_from_multipliers",
        args=arguments(mu, da, L_I1, L_I2, L_II1, L_II2),
        expr=slip_zone_width_from_multipliers(),
        equations=("17",),
        summary="Width a1 - b of (17) from the four edge multipliers, cancellation-free.",
        doc="-C2 da/(C1 + C2) with C1 = mu L_I1 + L_II1, C2 = mu L_I2 - L_II2: (17) with a2 = "
        "a1 + da, for edges whose shear multiplier is known by itself rather than through (21) "
        "(an asymmetric or calibrated contact).  Forward slip (L_II2 > mu L_I2); for backward "
        "slip pass -L_II1, -L_II2.",
        module="corrective_slip",
        returns="a1 - b, same units as da.",
    )
    d.emit(
        name="stick_boundary_denominator_from_multipliers",
        args=arguments(mu, L_I1, L_I2, L_II1, L_II2),
        expr=stick_boundary_denominator_from_multipliers(),
        equations=("17",),
        summary="Denominator mu (L_I1 + L_I2) + L_II1 - L_II2 of (17) from the multipliers.",
        doc="(17) has no root where it vanishes, and no steady partial-slip state where it is "
        "negative.",
        module="corrective_slip",
        returns="C1 + C2 [force/length^(5/2)].",
    )
    d.emit(
        name="slip_zone_width",
        args=arguments(mu, lam, eta, a1, da, L_I1, L_I2),
        expr=slip_zone_width(),
        equations=("22", "25"),
        summary="Width a1 - b of the slip zone inside the load-state-1 contact.",
        doc="(22) rewritten with a2 = a1 + da and factored so that da multiplies the whole "
        "expression: no difference of nearly equal numbers, so the width keeps full relative "
        "precision however small da/a1 is.  Positive when the slip zone reaches inside a1.",
        module="corrective_slip",
        returns="a1 - b, same units as a1.",
    )
    return d
