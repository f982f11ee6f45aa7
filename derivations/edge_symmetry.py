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
(E3) derives this from the full-stick change (6) against the friction limits (8)/(11) and emits
it branch-free, with sign() alone: its NumPy, math, C, Fortran and MATLAB forms give exactly
+1, -1 or 0, with no slip at either equality.
"""

from __future__ import annotations

import sympy

from asymslip.codegen import Derivation

from ._glossary import L_I1, L_I2, L_II1, L_II2, a1, arguments, da, mu
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


def slip_direction() -> sympy.Expr:
    """+1, -1 or 0 from the signs of the two margins of (E3), branch-free.

    u = L_II2 - mu L_I2 > 0 slips forward, v = L_II2 + mu L_I2 < 0 backward (v >= u, so at
    most one holds); (sign(u) + |sign(u)|)/2 is 1 for u > 0 and 0 otherwise, (|sign(v)| -
    sign(v))/2 is 1 for v < 0 and 0 otherwise.
    """
    forward = sympy.sign(L_II2 - mu * L_I2)
    backward = sympy.sign(L_II2 + mu * L_I2)
    return (forward + sympy.Abs(forward) + backward - sympy.Abs(backward)) / 2


def _slip_direction_cases() -> list[tuple[sympy.Expr, int, str]]:
    """(L_II2, expected direction, case): every region of (E3) and both equalities."""
    gap = sympy.Symbol("g", positive=True)  # a strictly positive amount
    share = sympy.Symbol("k", positive=True)  # |L_II2| = mu L_I2 / (1 + k) < mu L_I2
    inside = mu * L_I2 / (1 + share)
    return [
        (mu * L_I2 + gap, 1, "L_II2 > mu L_I2: forward"),
        (-mu * L_I2 - gap, -1, "L_II2 < -mu L_I2: backward"),
        (inside, 0, "0 < L_II2 < mu L_I2: stick"),
        (-inside, 0, "-mu L_I2 < L_II2 < 0: stick"),
        (sympy.Integer(0), 0, "L_II2 = 0: stick"),
        (mu * L_I2, 0, "L_II2 = mu L_I2: at the limit, no slip"),
        (-mu * L_I2, 0, "L_II2 = -mu L_I2: at the limit, no slip"),
    ]


def derive() -> Derivation:
    d = Derivation(__file__)
    d.describe_module(
        "edge_symmetry",
        "Which way a contact edge slips on loading (beyond the paper, which assumes forward "
        "slip at the right-hand edge): derivations/edge_symmetry.py.",
    )
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
    with d.equation("E3", "Slip direction on loading: the sign of L_II2 against mu L_I2") as eq:
        eq.beyond_paper("the paper assumes forward slip on loading at the right-hand edge")
        # In a1 < x < a2 the edge is in contact at state 2 only: (6) with H(a1 - x) = 0 is the
        # whole state-2 traction under full stick, and (8)/(11) bound it by mu p2 either way.
        # A point of the annulus, a1 < x = a1 + s da < a2 (0 < s < 1 from k > 0).
        share = sympy.Symbol("k", positive=True)
        position = a1 + da / (1 + share)
        depth = sympy.sqrt(a1 + da - position)  # sqrt(a2 - x) of (4), (5)
        full_stick = L_II2 * depth - L_II1 * sympy.Heaviside(a1 - position) * depth  # (6)
        limit = mu * L_I2 * depth  # mu p2, (4) and (8)
        eq.holds(
            sympy.factor(full_stick - limit) / depth - (L_II2 - mu * L_I2),
            how="in a1 < x < a2 the full-stick q2 - mu p2 is (L_II2 - mu L_I2) sqrt(a2 - x): "
            "loading slips forward (q2 would pass +mu p2, (8)) iff L_II2 > mu L_I2",
        )
        eq.holds(
            sympy.factor(full_stick + limit) / depth - (L_II2 + mu * L_I2),
            how="and backward (q2 would pass -mu p2, (11) reversed by E2) iff L_II2 < -mu L_I2",
        )
        direction = slip_direction()
        for value, expected, case in _slip_direction_cases():
            eq.holds(
                direction.subs(L_II2, value) - expected,
                how=f"the branch-free form gives {expected:+d} for {case}",
                derived=direction,
            )
    d.emit(
        name="slip_direction",
        args=arguments(mu, L_I2, L_II2),
        expr=slip_direction(),
        equations=("8", "11"),
        summary="Slip direction of an edge on loading: +1 forward, -1 backward, 0 none.",
        doc="Near the state-2 edge (a1 < x < a2) the state-1 traction is zero, so loading from "
        "full stick slips there iff |L_II2| > mu L_I2: forward (q2 = +mu p2, (8)) if L_II2 > "
        "mu L_I2, backward if L_II2 < -mu L_I2, none otherwise (no slip at either equality).  "
        "In the edge's own frame (the left edge sees lambda -> -lambda, edge_symmetry E1).  "
        "Branch-free: signs only, exactly +1.0, -1.0 or 0.0.",
        module="edge_symmetry",
        returns="+1.0, -1.0 or 0.0.",
    )
    return d
