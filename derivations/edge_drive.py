"""The bulk tension's share of an edge's slip drive, tau, from (21); and eta back from tau.

On the proportional path (18) the shear multiplier is L_II = (lam + pi eta a/4) L_I (21).  At
load state 1 the edge's drive L_II1/(mu L_I1) -- the edge slips forward on loading when it
exceeds 1 -- is the sum of the shear force's share lam/mu and the bulk tension's share

    tau = pi eta a1/(4 mu),

the bracket of (28) and the r = rho + tau of the second-order slip zone
(``second_order_slip_zone.py``).  The error map (``asymslip.solver.error_map``) sets its cycles
out on (lam/mu, tau): it turns tau into the path slope eta for each cycle, and each edge's own
eta back into tau.  Both directions are derived here, the second by solving the first.
"""

from __future__ import annotations

import functools

import sympy

from asymslip.codegen import Argument, Derivation

from ._glossary import L_I, L_I1, a, a1, arguments, eta, lam, mu
from .section2_calibrations import shear_multiplier_proportional

tau = sympy.Symbol("tau", real=True)

SHARE = Argument(
    tau,
    "Bulk tension's share tau = pi eta a1/(4 mu) of the edge's slip drive L_II1/(mu L_I1) "
    "(dimensionless, either sign).",
)


@functools.cache
def tension_share() -> sympy.Expr:
    """tau: L_II1/(mu L_I1) from (21) at state 1, less the shear force's share lam/mu."""
    drive = shear_multiplier_proportional().subs({L_I: L_I1, a: a1}) / (mu * L_I1)
    return sympy.simplify(sympy.expand(drive) - lam / mu)


@functools.cache
def tension_slope_for_share() -> sympy.Expr:
    """eta for a given tau: the one solution of tau = tension_share() for eta."""
    (solution,) = sympy.solve(sympy.Eq(tau, tension_share()), eta)
    return sympy.simplify(solution)


def derive() -> Derivation:
    d = Derivation(__file__)
    d.describe_module(
        "edge_drive",
        "The bulk tension's share tau = pi eta a1/(4 mu) of an edge's slip drive "
        "L_II1/(mu L_I1), from the calibration (21), and the path slope eta for a given tau: "
        "the axes of the error map (beyond the paper).",
    )
    with d.equation("TS-1", "The tension's share of the slip drive") as eq:
        eq.beyond_paper(
            "(21) at state 1 divided by mu L_I1: L_II1/(mu L_I1) = lam/mu + tau; the shear "
            "force's share lam/mu taken away",
            derived=tension_share(),
        )
        eq.holds(
            tension_share() - sympy.pi * eta * a1 / (4 * mu),
            how="tau = pi eta a1/(4 mu), the tension term of (28)'s bracket",
        )
        eq.holds(
            sympy.simplify(tension_share().subs(eta, tension_slope_for_share()) - tau),
            how="eta from tau, solved, gives tau back",
        )
    d.emit(
        name="tension_share",
        args=arguments(eta, a1, mu),
        expr=tension_share(),
        equations=("21", "28", "TS-1"),
        summary="The bulk tension's share tau of an edge's slip drive L_II1/(mu L_I1).",
        doc="tau = pi eta a1/(4 mu): with the shear force's share lam/mu it makes up "
        "L_II1/(mu L_I1) of (21), which exceeds 1 when the edge slips forward on loading.  "
        "For the left-hand edge pass its own slope (eta is the same at both edges).",
        module="edge_drive",
        returns="tau (dimensionless).",
    )
    d.emit(
        name="tension_slope_for_share",
        args=(SHARE, *arguments(a1, mu)),
        expr=tension_slope_for_share(),
        equations=("21", "28", "TS-1"),
        summary="The path slope eta = dsigma/dP that gives the bulk tension's share tau.",
        doc="eta = 4 mu tau/(pi a1), the inverse of tension_share: the load path's tension "
        "slope (18) for which the tension supplies tau of the edge's slip drive "
        "L_II1/(mu L_I1).",
        module="edge_drive",
        returns="eta [1/length].",
    )
    return d
