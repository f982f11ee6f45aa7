"""Eq. (15): the loading dislocation density, from the inversion (13) evaluated with (14).

On b < x < a1 both integrals of (13) are principal values (-pi each); on a1 < x < a2 the first
is an ordinary integral.  The two pieces differ by a term proportional to sqrt(x - a1), so one
branch-free expression with sqrt(Max(0, x - a1)) covers the slip zone, and with
sqrt(Max(0, x - b)) it also gives the correct zero density in the stick zone x <= b.
The result is checked against the integral equation (12) itself by 30-digit quadrature.
"""

from __future__ import annotations

import functools

import mpmath
import sympy

from asymslip.codegen import Derivation

from ._glossary import L_I1, L_I2, L_II1, L_II2, E_star, a1, a2, arguments, b, mu, x
from .section2_consistency import stick_boundary
from .section2_hilbert_identity import hilbert_on_interval

# Positive distances that put x inside each piece of the slip zone.
beyond_b, beyond_a1 = sympy.symbols("r s", positive=True)
gap = sympy.Symbol("g", positive=True)  # a1 = b + g, so that b < a1


#: A Fig. 5-like cycle in exact rationals for the numerical checks of Section 2 and 3.4;
#: mu L_I2 - L_II2 < 0 puts the consistent b of (17) inside a1, as in Fig. 5.
EXAMPLE_CYCLE = {
    mu: "3/10",
    E_star: "2",
    a1: "1",
    a2: "21/20",
    L_I1: "1",
    L_I2: "11/10",
    L_II1: "1/2",
    L_II2: "11/20",
}


def example_cycle() -> dict[sympy.Symbol, sympy.Rational]:
    """:data:`EXAMPLE_CYCLE` as rationals, with b from (17)."""
    values = {symbol: sympy.Rational(value) for symbol, value in EXAMPLE_CYCLE.items()}
    values[b] = stick_boundary().subs(values)
    return values


def inversion(inside_a1: bool) -> sympy.Expr:
    """(13) with its two finite Hilbert transforms evaluated by (14)."""
    coefficient1, coefficient2 = mu * L_I1 + L_II1, mu * L_I2 - L_II2
    bracket = coefficient1 * hilbert_on_interval(b, a1, x, inside=inside_a1) + (
        coefficient2 * hilbert_on_interval(b, a2, x, inside=True)
    )
    return 2 * sympy.sqrt(x - b) / (sympy.pi * E_star) * bracket


@functools.cache
def dislocation_density() -> sympy.Expr:
    """B^{1->2}(a2 - x) as one clamped expression valid for every x < a2."""
    stick_side = sympy.expand(inversion(inside_a1=True).subs(x, b + beyond_b))
    outer = inversion(inside_a1=False).subs(a1, b + gap).subs(x, b + gap + beyond_a1)
    jump = sympy.simplify(outer - stick_side.subs(beyond_b, gap + beyond_a1))
    clamp = {
        beyond_b: sympy.Max(0, x - b),
        beyond_a1: sympy.Max(0, x - a1),
    }
    density = stick_side.subs(clamp) + sympy.expand(jump).subs(clamp)
    # Group by the two square roots: one multiply-add per root in the generated code.
    roots = [sympy.sqrt(value) for value in clamp.values()]
    return sympy.collect(sympy.expand(density), roots, func=sympy.factor)


def _reference_traction(values: dict, x_value: mpmath.mpf, density) -> mpmath.mpf:
    """Right side of (12): E*/(2 pi sqrt(a2 - x)) * PV int_{a2}^{b} sqrt(a2-t) B dt/(t - x)."""
    a2v, bv, a1v = values["a2"], values["b"], values["a1"]

    def weighted(t):
        return mpmath.sqrt(a2v - t) * density(t)

    at_pole = weighted(x_value)
    breaks = sorted({bv, a1v, x_value, a2v})
    regular = mpmath.quad(lambda t: (weighted(t) - at_pole) / (t - x_value), breaks)
    principal = regular + at_pole * mpmath.log((a2v - x_value) / (x_value - bv))
    return -values["E_star"] / (2 * mpmath.pi * mpmath.sqrt(a2v - x_value)) * principal


def derive() -> Derivation:
    d = Derivation(__file__)
    density = dislocation_density()
    with d.equation("15", "Dislocation density of the loading half-cycle") as eq:
        paper = -2 * sympy.sqrt(x - b) / E_star * (mu * (L_I1 + L_I2) + L_II1 - L_II2) + (
            2 * (mu * L_I1 + L_II1) / E_star * sympy.sqrt(sympy.Max(0, x - a1))
        )
        eq.matches_paper(
            density.subs(sympy.Max(0, x - b), x - b),
            paper,
            how="(13) evaluated with (14) on (b, a1) and (a1, a2); H(x - a1) sqrt(x - a1) "
            "written as sqrt(Max(0, x - a1))",
            printed=r"-\frac{2\sqrt{x-b}}{E^*}\left(\mu(L_{I,1}+L_{I,2})+L_{II,1}-L_{II,2}\right)"
            r"+\frac{2(\mu L_{I,1}+L_{II,1})}{E^*}H(x-a_1)\sqrt{x-a_1}",
        )

    with d.equation("13", "Bounded inversion of the singular integral equation (12)") as eq:
        exact = example_cycle()

        def values() -> dict[str, mpmath.mpf]:
            # Converted at call time, inside the caller's raised working precision.
            return {symbol.name: mpmath.mpf(value.p) / value.q for symbol, value in exact.items()}

        numeric_density = sympy.lambdify(x, density.subs(exact), modules="mpmath")

        def left_side(fraction):
            v = values()
            x_value = v["b"] + (v["a2"] - v["b"]) * mpmath.mpf(fraction)
            inner = mpmath.sqrt(v["a1"] - x_value) if x_value < v["a1"] else 0
            return (v["mu"] * v["L_I1"] + v["L_II1"]) * inner + (
                v["mu"] * v["L_I2"] - v["L_II2"]
            ) * mpmath.sqrt(v["a2"] - x_value)

        def right_side(fraction):
            v = values()
            x_value = v["b"] + (v["a2"] - v["b"]) * mpmath.mpf(fraction)
            return _reference_traction(v, x_value, numeric_density)

        points = [{"fraction": f} for f in ("0.1", "0.5", "0.9")]
        eq.matches_numerically(
            right_side,
            left_side,
            points,
            how="(15), the result of (13), substituted into (12) by principal-value quadrature",
            derived_expr=density,
        )

    d.emit(
        name="dislocation_density",
        args=arguments(x, b, a1, mu, L_I1, L_I2, L_II1, L_II2, E_star),
        expr=density,
        equations=("13", "14", "15"),
        summary="Glide-dislocation density B^{1->2}(a2 - x) inserted on loading.",
        doc="Bounded at both ends of the slip zone b < x < a2.  The clamped square roots make "
        "it zero in the stick zone x <= b, where no dislocations are inserted, and supply the "
        "H(x - a1) factor without branches; beyond the contact (x >= a2) it has no meaning.  "
        "Solves (12) only for b from (17); the unloading density is its negative.",
        module="corrective_slip",
        returns="Dislocation density B^{1->2}, dimensionless (slip per unit length).",
    )
    return d
