"""Both contact edges and both slip directions, mapped onto the paper's Section 2 problem.

Section 2 treats the right-hand edge with forward slip on loading, q2 = +mu p2 (8) and
q1 = -mu p1 (11).  Two symmetries carry every other case onto it:

* Mirror, x' = -x (E1): normal tractions keep their sign, tangential ones change sign.  The
  full-stick shear traction of a bonded strip, q = (Q/pi + sigma x/4)/sqrt(c^2 - x^2) -- the
  building block of (20) -- has an even Q part and an odd sigma part, so the left edge is a
  right edge loaded by (-Q, +sigma): lambda -> -lambda, eta -> eta.
* Reversal, q -> -q (E2): backward slip on loading (q2 = -mu p2, q1 = +mu p1) under loads
  (L_II1, L_II2) is forward slip under (-L_II1, -L_II2) with the dislocation traction negated:
  lambda -> -lambda, eta -> -eta.

Near the state-2 edge (a1 < x < a2) the state-1 traction is zero, so loading slips there iff
|L_II2| > mu L_I2: forward if L_II2 > mu L_I2, backward if L_II2 < -mu L_I2, none otherwise.
"""

from __future__ import annotations

import sympy

from asymslip.codegen import Derivation

from ._glossary import L_I1, L_I2, L_II1, L_II2, mu
from .section2_integral_equation import dislocations_12, edge1, edge2, integral_equation, q1

x, c = sympy.symbols("x c", real=True)
Q, sigma = sympy.symbols("Q sigma", real=True)


def bonded_strip_shear(position: sympy.Expr, shear: sympy.Expr, tension: sympy.Expr) -> sympy.Expr:
    """Full-stick shear traction of a bonded strip (the integrand of (20)'s superposition)."""
    return (shear / sympy.pi + tension * position / 4) / sympy.sqrt(c**2 - position**2)


def backward_slip_traction() -> sympy.Expr:
    """The dislocation traction (12) when loading slips backwards: (7) with q2 = -mu p2."""
    change_full_stick = L_II2 * edge2 - L_II1 * edge1
    loading = sympy.Eq(q1 + change_full_stick + dislocations_12, -mu * L_I2 * edge2)
    unloading = sympy.Eq(q1, mu * L_I1 * edge1)
    (solution,) = sympy.solve([loading, unloading], [dislocations_12, q1], dict=True)
    return sympy.expand(solution[dislocations_12])


def derive() -> Derivation:
    d = Derivation(__file__)
    with d.equation("E1", "Left edge = right edge with Q -> -Q, sigma -> sigma") as eq:
        eq.beyond_paper("the paper treats the right-hand edge only")
        seen_from_left = -bonded_strip_shear(-x, Q, sigma)  # mirrored position and component
        eq.holds(
            seen_from_left - bonded_strip_shear(x, -Q, sigma),
            how="mirroring x -> -x flips the tangential traction: the shear-force term (even "
            "in x) changes sign, the bulk-tension term (odd in x) does not; so at the left edge "
            "lambda -> -lambda and eta -> eta, and the pressure multiplier L_I is unchanged",
            derived=bonded_strip_shear(x, -Q, sigma),
        )
    with d.equation(
        "E2", "Backward slip = forward slip with L_II -> -L_II, traction negated"
    ) as eq:
        eq.beyond_paper("the paper's (8) and (11) assume forward slip on loading (lambda > mu)")
        forward_reversed = integral_equation().subs(
            {L_II1: -L_II1, L_II2: -L_II2}, simultaneous=True
        )
        eq.holds(
            backward_slip_traction() + forward_reversed,
            how="(12) with q2 = -mu p2, q1 = +mu p1 is minus (12) with L_II -> -L_II: the "
            "density and q_diff change sign, b is that of (lambda, eta) -> (-lambda, -eta)",
            derived=backward_slip_traction(),
        )
    return d
