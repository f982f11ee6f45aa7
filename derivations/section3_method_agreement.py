"""Section 3.3, Eq. (45), and how far the three Hertz slip-zone predictions agree.

(45) is the corrective-slip first-order result (28) with the Hertz slope a'(P) = a/(2P).

Beyond the paper: for Hertz with eta = 0 the stick ratio b/a1 of
  (i)   the exact solution a(P_K) of Section 3.1,
  (ii)  the corrective-slip boundary (22) with a2 = a(P1 + dP) and L_I from (31),
  (iii) the corrective-stick boundary (41),
is expanded to third order in eps = dP/P1, with r = lam/mu kept symbolic.  All three agree at
first order, as the paper shows.  (22) also agrees with the exact result at second order and
first differs at third; (41) already differs at second order.  The paper's Section 3.4 remark
that the asymptotic methods recover "the first term" of the exact slip-zone size is therefore
an understatement for the corrective-slip method.  The discrepancy coefficients are emitted so
that the report and the tests can use them.
"""

from __future__ import annotations

import functools

import sympy

from asymslip.codegen import Argument, Derivation

from ._glossary import L_I1, L_I2, P1, a1, a2, da_dP, dP, eta, lam, mu
from .contact_law_hertz import (
    LOAD1,
    LOAD_CHANGE,
    MODULUS,
    RADIUS,
    P,
    hertz_half_width,
    hertz_multiplier,
)
from .section2_calibrations import stick_boundary_proportional
from .section2_validity import first_order_slip_zone_width, first_order_stick_ratio
from .section3_corrective_stick import hertz_stick_ratio_series
from .section3_exact_solution import eps, exact_stick_ratio_series

ORDER = 3  # expansions through eps**3
# lam/mu and dP/P1 as the report writes them, for the readable formulas
ratio_symbol = sympy.Symbol("r", real=True)
eps_symbol = sympy.Symbol("eps", positive=True)

FRICTION = Argument(mu, "Coefficient of friction, mu > 0.")
SLOPE = Argument(lam, "Load-path slope lambda = dQ/dP (18), either sign.")
ETA = Argument(eta, "Load-path slope eta = dsigma/dP (18), either sign [1/length].")
HERTZ_ARGS = (LOAD1, LOAD_CHANGE, SLOPE, ETA, FRICTION, RADIUS, MODULUS)


def _on_hertz_law(expr: sympy.Expr) -> sympy.Expr:
    """Replace a1 and a'(P1) of a Section 2 result by the Hertz law (29)."""
    slope = sympy.diff(hertz_half_width(), P).subs(P, P1)
    return expr.subs({da_dP: slope}).subs({a1: hertz_half_width().subs(P, P1)})


@functools.cache
def hertz_first_order_width() -> sympy.Expr:
    """a1 - b of (28) for Hertz, as the product the Section 2 series gives."""
    return sympy.factor(_on_hertz_law(first_order_slip_zone_width()))


@functools.cache
def corrective_slip_ratio_series(order: int) -> sympy.Expr:
    """b/a1 of (22) for Hertz, eta = 0, as a series in eps = dP/P1."""
    # P2 = P1 (1 + eps): square roots of P1 (1 + eps) split, so P1, R and E* cancel.
    state1, state2 = P1, P1 * (1 + eps)
    hertz = {
        a1: hertz_half_width().subs(P, state1),
        a2: hertz_half_width().subs(P, state2),
        L_I1: hertz_multiplier().subs(P, state1),
        L_I2: hertz_multiplier().subs(P, state2),
    }
    boundary = stick_boundary_proportional().subs(eta, 0).subs(hertz, simultaneous=True)
    ratio = sympy.cancel(boundary / hertz[a1])
    assert ratio.free_symbols <= {eps, lam, mu}, ratio
    return sympy.series(ratio, eps, 0, order + 1).removeO()


@functools.cache
def discrepancies() -> dict[str, list[sympy.Expr]]:
    """Coefficients of eps**0..ORDER of (method - exact) b/a1, per method (eta = 0)."""
    exact = sympy.expand(exact_stick_ratio_series(ORDER))
    methods = {
        "corrective_slip": corrective_slip_ratio_series(ORDER),
        "corrective_stick": hertz_stick_ratio_series(ORDER).subs(eta, 0),
    }
    return {
        name: [sympy.factor(sympy.expand(series - exact).coeff(eps, k)) for k in range(ORDER + 1)]
        for name, series in methods.items()
    }


def _readable(expr: sympy.Expr) -> str:
    """A coefficient as a function of r = lam/mu, for the report."""
    return sympy.sstr(sympy.factor(sympy.expand(expr.subs(lam, ratio_symbol * mu))))


def derive() -> Derivation:
    d = Derivation(__file__)
    d.describe_module(
        "method_agreement",
        "Section 3.3 of the paper and beyond: the first-order Hertz slip zone common to the "
        "three methods, and the higher-order discrepancies of the corrective-slip (22) and "
        "corrective-stick (41) predictions from the exact solution (eta = 0).",
    )
    paper_45 = 1 - (lam / mu - 1) * dP / (4 * P1)
    with d.equation("45", "Corrective-slip stick ratio for Hertz, first order") as eq:
        derived_45 = sympy.expand(_on_hertz_law(first_order_stick_ratio()))
        eq.matches_paper(
            derived_45.subs(eta, 0),
            paper_45,
            how="(28) with the Hertz slope a'(P1) = a1/(2 P1) of (29), eta = 0",
            printed=r"\frac{b}{a_1}\approx 1-\left(\frac{\lambda}{\mu}-1\right)"
            r"\frac{\Delta P}{4P_1}",
        )
        eq.holds(
            paper_45 - exact_stick_ratio_series(1).subs(eps, dP / P1),
            how="equals the exact first-order result (36)",
        )
        eq.holds(
            paper_45 - hertz_stick_ratio_series(1).subs(eta, 0).subs(eps, dP / P1),
            how="equals the corrective-stick first-order result (44) at eta = 0",
        )
        eq.holds(
            derived_45 - _on_hertz_law(hertz_stick_ratio_series(1).subs(eps, dP / P1)),
            how="beyond the paper: with eta kept, (28) for Hertz equals (44) identically",
        )
        eq.holds(
            hertz_first_order_width() - hertz_half_width().subs(P, P1) * (1 - derived_45),
            how="emitted width a1 - b = a1 (lam/mu + pi eta a1/(4 mu) - 1) dP/(4 P1), a product",
            derived=hertz_first_order_width(),
        )

    exact = sympy.expand(exact_stick_ratio_series(ORDER))
    slip = discrepancies()["corrective_slip"]
    stick = discrepancies()["corrective_stick"]
    with d.equation("A1", "Exact Hertz stick ratio to third order in dP/P1") as eq:
        readable = sympy.collect(
            sympy.expand(exact.subs({lam: ratio_symbol * mu, eps: eps_symbol})),
            eps_symbol,
            sympy.factor,
        )
        eq.beyond_paper(
            "series of b/a1 = sqrt(1 + eps (1 - r)/2), eps = dP/P1, r = lam/mu: "
            f"{sympy.sstr(readable, order='rev-lex')} + O(eps^4)",
            derived=exact,
        )
    with d.equation("A2", "Corrective slip (22) vs exact: agree through second order") as eq:
        eq.beyond_paper(
            "(22) for Hertz (a2 = a(P1 + dP), L_I from (31), eta = 0) minus the exact b/a1: "
            f"b22/a1 - b_exact/a1 = ({_readable(slip[3])}) eps^3 + O(eps^4), r = lam/mu, "
            "eps = dP/P1; so (22) recovers the first two terms of the exact slip-zone size, and "
            "Section 3.4's remark that only the first term is recovered is an understatement",
            derived=slip[3],
        )
        eq.holds(
            slip[0] + slip[1] * eps + slip[2] * eps**2,
            how="the eps^0, eps^1 and eps^2 coefficients of the difference vanish identically "
            "in lam/mu (series of both to eps^3)",
        )
    with d.equation("A3", "Corrective stick (41) vs exact: differ at second order") as eq:
        assert slip[2] == 0 and stick[2] != 0
        eq.beyond_paper(
            "(41) for Hertz (eta = 0) minus the exact b/a1: b41/a1 - b_exact/a1 = "
            f"({_readable(stick[2])}) eps^2 + ({_readable(stick[3])}) eps^3 + O(eps^4), "
            "r = lam/mu: nonzero at second order for every r except 1 +- sqrt(2); the eps^3 "
            "coefficient is (4 - (1 - r)^3)/128",
            derived=sympy.Tuple(stick[2], stick[3]),
        )
        eq.holds(
            stick[0] + stick[1] * eps,
            how="the eps^0 and eps^1 coefficients of the difference vanish identically",
        )
        eq.holds(
            stick[3] - (4 - (1 - lam / mu) ** 3) / 128,
            how="the eps^3 coefficient equals (4 - (1 - r)^3)/128",
        )

    d.emit(
        name="hertz_slip_zone_width_first_order",
        args=HERTZ_ARGS,
        expr=hertz_first_order_width(),
        equations=("28", "36", "44", "45"),
        summary="First-order Hertz slip-zone width a1 - b, common to the three methods.",
        doc="(28) with a'(P) = a/(2P): a1 (lam/mu + pi eta a1/(4 mu) - 1) dP/(4 P1), identical "
        "to the corrective-stick (44) for any eta and to the exact (36) at eta = 0.  A product, "
        "so it keeps full relative precision for tiny dP/P1.",
        module="method_agreement",
        returns="a1 - b [length].",
    )
    d.emit(
        name="corrective_slip_discrepancy_third_order",
        args=(SLOPE, FRICTION),
        expr=slip[3],
        equations=("22", "36"),
        summary="eps^3 coefficient of (b22 - b_exact)/a1 for Hertz, eps = dP/P1, eta = 0.",
        doc="The corrective-slip boundary (22) (with a2 = a(P1 + dP) and L_I of (31)) agrees "
        "with the exact a(P_K) through eps^2; this is the first nonzero coefficient, "
        "r (r^2 - 1)/256 with r = lam/mu.  Beyond the paper.",
        module="method_agreement",
        returns="Dimensionless coefficient.",
    )
    d.emit(
        name="corrective_stick_discrepancy_second_order",
        args=(SLOPE, FRICTION),
        expr=stick[2],
        equations=("36", "41"),
        summary="eps^2 coefficient of (b41 - b_exact)/a1 for Hertz, eps = dP/P1, eta = 0.",
        doc="The first nonzero coefficient of the corrective-stick discrepancy, "
        "(r^2 - 2 r - 1)/32 with r = lam/mu.  Beyond the paper.",
        module="method_agreement",
        returns="Dimensionless coefficient.",
    )
    d.emit(
        name="corrective_stick_discrepancy_third_order",
        args=(SLOPE, FRICTION),
        expr=stick[3],
        equations=("36", "41"),
        summary="eps^3 coefficient of (b41 - b_exact)/a1 for Hertz, eps = dP/P1, eta = 0.",
        doc="(4 - (1 - r)^3)/128 with r = lam/mu.  Beyond the paper.",
        module="method_agreement",
        returns="Dimensionless coefficient.",
    )
    return d
