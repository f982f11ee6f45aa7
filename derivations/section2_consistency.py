"""Eqs. (16)-(17): the consistency condition and the stick boundary b it fixes.

(16) is the condition for the bounded-at-both-ends inverse of (12) to exist: the integrals are
the weight integral of section2_hilbert_identity scaled onto (b, a1) and (b, a2).  Solving the
linear condition for b gives (17).
"""

from __future__ import annotations

import functools

import sympy

from asymslip.codegen import Derivation

from ._glossary import L_I1, L_I2, L_II1, L_II2, a1, a2, arguments, b, mu
from .section2_hilbert_identity import beta, weight_integral


def scaled_weight_integral(lower: sympy.Expr, top: sympy.Expr) -> sympy.Expr:
    """int_lower^top sqrt((top - t)/(t - lower)) dt, by t = top * tau from the unit form."""
    return sympy.simplify(top * weight_integral().subs(beta, lower / top))


# The two load coefficients of (12), kept as symbols while solving so that the root keeps the
# structure (C2 a2 + C1 a1)/(C2 + C1): four array operations at run time instead of a dozen.
coefficient1, coefficient2 = sympy.symbols("C_1 C_2", real=True)


def load_coefficients() -> dict[sympy.Symbol, sympy.Expr]:
    """C1 = mu L_I1 + L_II1 and C2 = mu L_I2 - L_II2, the coefficients in (12) and (16)."""
    return {coefficient1: mu * L_I1 + L_II1, coefficient2: mu * L_I2 - L_II2}


@functools.cache
def consistency_condition() -> sympy.Expr:
    """Right side of (16), as a function of the stick boundary b."""
    return coefficient1 * scaled_weight_integral(b, a1) + coefficient2 * scaled_weight_integral(
        b, a2
    )


@functools.cache
def stick_boundary_in_coefficients() -> sympy.Expr:
    """(17) in terms of C1, C2: the root of (16) in b."""
    (root,) = sympy.solve(consistency_condition(), b)
    return sympy.factor(root)


@functools.cache
def stick_boundary() -> sympy.Expr:
    """(17) in terms of the edge multipliers."""
    return stick_boundary_in_coefficients().subs(load_coefficients())


def derive() -> Derivation:
    d = Derivation(__file__)
    d.describe_module(
        "corrective_slip",
        "Section 2 of the paper: the corrective-slip (glide dislocation) solution at a contact "
        "edge -- stick boundary, slip-zone width and dislocation density.",
    )
    with d.equation("16", "Consistency condition of the bounded inversion") as eq:
        eq.matches_paper(
            scaled_weight_integral(b, a1),
            sympy.pi * (a1 - b) / 2,
            how="weight integral pi (a - b)/2 from the rationalising substitution, scaled",
            printed=r"\int_b^{a}\sqrt{\frac{a-t}{t-b}}\,dt = \frac{\pi (a-b)}{2}",
        )
    with d.equation("17", "Stick boundary b from the consistency condition") as eq:
        derived = stick_boundary()
        coefficient1, coefficient2 = mu * L_I1 + L_II1, mu * L_I2 - L_II2
        paper = (coefficient2 * a2 + coefficient1 * a1) / (coefficient2 + coefficient1)
        eq.matches_paper(
            derived,
            paper,
            how="solved (16) for b (linear)",
            printed=r"\frac{(\mu L_{I,2}-L_{II,2})a_2+(\mu L_{I,1}+L_{II,1})a_1}"
            r"{(\mu L_{I,2}-L_{II,2})+(\mu L_{I,1}+L_{II,1})}",
        )
    d.emit(
        name="stick_boundary",
        args=arguments(mu, a1, a2, L_I1, L_I2, L_II1, L_II2),
        expr=stick_boundary(),
        equations=("16", "17"),
        summary="Stick-slip boundary b of the steady-state cycle from the edge multipliers.",
        doc="The root of the consistency condition (16) of the bounded inversion of (12): the "
        "slip zone is b < x < a2 at both ends of the cycle.  Valid when the asymptotes (4)-(5) "
        "hold, i.e. a2 - a1 and a1 - b are small compared with a1 (Section 2.2), and when the "
        "denominator mu (L_I1 + L_I2) + L_II1 - L_II2 is not zero.",
        module="corrective_slip",
        returns="Stick boundary b, same units as a1.",
    )
    return d
