"""Beyond the paper: how far each estimate of the stick boundary b is stated to be trusted.

Every estimate ``slip-zone`` reports carries a stated accuracy, an error scale in the order of
its neglected terms (w = a1 - b the slip-zone width, da = a2 - a1):

* b2, the headline second-order b (second_order_slip_zone.py): (da/a1)^2 |w|;
* (22), a formula right to second order: twice that, 2 (da/a1)^2 |w|;
* (28), (40) and (17) in an edge's own multipliers, first order: 2 (da/a1) |w|;
* a(P_K), exact for a symmetric law without bulk tension: 0.

Two estimates disagree when they differ by more than their two accuracies together (and a
rounding allowance of ``rounding`` a1).  The scales are in units of w because every estimate
is a series in dP whose terms all carry w's first-order factor a'(P1) (r - 1) dP/2
(r = (lam + pi eta a1/4)/mu); da/a1 = a'(P1) dP/a1 + O(dP^2) counts the orders.

**Checked against Hertz without tension**, where b = a(P_K) is exact (33)-(34): with
r = lam/mu and eps = dP/P1 the errors are, to leading order,

    b(exact) - b2   = -((r - 1)^2/8) (da/a1)^2 w,
    b(exact) - b22  = -(r (r + 1)/16) (da/a1)^2 w,
    b(exact) - b28  = -((r - 1)/4) (da/a1) w,
    b(exact) - b40  = -(((r - 1)^2 - 2)/(4 (r - 1))) (da/a1) w,

so the stated accuracies cover Hertz for |r - 1| <= 2 sqrt(2) (b2), r (r + 1) <= 32 ((22)),
r - 1 <= 8 ((28)) and 0.243 <= r - 1 <= 8.24 ((40): its error does not vanish with the width,
so it is relatively large where the slip zone is narrow).  Outside those ratios the estimate
disagrees with b and the slip-zone warnings say so; b2's own error stays a small part of the
width, |b(exact) - b2| / w = eq27^2 / 8 to leading order (eq27 = (da/a1) |r - 1| the
necessary condition (27)), and b_exact (computed there) disagrees with b beyond its
accuracy.  For other laws and with tension the constants were measured against the exact
steady-state conditions and the reference solver (README, "How far to trust b").
"""

from __future__ import annotations

import functools

import sympy

from asymslip.codegen import Argument, Derivation

from ._glossary import L_I1, L_I2, P1, a1, a2, arguments, da_dP, dP, eta, lam, mu
from .generic_law_comparison import d2a_dP2
from .second_order_slip_zone import other_edge, second_order_width
from .section2_calibrations import stick_boundary_proportional
from .section3_corrective_stick import hertz_stick_ratio_series
from .section3_exact_solution import eps, exact_stick_ratio

width = sympy.Symbol("width", real=True)
accuracy = sympy.Symbol("accuracy", nonnegative=True)
other_accuracy = sympy.Symbol("other_accuracy", nonnegative=True)
rounding = sympy.Symbol("rounding", nonnegative=True)
ratio = sympy.Symbol("r", positive=True)  # lam/mu without tension
relative_growth = sympy.Symbol("relative_growth", nonnegative=True)

#: da/a1 as one argument: (da/a1)^2 |w| printed as da**2 |w| / a1**2 would overflow at loads
#: where the accuracy itself is a double (a1 ~ 1e150).
RELATIVE_GROWTH = Argument(relative_growth, "da/a1, the contact growth over the cycle.")
WIDTH = Argument(width, "Slip-zone width a1 - b of the estimate b (either sign) [length].")
ACCURACY = Argument(accuracy, "Stated accuracy of b, the headline stick boundary [length].")
OTHER_ACCURACY = Argument(
    other_accuracy, "Stated accuracy of the other estimate compared with b [length]."
)
ROUNDING = Argument(
    rounding,
    "Rounding allowance relative to a1 (the core passes 1e-12): two estimates a few units in "
    "the last place apart do not disagree.",
)


def second_order_accuracy() -> sympy.Expr:
    """The stated accuracy of b2: (da/a1)^2 |w|."""
    return relative_growth**2 * sympy.Abs(width)


def paper_accuracy() -> sympy.Expr:
    """The stated accuracy of (22): twice b2's (a second-order formula)."""
    return 2 * second_order_accuracy()


def first_order_accuracy() -> sympy.Expr:
    """The stated accuracy of a first-order estimate: 2 (da/a1) |w|."""
    return 2 * relative_growth * sympy.Abs(width)


def disagreement_limit() -> sympy.Expr:
    """How far two estimates may lie apart: their accuracies added, and the rounding."""
    return accuracy + other_accuracy + rounding * a1


@functools.cache
def hertz_stick_ratios() -> dict[str, sympy.Expr]:
    """b/a1 of each estimate for Hertz without tension, as functions of eps = dP/P1 and r."""
    on_hertz = {
        eta: 0,
        lam: ratio * mu,
        other_edge: 1,  # without tension both edges slip the same way in the global frame
        da_dP: a1 / (2 * P1),  # a = sqrt(4 P R/(pi E*)): a' = a/(2P), a'' = -a/(4P^2)
        d2a_dP2: -a1 / (4 * P1**2),
    }
    second = 1 - second_order_width().subs(on_hertz).subs(dP, eps * P1) / a1
    # (22) with a2/a1 = sqrt(1 + eps) and L_I2/L_I1 = (1 + eps)^(1/4) ((31): L_I ~ sqrt(a)).
    paper = stick_boundary_proportional().subs(
        {
            eta: 0,
            lam: ratio * mu,
            a2: a1 * sympy.sqrt(1 + eps),
            L_I2: L_I1 * (1 + eps) ** sympy.Rational(1, 4),
        }
    )
    return {
        "exact": exact_stick_ratio().subs(lam, ratio * mu),
        "b2": sympy.expand(second),
        "b(22)": sympy.simplify(paper / a1),
        "b(28)": 1 - (ratio - 1) * eps / 4,  # (45)
        "b(40)": hertz_stick_ratio_series(2).subs({eta: 0, lam: ratio * mu}),
    }


def _leading(expr: sympy.Expr, order: int) -> sympy.Expr:
    """The eps^order coefficient of expr's series (asserting nothing of lower order)."""
    series = sympy.expand(sympy.series(expr, eps, 0, order + 1).removeO())
    for lower in range(order):
        assert sympy.simplify(series.coeff(eps, lower)) == 0, (expr, lower)
    return sympy.factor(series.coeff(eps, order))


def hertz_error_coefficient(estimate: str, power: int) -> sympy.Expr:
    """C of b(exact) - b(estimate) = C (da/a1)^power w for Hertz without tension (leading)."""
    ratios = hertz_stick_ratios()
    growth = sympy.sqrt(1 + eps) - 1  # da/a1
    scale = growth**power * (1 - ratios["b2"])  # (da/a1)^power w / a1
    order = power + 1
    return sympy.factor(
        _leading(ratios["exact"] - ratios[estimate], order) / _leading(scale, order)
    )


def derive() -> Derivation:
    d = Derivation(__file__)
    d.describe_module(
        "stated_accuracy",
        "Beyond the paper: the stated accuracy of each estimate of the stick boundary, and how "
        "far two estimates may lie apart before they disagree.",
    )
    expected = {
        ("b2", 2): -((ratio - 1) ** 2) / 8,
        ("b(22)", 2): -ratio * (ratio + 1) / 16,
        ("b(28)", 1): -(ratio - 1) / 4,
        ("b(40)", 1): -((ratio - 1) ** 2 - 2) / (4 * (ratio - 1)),
    }
    with d.equation("X-acc", "Stated accuracies of the estimates of b") as eq:
        eq.beyond_paper(
            "b2: (da/a1)^2 |a1 - b|; (22): twice that; (28), (40), (17) in own multipliers: "
            "2 (da/a1) |a1 - b|; a(P_K): exact.  Two estimates disagree beyond the sum of their "
            "accuracies (and 1e-12 a1).  Hertz without tension (exact b = a(P_K)), r = lam/mu: "
            "b(exact) - b = C (da/a1)^k (a1 - b) with C = -(r - 1)^2/8 (b2), -r (r + 1)/16 "
            "((22)), -(r - 1)/4 ((28)), -((r - 1)^2 - 2)/(4 (r - 1)) ((40)): covered by the "
            "stated accuracies for |r - 1| <= 2 sqrt(2), r (r + 1) <= 32, r - 1 <= 8 and "
            "0.243 <= r - 1 <= 8.24; outside, the estimate disagrees with b (a warning)",
            derived=second_order_accuracy(),
        )
        for (estimate, power), value in expected.items():
            eq.holds(
                hertz_error_coefficient(estimate, power) - value,
                how=f"Hertz, eta = 0: b(exact) - {estimate} = ({value}) (da/a1)^{power} "
                "(a1 - b) to leading order in dP",
            )
    common = (RELATIVE_GROWTH,)
    d.emit(
        name="stick_boundary_accuracy",
        args=(*common, WIDTH),
        expr=second_order_accuracy(),
        equations=("28",),
        summary="Stated accuracy of the headline b (b2): (da/a1)^2 |a1 - b|.",
        doc="b2 is exact to second order in dP; its error is of third order, which (da/a1)^2 "
        "times the width counts.  For Hertz without tension the error is (r - 1)^2/8 times "
        "this (r = lam/mu), so it covers |r - 1| <= 2 sqrt(2); beyond, the exact a(P_K) "
        "disagrees with b and a warning says so.",
        module="stated_accuracy",
        returns="The accuracy [length].",
    )
    d.emit(
        name="paper_stick_boundary_accuracy",
        args=(*common, WIDTH),
        expr=paper_accuracy(),
        equations=("22",),
        summary="Stated accuracy of (22): 2 (da/a1)^2 |a1 - b|, twice b2's.",
        doc="(22) is right to second order in dP without bulk tension for Hertz (third-order "
        "error r (r + 1)/16 (da/a1)^2 |a1 - b|, r = lam/mu); with tension its dP^2 term is "
        "spurious (erratum 22-T) and it disagrees with b beyond this.",
        module="stated_accuracy",
        returns="The accuracy [length].",
    )
    d.emit(
        name="stick_boundary_accuracy_first_order",
        args=(*common, WIDTH),
        expr=first_order_accuracy(),
        equations=("28", "40"),
        summary="Stated accuracy of a first-order b ((28), (40)): 2 (da/a1) |a1 - b|.",
        doc="A first-order estimate errs at second order in dP, which (da/a1) times the width "
        "counts; for Hertz without tension (28) errs by (r - 1)/4 times (da/a1) |a1 - b| (r = "
        "lam/mu), so the factor 2 covers r - 1 <= 8, and (40) by ((r - 1)^2 - 2)/(4 (r - 1)) "
        "times it (covered for 0.243 <= r - 1 <= 8.24).  Also the accuracy of (17) in an "
        "edge's own multipliers (a calibrated or asymmetric contact).",
        module="stated_accuracy",
        returns="The accuracy [length].",
    )
    d.emit(
        name="disagreement_limit",
        args=(ACCURACY, OTHER_ACCURACY, *arguments(a1), ROUNDING),
        expr=disagreement_limit(),
        equations=("22", "28", "40"),
        summary="How far an estimate may lie from b before the two disagree.",
        doc="The two stated accuracies added, and a rounding allowance of rounding a1: an "
        "estimate farther from b than this disagrees with it beyond what either claims.",
        module="stated_accuracy",
        returns="The largest difference that is no disagreement [length].",
    )
    return d
