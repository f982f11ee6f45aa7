"""Symbols shared by the derivations, each with its meaning stated once.

Generated functions take their parameters from here, so a parameter means the same thing (and
is documented the same way) in every generated module.
"""

from __future__ import annotations

import sympy

from asymslip.codegen import Argument

_positive = {"positive": True}
_real = {"real": True}

mu = sympy.Symbol("mu", **_positive)
lam = sympy.Symbol("lam", **_real)
eta = sympy.Symbol("eta", **_real)
a = sympy.Symbol("a", **_positive)
a1 = sympy.Symbol("a1", **_positive)
a2 = sympy.Symbol("a2", **_positive)
da = sympy.Symbol("da", **_positive)
b = sympy.Symbol("b", **_positive)
x = sympy.Symbol("x", **_real)
E_star = sympy.Symbol("E_star", **_positive)
L_I = sympy.Symbol("L_I", **_positive)
L_I1 = sympy.Symbol("L_I1", **_positive)
L_I2 = sympy.Symbol("L_I2", **_positive)
L_II1 = sympy.Symbol("L_II1", **_real)
L_II2 = sympy.Symbol("L_II2", **_real)
P1 = sympy.Symbol("P1", **_positive)
dP = sympy.Symbol("dP", **_positive)
da_dP = sympy.Symbol("da_dP", **_positive)
dL_I_dP = sympy.Symbol("dL_I_dP", **_real)
dP_da = sympy.Symbol("dP_da", **_positive)
dQ_da = sympy.Symbol("dQ_da", **_real)
dsigma_da = sympy.Symbol("dsigma_da", **_real)

MEANINGS: dict[sympy.Symbol, str] = {
    mu: "Coefficient of friction, mu > 0.",
    lam: "Load-path slope lambda = dQ/dP (18), either sign.",
    eta: "Load-path slope eta = dsigma/dP (18), either sign [1/length].",
    a: "Contact half-width at the load state considered [length].",
    a1: "Contact half-width a(P1) at load state 1 [length].",
    a2: "Contact half-width a(P2) at load state 2, a2 > a1 [length].",
    da: "Growth of the contact half-width a2 - a1 > 0, passed in directly so that callers who "
    "know it accurately keep every digit [length].",
    b: "Stick-slip boundary (distance from the contact centre), b < a1 [length].",
    x: "Position along the interface, measured from the contact centre [length].",
    E_star: "Plane-strain contact modulus E* [force/length^2].",
    L_I: "Normal edge multiplier L_I of the contact pressure p = L_I sqrt(a - x) (4) "
    "[force/length^(5/2)].",
    L_I1: "Normal edge multiplier L_I at load state 1 (4) [force/length^(5/2)].",
    L_I2: "Normal edge multiplier L_I at load state 2 (4) [force/length^(5/2)].",
    L_II1: "Shear edge multiplier L_II at load state 1 (5), either sign [force/length^(5/2)].",
    L_II2: "Shear edge multiplier L_II at load state 2 (5), either sign [force/length^(5/2)].",
    P1: "Normal load at load state 1 [force/length].",
    dP: "Normal-load change P2 - P1 > 0 [force/length].",
    da_dP: "Slope a'(P) of the contact law [length^2/force].",
    dL_I_dP: "Slope L_I'(P) of the normal edge multiplier with load.",
    dP_da: "Slope dP/da of the contact law, > 0 for an incomplete contact [force/length^2].",
    dQ_da: "Slope dQ/da of the shear force along the load path [force/length^2].",
    dsigma_da: "Slope dsigma/da of the differential bulk tension along the load path "
    "[force/length^3].",
}


def arguments(*symbols: sympy.Symbol) -> tuple[Argument, ...]:
    """Generated-function parameters, in the given order, documented from :data:`MEANINGS`."""
    return tuple(Argument(symbol, MEANINGS[symbol]) for symbol in symbols)
