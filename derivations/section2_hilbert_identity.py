"""Eq. (14): the finite Hilbert transform of sqrt((1 - t)/(t - beta)), and the integral in (16).

SymPy cannot do these principal-value integrals directly.  The substitution
u = sqrt((1 - t)/(t - beta)) makes the integrand rational; ``apart`` splits it into a bounded
term and a pole term, each integrated with positive symbols, and the principal value is the
symmetric limit around the pole.  An mpmath quadrature at 30 digits checks both branches.
"""

from __future__ import annotations

import functools

import mpmath
import sympy

from asymslip.codegen import Derivation

u, eps, upper = sympy.symbols("u epsilon U", positive=True)
# beta < x < 1 (principal value) and x > 1 (ordinary) are parametrised by positive distances.
beta = sympy.Symbol("beta", real=True)
x = sympy.Symbol("x", real=True)
d1, d2 = sympy.symbols("d_1 d_2", positive=True)

T_OF_U = (1 + beta * u**2) / (1 + u**2)


def rationalised_integrand(numerator_only: bool = False) -> sympy.Expr:
    """Integrand of (14) in u, oriented from u = 0 to u = oo (t runs from 1 down to beta)."""
    weight = sympy.sqrt(sympy.factor(sympy.cancel((1 - T_OF_U) / (T_OF_U - beta))))
    assert sympy.simplify(weight - u) == 0, "the substitution must rationalise the weight"
    jacobian = -sympy.diff(T_OF_U, u)  # minus: the limits are flipped to 0 .. oo
    kernel = 1 if numerator_only else 1 / (T_OF_U - x)
    return sympy.factor(sympy.cancel(u * jacobian * kernel))


def _principal_value(integrand: sympy.Expr, pole: sympy.Expr) -> sympy.Expr:
    """PV of int_0^oo integrand du with a simple pole at u = pole > 0, term by term."""
    total = sympy.Integer(0)
    for term in sympy.Add.make_args(sympy.apart(integrand, u)):
        antiderivative = sympy.integrate(term, u)
        total += (antiderivative.subs(u, pole - eps) - antiderivative.subs(u, 0)) + (
            antiderivative.subs(u, upper) - antiderivative.subs(u, pole + eps)
        )
    # limit() on the raw expression: simplifying first loses the branch of the logarithms.
    return sympy.limit(sympy.limit(total, eps, 0, "+"), upper, sympy.oo)


@functools.cache
def hilbert_identity() -> tuple[sympy.Expr, sympy.Expr]:
    """(inside, outside): the integral of (14) for beta < x < 1 and for x > 1."""
    integrand = rationalised_integrand()
    # Inside: x = 1 - d1, beta = x - d2; the pole sits at u0 = sqrt(d1/d2).
    inside_integrand = sympy.factor(integrand.subs(beta, x - d2).subs(x, 1 - d1))
    inside = _principal_value(inside_integrand, sympy.sqrt(d1 / d2))
    inside = sympy.simplify(inside)
    # Outside: x = 1 + d1, beta = x - d2 (d2 > d1); no pole on (0, oo).
    outside_integrand = sympy.factor(integrand.subs(beta, x - d2).subs(x, 1 + d1))
    outside = sympy.integrate(sympy.apart(outside_integrand, u), (u, 0, sympy.oo))
    outside = sympy.simplify(outside.subs({d1: x - 1, d2: x - beta}))
    return inside, outside


@functools.cache
def weight_integral() -> sympy.Expr:
    """int_beta^1 sqrt((1 - t)/(t - beta)) dt, the integral that (16) scales."""
    integrand = sympy.factor(rationalised_integrand(numerator_only=True))
    return sympy.simplify(sympy.integrate(integrand, (u, 0, sympy.oo)))


def hilbert_on_interval(lower: sympy.Expr, top: sympy.Expr, point: sympy.Expr, inside: bool):
    """int_lower^top sqrt((top - t)/(t - lower)) dt/(t - point), by scaling t = top * tau."""
    value_inside, value_outside = hilbert_identity()
    value = value_inside if inside else value_outside
    return value.subs({beta: lower / top, x: point / top}, simultaneous=True)


def _quadrature(beta_value: mpmath.mpf, x_value: mpmath.mpf) -> mpmath.mpf:
    """Independent mpmath evaluation of the left side of (14)."""

    def weight(t):
        return mpmath.sqrt((1 - t) / (t - beta_value))

    if x_value > 1:
        return mpmath.quad(lambda t: weight(t) / (t - x_value), [beta_value, 1])
    # Principal value: subtract the weight at the pole, add back its exact PV.
    w0 = weight(x_value)
    regular = mpmath.quad(lambda t: (weight(t) - w0) / (t - x_value), [beta_value, x_value, 1])
    return regular + w0 * mpmath.log((1 - x_value) / (x_value - beta_value))


def derive() -> Derivation:
    d = Derivation(__file__)
    with d.equation("14", "Finite Hilbert transform of sqrt((1-t)/(t-beta))") as eq:
        inside, outside = hilbert_identity()
        eq.matches_paper(
            inside,
            -sympy.pi,
            how="u = sqrt((1-t)/(t-beta)) rationalises; apart; symmetric limit around the pole",
            printed=r"\int_{\beta}^{1}\sqrt{\frac{1-t}{t-\beta}}\frac{dt}{t-x}="
            r"\begin{cases}-\pi & \beta<x<1\\ -\pi\left(1-\sqrt{\frac{x-1}{x-\beta}}\right)"
            r" & x>1\end{cases}",
        )
        paper_outside = -sympy.pi * (1 - sympy.sqrt((x - 1) / (x - beta)))
        eq.holds(
            (outside - paper_outside).subs({x: 1 + d1, beta: 1 + d1 - d2}),
            how="outside branch x > 1 equals -pi (1 - sqrt((x-1)/(x-beta)))",
            derived=sympy.Tuple(inside, outside),
        )
        points = [
            {"beta_value": mpmath.mpf(bv), "x_value": mpmath.mpf(xv)}
            for bv, xv in [("-0.7", "0.3"), ("0.25", "0.9"), ("-2", "1.5"), ("0.5", "7")]
        ]

        def closed_form(beta_value, x_value):
            branch = inside if x_value < 1 else outside
            return sympy.N(branch.subs({beta: beta_value, x: x_value}), 40)

        eq.matches_numerically(
            closed_form, _quadrature, points, how="mpmath quadrature of (14)", symbolic=True
        )
    return d
