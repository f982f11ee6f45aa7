"""The slip displacement of the loading half-cycle: the integral of the dislocation density (15).

The paper notes (abstract, conclusion) that the slip displacement follows readily from the
density (15) but does not write it down.  Here it is
    h(x) = int_b^x B^{1->2}(a2 - t) dt,
the net Burgers vector of the dislocations between the stick boundary and x.  (15) is a sum of
terms coefficient * sqrt(Max(0, t - c)) with c = b and c = a1, each integrated in closed form
as (2/3) Max(0, x - c)^(3/2): one branch-free expression, zero throughout the stick zone.
"""

from __future__ import annotations

import functools

import mpmath
import sympy

from asymslip.codegen import Derivation

from ._glossary import L_I1, L_I2, L_II1, L_II2, E_star, a1, arguments, b, mu, x
from .section2_dislocation_density import dislocation_density, example_cycle
from .section3_tractions import density_pieces

t = sympy.Symbol("t", real=True)
beyond = sympy.Symbol("g", positive=True)  # x - c > 0
h1, h2 = sympy.symbols("h1 h2", positive=True)  # positive gaps that order b < a1 < x


@functools.cache
def slip_on_loading() -> sympy.Expr:
    """int_b^x B^{1->2}(a2 - t) dt for every x < a2, clamped so that it is 0 for x <= b."""
    c = sympy.Symbol("c", real=True)
    # For x = c + g beyond the lower end c >= b, int_b^x sqrt(Max(0, t - c)) dt = int_c^x.
    piece = sympy.integrate(sympy.sqrt(t - c), (t, c, c + beyond))
    clamped = piece.subs(beyond, sympy.Max(0, x - c))
    total = sum(coefficient * clamped.subs(c, end) for end, coefficient in density_pieces().items())
    powers = [sympy.Max(0, x - end) ** sympy.Rational(3, 2) for end in (b, a1)]
    return sympy.collect(sympy.expand(total), powers, func=sympy.factor)


def _values() -> dict[str, mpmath.mpf]:
    """The example at the caller's working precision."""
    return {symbol.name: mpmath.mpf(value.p) / value.q for symbol, value in _example().items()}


def _position(fraction: str) -> mpmath.mpf:
    """x = b + (a2 - b) * fraction."""
    v = _values()
    return v["b"] + (v["a2"] - v["b"]) * mpmath.mpf(fraction)


def _reference(fraction: str) -> mpmath.mpf:
    """int_b^x of (15) as printed (H(x - a1) as a test), by mpmath quadrature."""
    v = _values()
    coefficient1 = v["mu"] * v["L_I1"] + v["L_II1"]
    total = coefficient1 + v["mu"] * v["L_I2"] - v["L_II2"]

    def density(s):
        inner = mpmath.sqrt(s - v["a1"]) if s > v["a1"] else 0
        return (-2 * mpmath.sqrt(s - v["b"]) * total + 2 * coefficient1 * inner) / v["E_star"]

    x_value = _position(fraction)
    if x_value <= v["b"]:
        return mpmath.mpf(0)
    return mpmath.quad(density, sorted({v["b"], min(v["a1"], x_value), x_value}))


def _example() -> dict[sympy.Symbol, sympy.Rational]:
    return example_cycle()


def derive() -> Derivation:
    d = Derivation(__file__)
    d.describe_module(
        "slip_displacement",
        "The slip displacement of the loading half-cycle, integrated from the dislocation "
        "density (15) of Section 2 (stated, not written out, in the paper).",
    )
    slip = slip_on_loading()
    with d.equation("15", "Slip displacement: the integral of the density (15)") as eq:
        eq.beyond_paper(
            "int_b^x B^{1->2}(a2 - t) dt of (15), each sqrt(Max(0, t - c)) integrated to "
            "(2/3) Max(0, x - c)^(3/2)",
            derived=slip,
        )
        density = dislocation_density()
        ordered = {b: a1 - h1, x: a1 + h2}  # b < a1 < x: every clamp resolved
        eq.holds(
            sympy.diff(slip, x).subs(ordered) - density.subs(ordered),
            how="d(slip)/dx equals (15) on a1 < x < a2",
        )
        ordered = {a1: x + h2, b: x - h1}  # b < x < a1
        eq.holds(
            sympy.diff(slip, x).subs(ordered) - density.subs(ordered),
            how="d(slip)/dx equals (15) on b < x < a1",
        )
        eq.holds(
            slip.subs({b: x + h1, a1: x + h1 + h2}),
            how="the slip is zero throughout the stick zone x <= b",
        )
        numeric = sympy.lambdify(x, slip.subs(_example()), "mpmath")
        eq.matches_numerically(
            lambda fraction: numeric(_position(fraction)),
            _reference,
            [{"fraction": f} for f in ("0.3", "0.8", "1")],
            how="mpmath quadrature of (15) from b, in both pieces of the slip zone",
            symbolic=True,
        )
    d.emit(
        name="slip_on_loading",
        args=arguments(x, b, a1, mu, L_I1, L_I2, L_II1, L_II2, E_star),
        expr=slip,
        equations=("15",),
        summary="Slip displacement accumulated on loading 1 -> 2, integrated from (15).",
        doc="h(x) = int_b^x B^{1->2}(a2 - t) dt: the net Burgers vector of the glide "
        "dislocations lying between the stick boundary b and x (in the coordinate z = a2 - x "
        "of (1), int_{a2 - x}^{a2 - b} B_x(z) dz).  It is the change, from load state 1 to "
        "load state 2, of the relative tangential displacement of the two bodies at x, in the "
        "sign convention of B_x in (1), measured from the stick zone, where it is zero "
        "(so h = 0 for x <= b).  Unloading 2 -> 1 inserts -B^{1->2} and takes it back, so "
        "|h| is the slip range of the steady cycle.  Valid on b <= x <= a2 and in the stick "
        "zone; b is the consistent stick boundary of (17) for which (15) holds.",
        module="slip_displacement",
        returns="Slip displacement h [length].",
    )
    return d
