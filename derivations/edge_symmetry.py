"""Both contact edges: the left-hand edge's problem mapped onto the paper's right-hand edge.

Mirror the plane, x' = -x.  Normal tractions keep their sign, tangential tractions change sign.
The full-stick shear traction of a bonded strip of half-width c under shear force Q and
differential bulk tension sigma is q = (Q/pi + sigma x/4) / sqrt(c^2 - x^2), the building block
of (20): the Q part is even in x, the sigma part odd.  In the mirrored frame the left edge
becomes a right edge whose shear traction is that of loads (-Q, +sigma), and the pressure
(even) is unchanged.  So the left edge is the paper's problem with lambda -> -lambda, eta -> eta.
"""

from __future__ import annotations

import sympy

from asymslip.codegen import Derivation

x, c = sympy.symbols("x c", real=True)
Q, sigma = sympy.symbols("Q sigma", real=True)


def bonded_strip_shear(position: sympy.Expr, shear: sympy.Expr, tension: sympy.Expr) -> sympy.Expr:
    """Full-stick shear traction of a bonded strip (the integrand of (20)'s superposition)."""
    return (shear / sympy.pi + tension * position / 4) / sympy.sqrt(c**2 - position**2)


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
    return d
