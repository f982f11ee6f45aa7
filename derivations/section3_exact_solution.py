"""Section 3.1, Eqs. (33)-(36): the exact Hertz stick zone of Jaeger and Ciavarella.

(33) is taken from [2]: on a loop in (P, Q)-space enclosed by two lines of slope +-mu, the
permanent stick zone of a Hertzian contact is the contact of the normal load P_K at their
intersection.  On the proportional path of (18) with eta = 0, P2 = P1 + dP and
Q2 - Q1 = lam dP, so P_K = P1 + dP (mu - lam) / (2 mu).  The stick boundary is then b = a(P_K)
from the Hertz law (29); b exists only while P_K > 0 (for P_K <= 0 the loop is not enclosed by
the friction lines and the contact slides: no steady partial slip).

(33) puts load state 1 on the line of slope -mu and state 2 on the line of slope +mu, which is
the enclosing pair when lam >= mu: the paper's case, with forward slip at the right-hand edge
during loading as in (8).  For |lam| < mu the enclosing wedge has its apex at state 1, so the
true P_K is P1 and b = a1 (no slip inside a1); the formula then gives b > a1 and a negative
width, the same sign convention as the asymptotic results (22) and (41).

Because a^2 is affine in P for Hertz, a1^2 - b^2 is a plain product in dP, and the slip-zone
width a1 - b = (a1^2 - b^2) / (a1 + b) is free of cancellation however small dP/P1 is.
"""

from __future__ import annotations

import functools

import sympy

from asymslip.codegen import Argument, Derivation

from ._glossary import P1, dP, lam, mu
from .contact_law_hertz import LOAD1, LOAD_CHANGE, MODULUS, RADIUS, E_star, P, R, hertz_half_width

# End points of the load path in (P, Q)-space, for (33)-(34) in the paper's own variables.
P2 = sympy.Symbol("P2", positive=True)
Q1, Q2 = sympy.symbols("Q1 Q2", real=True)
# Relative load change dP/P1, the expansion variable of (30), (36) and the agreement study.
eps = sympy.Symbol("epsilon", positive=True)

FRICTION = Argument(mu, "Coefficient of friction, mu > 0.")
SLOPE = Argument(lam, "Load-path slope lambda = dQ/dP (18), either sign.")
HERTZ_ARGS = (LOAD1, LOAD_CHANGE, SLOPE, FRICTION, RADIUS, MODULUS)


def paper_permanent_stick_load() -> sympy.Expr:
    """(33) as printed: P_K = (P1 + P2)/2 - (Q2 - Q1)/(2 mu), the starting point from [2]."""
    return (P1 + P2) / 2 - (Q2 - Q1) / (2 * mu)


@functools.cache
def permanent_stick_load() -> sympy.Expr:
    """(33) on the proportional path (18): P2 = P1 + dP, Q2 - Q1 = lam dP."""
    on_path = paper_permanent_stick_load().subs({P2: P1 + dP, Q2: Q1 + lam * dP})
    return sympy.collect(sympy.expand(on_path), dP, sympy.factor)


@functools.cache
def exact_stick_boundary() -> sympy.Expr:
    """(34): b = a(P_K), the Hertz half-width at the permanent-stick load."""
    return hertz_half_width().subs(P, permanent_stick_load())


@functools.cache
def exact_slip_zone_width() -> sympy.Expr:
    """a1 - b as (a1^2 - b^2)/(a1 + b): the numerator is a product, not a difference."""
    a1_hertz = hertz_half_width().subs(P, P1)
    squares = sympy.factor(sympy.expand(a1_hertz**2 - exact_stick_boundary() ** 2))
    assert not squares.has(P1), "a1^2 - b^2 must be proportional to dP alone"
    return squares / (a1_hertz + exact_stick_boundary())


@functools.cache
def exact_stick_ratio() -> sympy.Expr:
    """b / a1 as a function of eps = dP/P1 (P1, R and E* cancel)."""
    # With dP = eps P1 the load P_K is P1 times a factor, and sqrt(P1 * factor) splits.
    scaled_load = sympy.factor(permanent_stick_load().subs(dP, eps * P1))
    ratio = hertz_half_width().subs(P, scaled_load) / hertz_half_width().subs(P, P1)
    assert ratio.free_symbols <= {eps, lam, mu}, ratio
    return ratio


@functools.cache
def exact_stick_ratio_series(order: int) -> sympy.Expr:
    """The series of b/a1 in eps = dP/P1 through eps**order."""
    return sympy.series(exact_stick_ratio(), eps, 0, order + 1).removeO()


def derive() -> Derivation:
    d = Derivation(__file__)
    d.describe_module(
        "exact_solution",
        "Section 3.1 of the paper: the exact steady-state stick zone of a Hertzian contact on "
        "a proportional (P, Q) load path, from the Jaeger-Ciavarella construction [2].",
    )
    a1_hertz = hertz_half_width().subs(P, P1)
    with d.equation("33", "Permanent-stick load P_K (Jaeger-Ciavarella)") as eq:
        eq.given(
            "from [2]: the friction lines of slope +-mu through load states 1 and 2 meet at "
            "abscissa P_K",
            derived=paper_permanent_stick_load(),
        )
        eq.holds(
            permanent_stick_load() - (P1 + dP * (mu - lam) / (2 * mu)),
            how="on the path (18) with eta = 0 (P2 = P1 + dP, Q2 - Q1 = lam dP): "
            "P_K = P1 + dP (mu - lam) / (2 mu)",
            derived=permanent_stick_load(),
        )
    with d.equation("34", "Exact Hertz stick boundary b = a(P_K)") as eq:
        eq.matches_paper(
            hertz_half_width().subs(P, paper_permanent_stick_load()) ** 2,
            2 * R / (sympy.pi * E_star) * (P1 + P2 - (Q2 - Q1) / mu),
            how="(33) substituted into the Hertz law (29)",
            printed=r"b^2=\frac{2R}{\pi E^*}\left(P_1+P_2-\frac{Q_2-Q_1}{\mu}\right)",
        )
    with d.equation("35", "b^2 in terms of a1 (exact for Hertz)") as eq:
        paper_35 = a1_hertz**2 * (1 + dP / (2 * mu * P1) * (mu - lam))
        residual = exact_stick_boundary() ** 2 - paper_35
        eq.holds(
            residual,
            how="b^2 - a1^2 (1 + dP (mu - lam)/(2 mu P1)) simplifies to 0 identically",
            derived=exact_stick_boundary() ** 2,
        )
        eq.erratum(
            "the paper derives (35) 'using the approximations (32)', but it is exact for Hertz: "
            "a^2 = 4PR/(pi E*) is affine in P, so b^2 - a1^2 (1 + dP (mu - lam)/(2 mu P1)) = 0 "
            "identically (checked symbolically, no smallness of dP/P1 used); only (36) "
            "approximates",
            derived=exact_stick_boundary() ** 2,
        )
    with d.equation("36", "Exact stick zone to first order in dP/P1") as eq:
        first = exact_stick_ratio_series(1).subs(eps, dP / P1)
        eq.matches_paper(
            first,
            1 - (lam / mu - 1) * dP / (4 * P1),
            how="series of b/a1 = sqrt(1 + eps (mu - lam)/(2 mu)) in eps = dP/P1",
            printed=r"\frac{b}{a_1}\approx 1-\left(\frac{\lambda}{\mu}-1\right)"
            r"\frac{1}{4}\frac{\Delta P}{P_1}",
        )
        eq.holds(
            exact_slip_zone_width() - (a1_hertz - exact_stick_boundary()),
            how="emitted width: a1 - a(P_K) = (a1^2 - b^2)/(a1 + b) with a1^2 - b^2 = "
            "2 R dP (lam - mu)/(pi E* mu), no difference of nearly equal numbers",
            derived=exact_slip_zone_width(),
        )

    validity = (
        "Valid for every dP > 0 while P_K = P1 + dP (mu - lam)/(2 mu) > 0; for P_K <= 0 the "
        "friction lines do not enclose the load path, the contact slides and no stick zone "
        "exists (the square root of P_K is then NaN, with NumPy's invalid-value warning)."
    )
    d.emit(
        name="permanent_stick_load",
        args=(LOAD1, LOAD_CHANGE, SLOPE, FRICTION),
        expr=permanent_stick_load(),
        equations=("33",),
        summary="Normal load P_K whose contact is the permanent stick zone (Jaeger-Ciavarella).",
        doc="(33) from [2] on the proportional path (18) with eta = 0: P2 = P1 + dP and "
        "Q2 - Q1 = lam dP.  A stick zone exists only when P_K > 0.",
        module="exact_solution",
        returns="P_K [force/length].",
    )
    d.emit(
        name="hertz_stick_boundary_exact",
        args=HERTZ_ARGS,
        expr=exact_stick_boundary(),
        equations=("33", "34", "35"),
        summary="Exact stick-slip boundary b = a(P_K) of the Hertzian contact.",
        doc="The Hertz half-width (29) at the permanent-stick load (33), eta = 0.  Partial "
        "slip inside a1 needs lam >= mu (for |lam| < mu the true stick zone is all of a1, while "
        f"this formula gives b > a1). {validity}",
        module="exact_solution",
        returns="b [length].",
    )
    d.emit(
        name="hertz_slip_zone_width_exact",
        args=HERTZ_ARGS,
        expr=exact_slip_zone_width(),
        equations=("34", "35", "36"),
        summary="Exact slip-zone width a1 - a(P_K) of the Hertzian contact, without cancellation.",
        doc="Written as (a1^2 - b^2)/(a1 + b) with a1^2 - b^2 = 2 R dP (lam - mu)/(pi E* mu), "
        "so it keeps full relative precision for any dP/P1 (e.g. 1e-10).  A partial-slip cycle "
        "at this edge needs lam >= mu; for lam < mu the formula gives a negative width (the "
        f"true stick zone is then all of a1). {validity}",
        module="exact_solution",
        returns="a1 - b [length].",
    )
    return d
