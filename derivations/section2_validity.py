"""Section 2.2, Eqs. (23)-(28) and (51): validity measures and the first-order slip zone.

The contact law a(P) and the multiplier L_I(P) stay undefined functions; every expansion is a
``series`` in the load change dP.
"""

from __future__ import annotations

import functools

import sympy

from asymslip.codegen import Derivation

from ._glossary import (
    L_I1,
    L_I2,
    L_II1,
    L_II2,
    P1,
    a1,
    a2,
    arguments,
    da,
    da_dP,
    dL_I_dP,
    dP,
    eta,
    lam,
    mu,
)
from .section2_calibrations import (
    load_coefficients,
    slip_zone_width,
    stick_boundary_in_coefficients,
    stick_boundary_proportional,
)

law = sympy.Function("a")  # contact half-width as a function of load
multiplier = sympy.Function("L_I")  # normal edge multiplier as a function of load
load = sympy.Symbol("P", positive=True)


def _on_law(expr: sympy.Expr) -> sympy.Expr:
    """Express a2, L_I2 through the undefined laws at P1 + dP, and a1, L_I1 at P1."""
    return expr.subs(
        {a2: law(P1 + dP), L_I2: multiplier(P1 + dP), a1: law(P1), L_I1: multiplier(P1)},
        simultaneous=True,
    )


def _named_slopes(expr: sympy.Expr) -> sympy.Expr:
    """Replace a(P1), a'(P1), L_I(P1), L_I'(P1) by the glossary's plain symbols."""
    slope = sympy.Derivative(law(P1), P1)
    multiplier_slope = sympy.Derivative(multiplier(P1), P1)
    return expr.doit().subs(
        {slope: da_dP, multiplier_slope: dL_I_dP, law(P1): a1, multiplier(P1): L_I1}
    )


@functools.cache
def relative_slip_zone() -> sympy.Expr:
    """(b - a1)/a1 of (22), the exact quantity of (25)."""
    return sympy.factor((stick_boundary_proportional() - a1) / a1)


@functools.cache
def first_order_stick_ratio() -> sympy.Expr:
    """(28): b/a1 to first order in dP, from the series of (22) along the contact law."""
    ratio = _on_law(stick_boundary_proportional()) / law(P1)
    series = sympy.series(ratio, dP, 0, 2).removeO()
    return sympy.expand(_named_slopes(series))


@functools.cache
def first_order_slip_zone_width() -> sympy.Expr:
    """a1 - b to first order in dP, from the series of the exact width, with no cancellation."""
    width = slip_zone_width().subs(da, law(P1 + dP) - law(P1))
    width = _on_law(width)
    series = sympy.series(width, dP, 0, 2).removeO()
    return sympy.factor(_named_slopes(series))


shear = sympy.Function("L_II")  # an edge's own shear multiplier as a function of load


@functools.cache
def first_order_stick_ratio_from_multipliers() -> sympy.Expr:
    """b/a1 of (17) to first order in dP, in an edge's own multipliers L_I(P), L_II(P).

    For an edge whose L_II does not follow (21) (an asymmetric contact's): the series of (17)
    along undefined a(P), L_I(P) and L_II(P); their slopes other than a'(P1) drop out.
    """
    exact = stick_boundary_in_coefficients().subs(load_coefficients())
    on_path = _on_law(exact).subs({L_II1: shear(P1), L_II2: shear(P1 + dP)}, simultaneous=True)
    series = sympy.series(on_path / law(P1), dP, 0, 2).removeO()
    slope = sympy.Derivative(shear(P1), P1)
    named = _named_slopes(series).subs(shear(P1), L_II1)
    assert not named.has(slope, sympy.Derivative), named
    return sympy.expand(named)


def derive() -> Derivation:
    d = Derivation(__file__)
    d.describe_module(
        "validity",
        "Section 2.2 of the paper: measures that must be small for the asymptotic solution "
        "to hold, and the first-order slip-zone size.",
    )
    with d.equation("23", "Mean-value form of the contact growth") as eq:
        growth = sympy.series(law(P1 + dP), dP, 0, 2).removeO()
        eq.holds(
            _named_slopes(growth) - (a1 + dP * da_dP),
            how="a(P1 + dP) = a1 + dP a'(P1) + O(dP^2); (23) is its mean-value form",
        )
    with d.equation("24", "Contact growth small: dP a'(P) / a1 << 1") as eq:
        eq.given("definition of the measure, used with a'(P) at the worst P in (P1, P2)")
    with d.equation("25", "Slip zone small compared with the contact (exact)") as eq:
        A = (1 - lam / mu - sympy.pi * a2 / 4 * eta / mu) * L_I2
        C = (1 + lam / mu + sympy.pi * a1 / 4 * eta / mu) * L_I1
        corrected = (a2 - a1) / a1 / (1 + C / A)
        eq.holds(
            relative_slip_zone() - corrected,
            how="(b - a1)/a1 = ((a2 - a1)/a1) (1 + C/A)^-1 from (22)",
            derived=relative_slip_zone(),
        )
        eq.erratum(
            "the printed (25) has unbalanced absolute-value bars; the identity is "
            "(b - a1)/a1 = ((a2 - a1)/a1) (1 + C/A)^-1 with C, A the brackets times L_I1, L_I2 "
            "(checked symbolically above)",
            derived=relative_slip_zone(),
        )
    with d.equation("26", "Multiplier growth small: dP L_I'(P) / L_I1 << 1") as eq:
        eq.given("definition of the measure (taken in magnitude here)")
    with d.equation("27", "Necessary condition for a small slip zone") as eq:
        leading = sympy.series(_on_law(relative_slip_zone()), dP, 0, 2).removeO()
        leading = sympy.factor(_named_slopes(leading))
        paper_measure = dP * da_dP / a1 * (1 - lam / mu - sympy.pi * eta * a1 / (4 * mu))
        eq.holds(
            leading - paper_measure / 2,
            how="the leading term of (25) as dP -> 0 is half the measure of (27): "
            "(27) is |(b - a1)/a1| to first order, up to the factor 1/2",
            derived=leading,
        )
    printed_28 = (
        r"\frac{b}{a_1}\approx 1-\frac{\Delta P a'(P_1)}{2a_1}"
        r"\left(\frac{\lambda}{\mu}+\frac{\pi a_1}{4}\frac{\eta}{\mu}-1\right)"
    )
    paper_28 = 1 - dP * da_dP / (2 * a1) * (lam / mu + sympy.pi * a1 / 4 * eta / mu - 1)
    for number, title in [
        ("28", "First-order slip-zone size"),
        ("51", "First-order slip-zone size (conclusion, repeats (28))"),
    ]:
        with d.equation(number, title) as eq:
            eq.matches_paper(
                first_order_stick_ratio(),
                paper_28,
                printed=printed_28,
                how="series of (22) in dP with undefined a(P) and L_I(P); L_I'(P) drops out",
            )

    d.emit(
        name="contact_growth_measure",
        args=arguments(dP, da_dP, a1),
        expr=dP * da_dP / a1,
        equations=("24",),
        summary="Measure (24) of the contact growth, dP a'(P) / a1.",
        doc="Must be << 1 for the edge asymptotes to hold over the whole cycle; evaluate it "
        "with the largest a'(P) on (P1, P2).",
        module="validity",
        returns="Dimensionless measure.",
    )
    d.emit(
        name="relative_slip_zone_measure",
        args=arguments(mu, lam, eta, a1, da, L_I1, L_I2),
        expr=sympy.Abs(slip_zone_width()) / a1,
        equations=("25",),
        summary="Exact measure (25) of the slip-zone size, |b - a1| / a1.",
        doc="The corrected form of (25) (see the errata), computed from the cancellation-free "
        "slip-zone width.  Must be << 1.",
        module="validity",
        returns="Dimensionless measure.",
    )
    d.emit(
        name="multiplier_growth_measure",
        args=arguments(dP, dL_I_dP, L_I1),
        expr=dP * sympy.Abs(dL_I_dP) / L_I1,
        equations=("26",),
        summary="Measure (26) of the growth of L_I over the cycle, dP |L_I'(P)| / L_I1.",
        doc="Must be << 1 for (27) and (28) to apply; taken in magnitude, since a falling L_I "
        "is as much a departure from the assumption as a rising one.",
        module="validity",
        returns="Dimensionless measure.",
    )
    d.emit(
        name="slip_zone_growth_measure",
        args=arguments(mu, lam, eta, a1, dP, da_dP),
        expr=sympy.Abs(2 * leading),
        equations=("27",),
        summary="Necessary-condition measure (27), twice the first-order |b - a1| / a1.",
        doc="dP a'(P) / a1 |1 - lam/mu - pi eta a1 / (4 mu)|, obtained as twice the leading term "
        "of (25) in dP.  Must be << 1.",
        module="validity",
        returns="Dimensionless measure.",
    )
    d.emit(
        name="stick_ratio_first_order",
        args=arguments(mu, lam, eta, a1, dP, da_dP),
        expr=first_order_stick_ratio(),
        equations=("28", "51"),
        summary="First-order stick-boundary ratio b / a1 in the load change dP.",
        doc="Independent of the geometry except through the contact law; requires (24), (26) "
        "and (27) to be small.",
        module="validity",
        returns="b / a1, dimensionless.",
    )
    # The same in an edge's own multipliers: (28) with lam + pi eta a1/4 -> L_II1/L_I1.
    own = first_order_stick_ratio_from_multipliers()
    on_21 = own.subs(L_II1, (lam + sympy.pi * eta * a1 / 4) * L_I1)
    assert sympy.simplify(on_21 - first_order_stick_ratio()) == 0
    d.emit(
        name="stick_ratio_first_order_from_multipliers",
        args=arguments(mu, L_I1, L_II1, a1, dP, da_dP),
        expr=own,
        equations=("17", "28"),
        summary="First-order b / a1 of (17) in an edge's own multipliers L_I1, L_II1.",
        doc="The series of (17) in dP along the edge's a(P), L_I(P) and L_II(P); their slopes "
        "other than a'(P1) drop out.  Equals (28) where L_II follows (21); for an edge of an "
        "asymmetric contact, whose L_II does not (derivations/asymmetric_edge_multipliers.py).",
        module="validity",
        returns="b / a1, dimensionless.",
    )
    d.emit(
        name="slip_zone_growth_measure_from_multipliers",
        args=arguments(mu, L_I1, L_II1, a1, dP, da_dP),
        expr=sympy.Abs(2 * sympy.factor(1 - own)),
        equations=("17", "27"),
        summary="Measure (27) in an edge's own multipliers: twice the first-order |b - a1| / a1.",
        doc="dP a'(P) / a1 |1 - L_II1/(mu L_I1)|, from the first-order (17) in the edge's own "
        "multipliers; equals slip_zone_growth_measure where L_II follows (21).",
        module="validity",
        returns="Dimensionless measure.",
    )
    d.emit(
        name="slip_zone_width_first_order",
        args=arguments(mu, lam, eta, a1, dP, da_dP),
        expr=first_order_slip_zone_width(),
        equations=("28",),
        summary="First-order slip-zone width a1 - b, without forming 1 - b/a1.",
        doc="The series of the exact width in dP: proportional to dP, so it keeps full "
        "relative precision for tiny load changes.",
        module="validity",
        returns="a1 - b, same units as a1.",
    )
    return d
