"""Eqs. (1)-(12): the load cycle, the full-stick traction changes and the integral equation.

(12) is derived, not assumed: the slip conditions (8) and (11) and the annihilation condition
B^{2->1} = -B^{1->2} are substituted into the superpositions (7) and (10), with the dislocation
traction integral kept as an opaque symbol.  (10) then holds identically, which is the paper's
claim that one equation serves both halves of the cycle.
"""

from __future__ import annotations

import functools

import sympy

from asymslip.codegen import Derivation

from ._glossary import L_I1, L_I2, L_II1, L_II2, mu

# sqrt(a2 - x) and H(a1 - x) sqrt(a1 - x) as opaque, non-negative shape functions.
edge2 = sympy.Symbol("s_2", nonnegative=True)
edge1 = sympy.Symbol("s_1", nonnegative=True)
# Traction of the dislocations inserted on loading (1->2) and on unloading (2->1).
dislocations_12, dislocations_21 = sympy.symbols("D_12 D_21", real=True)
q1 = sympy.Symbol("q_1", real=True)


@functools.cache
def integral_equation() -> sympy.Expr:
    """Right side of (12): the traction the loading dislocations must supply in the slip zone."""
    change_full_stick = L_II2 * edge2 - L_II1 * edge1  # (6), from (5) at both ends
    q2_superposed = q1 + change_full_stick + dislocations_12  # (7)
    slip_on_loading = sympy.Eq(q2_superposed, mu * L_I2 * edge2)  # (8)
    slip_on_unloading = sympy.Eq(q1, -mu * L_I1 * edge1)  # (11)
    solution = sympy.solve([slip_on_loading, slip_on_unloading], [dislocations_12, q1], dict=True)
    (solution,) = solution
    return sympy.expand(solution[dislocations_12])


def derive() -> Derivation:
    d = Derivation(__file__)
    given = {
        "1": "Shear traction of a glide-dislocation array on a bonded half-line [8]",
        "2": "Proportional load path between load states 1 and 2",
        "3": "Load changes dP, dQ, dsigma",
        "5": "First-order edge asymptote of the full-stick shear traction, q = L_II sqrt(a - x)",
        "7": "Superposition on loading: full-stick change plus the dislocation traction",
        "8": "Slip condition on loading, q2 = mu p2 in b < x < a2",
        "10": "Superposition on unloading",
        "11": "Slip condition on unloading, q1 = -mu p1 in b < x < a2",
        "18": "Load-path slopes lambda = dQ/dP and eta = dsigma/dP",
    }
    for number, title in given.items():
        with d.equation(number, title) as eq:
            eq.given("model statement taken from the paper (used by the derivations below)")

    with d.equation("6", "Change of shear traction under full stick, 1 -> 2") as eq:
        eq.given("difference of (5) at load states 2 and 1; q1 = 0 beyond a1 (the H factor)")
    with d.equation("9", "Change of shear traction under full stick, 2 -> 1") as eq:
        eq.given("the negative of (6): the same path run backwards")
    with d.equation("12", "Singular integral equation for the loading dislocations") as eq:
        derived = integral_equation()
        paper = (mu * L_I1 + L_II1) * edge1 + (mu * L_I2 - L_II2) * edge2
        eq.matches_paper(
            derived,
            paper,
            how="solved (7), (8), (11) for the dislocation traction",
            printed=r"(\mu L_{I,1}+L_{II,1})H(a_1-x)\sqrt{a_1-x}"
            r"+(\mu L_{I,2}-L_{II,2})\sqrt{a_2-x}",
        )
        # With annihilation D_21 = -D_12, (10) must then hold identically on the slip zone.
        q2 = mu * L_I2 * edge2
        unloading = q2 - (L_II2 * edge2 - L_II1 * edge1) + (-dislocations_12)
        eq.holds(
            (unloading - (-mu * L_I1 * edge1)).subs(dislocations_12, derived),
            how="(10) with B^{2->1} = -B^{1->2} is then satisfied identically",
        )
    return d
