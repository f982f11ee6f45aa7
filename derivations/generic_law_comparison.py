"""The corrective-slip stick boundary (22) against a(P_K) for a generic law (beyond the paper).

For Hertz the paper shows that (22), the first-order (28) and the exact Jaeger-Ciavarella
stick zone b = a(P_K) of (33) agree to first order in dP.  Here the contact law is arbitrary:
a(P1 + h) is carried as its Taylor polynomial with free coefficients a1, a'(P1), a''(P1),
a'''(P1), L_I comes from (19) with dP/da = 1/a'(P), eta = 0 (the case (33) covers),
P2 = P1 + dP and Q2 - Q1 = lam dP.  Series in dP show

* for every law, (28) is exactly the first-order term of a(P_K) (and of (22)): the agreement
  of (36), (44), (45) is a property of the method, not of the cylinder;
* the second-order terms differ by
      b(22) - a(P_K) = -(1 - lam^2/mu^2) (a'' + a'^2/a) dP^2 / 8 + O(dP^3)
                     = (1 - lam^2/mu^2) a' (L_I'/L_I - a'/(2a)) dP^2 / 8 + O(dP^3)
  at P1 (a''' drops out).  a'' + a'^2/a = (a^2)''/(2a) vanishes exactly when a^2 is affine in
  P: Hertz's law (29) agrees through second order, as the design notes record.  For the power
  law a ~ P^(1/n) the coefficient is proportional to (2 - n)/n^2, nonzero unless n = 2.
"""

from __future__ import annotations

import functools

import sympy

from asymslip.codegen import Argument, Derivation

from ._glossary import (
    L_I1,
    L_I2,
    P1,
    a,
    a1,
    a2,
    arguments,
    da_dP,
    dL_I_dP,
    dP,
    dP_da,
    eta,
    lam,
    mu,
)
from .section2_calibrations import normal_multiplier, stick_boundary_proportional
from .section2_validity import first_order_stick_ratio
from .section3_exact_solution import permanent_stick_load

load = sympy.Symbol("P", positive=True)
step = sympy.Symbol("h", real=True)  # P - P1
d2a_dP2 = sympy.Symbol("d2a_dP2", real=True)
d3a_dP3 = sympy.Symbol("d3a_dP3", real=True)
n = sympy.Symbol("n", positive=True)
scale = sympy.Symbol("k", positive=True)
alpha, beta = sympy.symbols("alpha beta", positive=True)
ell = sympy.Symbol("ell", real=True)  # L_I'(P1) / L_I(P1)

CURVATURE = Argument(d2a_dP2, "Second derivative a''(P1) of the contact law [length^3/force^2].")


def half_width_near(h: sympy.Expr) -> sympy.Expr:
    """a(P1 + h) of an arbitrary analytic law, through its Taylor coefficients at P1.

    The coefficients are free symbols, so every law is covered; the third derivative is
    carried to show that it does not reach the dP^2 terms.
    """
    return a1 + da_dP * h + d2a_dP2 * h**2 / 2 + d3a_dP3 * h**3 / 6


def multiplier_near(h: sympy.Expr) -> sympy.Expr:
    """L_I(P1 + h) from (19) with dP/da = 1/a'(P)."""
    slope = sympy.diff(half_width_near(step), step).subs(step, h)
    return normal_multiplier().subs(dP_da, 1 / slope).subs(a, half_width_near(h))


@functools.cache
def multiplier_ratio() -> sympy.Expr:
    """L_I(P1 + dP)/L_I(P1) from (19), through dP^2 (all that the dP^2 terms of (22) need)."""
    ratio = multiplier_near(dP) / multiplier_near(0)
    return sympy.expand(sympy.series(ratio, dP, 0, 3).removeO())


@functools.cache
def stick_boundary_on_law() -> sympy.Expr:
    """(22) with eta = 0, a_i = a(P_i) and L_I,i from (19), through its dP^2 terms.

    (22) is homogeneous of degree 0 in (L_I1, L_I2), so only their ratio enters; it is
    replaced by its series, which leaves a rational function of dP.
    """
    ratio = sympy.Symbol("rho", positive=True)
    in_ratio = sympy.cancel(stick_boundary_proportional().subs(eta, 0).subs(L_I2, ratio * L_I1))
    assert not in_ratio.has(L_I1), in_ratio
    return in_ratio.subs({a2: half_width_near(dP), ratio: multiplier_ratio()})


@functools.cache
def permanent_stick_width() -> sympy.Expr:
    """a(P_K) with P_K of (33) on the proportional path, eta = 0."""
    return half_width_near(permanent_stick_load() - P1)


def taylor_coefficients(expr: sympy.Expr, order: int) -> list[sympy.Expr]:
    """Coefficients of dP^0 .. dP^order of a rational function of dP, by series division.

    With expr = N/D, N = sum n_k dP^k and D = sum d_k dP^k, the coefficients c_k of the
    quotient follow from N = C D: c_k = (n_k - sum_{j<k} c_j d_{k-j}) / d_0.
    """
    numerator, denominator = sympy.fraction(sympy.cancel(sympy.together(expr)))
    n_poly, d_poly = sympy.Poly(numerator, dP), sympy.Poly(denominator, dP)
    n_k = [n_poly.coeff_monomial(dP**k) for k in range(order + 1)]
    d_k = [d_poly.coeff_monomial(dP**k) for k in range(order + 1)]
    coefficients: list[sympy.Expr] = []
    for k in range(order + 1):
        known = sum((coefficients[j] * d_k[k - j] for j in range(k)), sympy.S.Zero)
        coefficients.append(sympy.factor(sympy.cancel((n_k[k] - known) / d_k[0])))
    return coefficients


def first_order(expr: sympy.Expr) -> sympy.Expr:
    """Taylor polynomial of expr in dP through dP**1."""
    c0, c1 = taylor_coefficients(expr, 1)
    return c0 + c1 * dP


@functools.cache
def second_order_gap() -> sympy.Expr:
    """Coefficient of dP^2 in b(22) - a(P_K)."""
    return taylor_coefficients(stick_boundary_on_law() - permanent_stick_width(), 2)[2]


@functools.cache
def second_order_gap_from_multiplier() -> sympy.Expr:
    """The same coefficient with a'' traded for L_I'(P1)/L_I(P1) (symbol ell)."""
    return (1 - lam**2 / mu**2) * da_dP * (ell - da_dP / (2 * a1)) / 8


def on_law(expr: sympy.Expr, half_width: sympy.Expr) -> sympy.Expr:
    """A coefficient in a1, a'(P1), a''(P1), evaluated for the concrete law a(P) = half_width."""
    derivatives = {
        d2a_dP2: sympy.diff(half_width, load, 2),
        da_dP: sympy.diff(half_width, load),
        a1: half_width,
    }
    return sympy.simplify(expr.subs(derivatives).subs(load, P1))


def derive() -> Derivation:
    d = Derivation(__file__)
    d.describe_module(
        "generic_law",
        "Beyond the paper: the corrective-slip stick boundary (22) against the Jaeger-Ciavarella "
        "stick zone a(P_K) of (33) for a generic contact law.",
    )
    paper_28 = a1 * first_order_stick_ratio().subs(eta, 0)
    with d.equation("G-28", "(28) is the first-order term of a(P_K) for any law") as eq:
        exact_first = first_order(permanent_stick_width())
        eq.beyond_paper(
            "the paper shows the agreement for Hertz, (36) and (45); for an arbitrary law a(P) "
            "the series of a(P_K), P_K = P1 + dP/2 - lam dP/(2 mu), is a1 times (28)",
            derived=exact_first,
        )
        eq.holds(exact_first - paper_28, how="a(P_K) = a1 (28) + O(dP^2) for every law a(P)")
        eq.holds(
            first_order(stick_boundary_on_law()) - paper_28,
            how="(22) with L_I from (19) is a1 (28) + O(dP^2) too: all three agree to first order",
        )
    gap = second_order_gap()
    with d.equation("G-22", "Second-order gap between (22) and a(P_K)") as eq:
        eq.beyond_paper(
            "b(22) - a(P_K) = -(1 - lam^2/mu^2) (a'' + a'^2/a) dP^2/8 + O(dP^3) at eta = 0",
            derived=gap,
        )
        eq.holds(
            gap + (1 - lam**2 / mu**2) * (d2a_dP2 + da_dP**2 / a1) / 8,
            how="the dP^2 coefficient of the series of (22) - a(P_K); a''' does not enter",
        )
        ratio = sympy.diff(multiplier_near(step), step).subs(step, 0) / multiplier_near(0)
        eq.holds(
            second_order_gap_from_multiplier().subs(ell, ratio) - gap,
            how="= (1 - lam^2/mu^2) a' (L_I'/L_I - a'/(2a)) dP^2/8, since (19) gives "
            "L_I'/L_I = -a'/(2a) - a''/a'",
        )
        eq.holds(
            on_law(gap, sympy.sqrt(alpha + beta * load)),
            how="zero when a^2 = alpha + beta P is affine in P (Hertz (29)): (22) and a(P_K) "
            "then agree through second order",
        )
        power = on_law(gap, (load / scale) ** (1 / n))
        power_a1 = (P1 / scale) ** (1 / n)
        eq.holds(
            power + (1 - lam**2 / mu**2) * (2 - n) * power_a1 / (8 * n**2 * P1**2),
            how="for the power law a = (P/k)^(1/n): -(1 - lam^2/mu^2) (2 - n) a1/(8 n^2 P1^2), "
            "nonzero for n != 2 and lam != +-mu (e.g. the wedge, n = 1)",
        )
        for order in (1, 3):
            assert power.subs({n: order, lam: 2, mu: 1, scale: 1, P1: 1}) != 0
    d.emit(
        name="second_order_stick_boundary_gap",
        args=(*arguments(mu, lam, a1, da_dP), CURVATURE),
        expr=gap,
        equations=("22", "28", "33"),
        summary="Coefficient C of b(22) - a(P_K) = C dP^2 + O(dP^3) for a generic contact law.",
        doc="-(1 - lam^2/mu^2) (a'' + a'^2/a)/8 at P1, with eta = 0 and L_I from (19).  To "
        "first order (22), (28) and a(P_K) agree for every law; C vanishes when a^2 is affine "
        "in P (Hertz) and is -(1 - lam^2/mu^2) (2 - n) a1/(8 n^2 P1^2) for a power law "
        "a ~ P^(1/n).",
        module="generic_law",
        returns="C [length^3/force^2].",
    )
    d.emit(
        name="second_order_stick_boundary_gap_from_multiplier",
        args=arguments(mu, lam, a1, da_dP, L_I1, dL_I_dP),
        expr=sympy.factor(second_order_gap_from_multiplier().subs(ell, dL_I_dP / L_I1)),
        equations=("22", "26", "33"),
        summary="The coefficient C of b(22) - a(P_K) = C dP^2 + O(dP^3), from L_I'(P1).",
        doc="(1 - lam^2/mu^2) a' (L_I'/L_I - a'/(2a))/8 at P1: the same C with a'' eliminated "
        "through (19); eta = 0.",
        module="generic_law",
        returns="C [length^3/force^2].",
    )
    return d
