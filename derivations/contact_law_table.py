"""A contact law tabulated from a finite-element model, fitted in log-log form (beyond the paper).

The table law fits s(u) = log a as a smooth function of u = log P (a straight line for every
power law a ~ P^k).  The paper's method needs L_I of (19) and, for the validity measure (26),
its slope dL_I/dP; both follow from (19) with dP/da = 1/a'(P) and a'(P) = (a/P) s'(u):

    L_I = (1/pi) sqrt(2/a) P / (a s'),    dL_I/dP = (L_I/P) (1 - 3 s'/2 - s''/s').

The second is derived here (not typed into the table law): differentiate (19) along the
fitted curve with s an undefined function of u.  For a power law (s'' = 0, s' = k) it gives
(1 - 3k/2) L_I/P, which for Hertz (k = 1/2) is the L_I/(4P) of Section 3.
"""

from __future__ import annotations

import functools

import sympy

from asymslip.codegen import Argument, Derivation

from ._glossary import L_I, a, dP_da
from .section2_calibrations import normal_multiplier

u = sympy.Symbol("u", real=True)  # log P
_s = sympy.Function("s")  # log a as a function of log P
P = sympy.Symbol("P", positive=True)
ds = sympy.Symbol("ds", positive=True)  # s'(u) > 0: the fitted law increases
d2s = sympy.Symbol("d2s", real=True)

ARGUMENTS = (
    Argument(P, "Normal load P > 0 [force/length]."),
    Argument(L_I, "Normal edge multiplier L_I at this load (4), (19) [force/length^(5/2)]."),
    Argument(ds, "Slope s'(u) = d(log a)/d(log P) of the fitted law at this load, > 0."),
    Argument(d2s, "Curvature s''(u) = d^2(log a)/d(log P)^2 of the fitted law at this load."),
)


@functools.cache
def multiplier_along_fit() -> sympy.Expr:
    """(19) with a = e^s(u) and dP/da = 1/a'(P) = P/(a s'(u)), P = e^u."""
    half_width = sympy.exp(_s(u))
    slope = sympy.exp(u) / (half_width * sympy.diff(_s(u), u))
    return normal_multiplier().subs({dP_da: slope}).subs(a, half_width)


@functools.cache
def multiplier_slope_in_fit() -> sympy.Expr:
    """dL_I/dP = (dL_I/du)/P, written in L_I, P, s' and s''."""
    multiplier = multiplier_along_fit()
    slope = sympy.diff(multiplier, u) / sympy.exp(u)
    ratio = sympy.simplify(slope / multiplier * sympy.exp(u))  # P dL_I/dP / L_I
    ratio = ratio.subs(sympy.Derivative(_s(u), (u, 2)), d2s).subs(sympy.Derivative(_s(u), u), ds)
    assert not ratio.has(_s), ratio
    return sympy.expand(ratio) * L_I / P


def derive() -> Derivation:
    d = Derivation(__file__)
    d.describe_module(
        "table_law",
        "Beyond the paper: the edge multiplier's slope of a contact law tabulated (from a "
        "finite-element model) and fitted as log a against log P.",
    )
    with d.equation("19", "Slope of L_I for a law fitted in log-log form") as eq:
        derived = multiplier_slope_in_fit()
        eq.holds(
            derived - L_I / P * (1 - sympy.Rational(3, 2) * ds - d2s / ds),
            how="(19) differentiated along log a = s(log P): dL_I/dP = (L_I/P)(1 - 3s'/2 - s''/s')",
        )
        k = sympy.Symbol("k", positive=True)
        eq.holds(
            derived.subs({ds: sympy.Rational(1, 2), d2s: 0}) - L_I / (4 * P),
            how="a power law a ~ P^(1/2) (Hertz): L_I/(4P), as Section 3 states",
        )
        eq.beyond_paper(
            "for a power law a ~ P^k the slope is (1 - 3k/2) L_I/P",
            derived=derived.subs({ds: k, d2s: 0}),
        )
    d.emit(
        name="normal_edge_multiplier_slope_loglog",
        args=ARGUMENTS,
        expr=multiplier_slope_in_fit(),
        equations=("19", "26"),
        summary="Slope dL_I/dP of the normal edge multiplier of a law fitted as log a(log P).",
        doc="(19) differentiated along the fitted curve s(u) = log a, u = log P.  Enters the "
        "validity measure (26).  Valid where the fit increases (s' > 0).",
        module="table_law",
        returns="dL_I/dP [1/length^(3/2)].",
    )
    return d
