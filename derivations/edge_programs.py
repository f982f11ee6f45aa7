"""The slip-zone core's arithmetic as programs: one contact edge, and a Hertzian cycle's state.

Nothing new is derived here.  The slip-zone core (``asymslip.core``) evaluates, for every edge
of every cycle, the same sequence of formulas derived elsewhere -- the shear multipliers (21)
and the slip direction (edge_symmetry.py), then every estimate of b with its validity measures
and stated accuracy.  These programs record that sequence once (:mod:`asymslip.codegen.program`)
and the code generator prints it twice, for NumPy arrays (many cycles) and for Python floats
(one cycle), so that the core's two paths share one text of the edge's steps and one cycle
costs one call per step group instead of one per formula.

The only arithmetic written here is glue between formulas, each line with its reason: a'(P) as
1/(dP/da), the larger slope of the two states for the validity measures (24), (27) and (26),
the dimensionless groups in which the second-order width cannot overflow
(second_order_slip_zone.GROUPS), and b (28) from its ratio b/a1.
"""

from __future__ import annotations

import sympy

from asymslip.codegen import Argument, Derivation, Output, Step

from ._glossary import L_I1, L_I2, MEANINGS, P1, a1, a2, arguments, da, dP, eta, lam, mu
from .contact_law_hertz import E_star, R
from .stated_accuracy import ROUNDING


def _symbols(names: str) -> tuple[sympy.Symbol, ...]:
    """Program variables read by glue expressions (their assumptions do not matter here)."""
    return tuple(sympy.Symbol(name, real=True) for name in names.split())


P2 = sympy.Symbol("P2", positive=True)
(
    load_slope1,
    load_slope2,
    L_I_slope1,
    L_I_slope2,
    a_slope1,
    a_slope2,
    ratio_first_order,
    root,
    width_ratio,
    direction,
    other_direction,
    own_lam,
    own_eta,
    first_limit,
) = _symbols(
    "load_slope1 load_slope2 L_I_slope1 L_I_slope2 a_slope1 a_slope2 ratio_first_order root "
    "width_ratio direction other_direction own_lam own_eta first_limit"
)

SLOPES = (
    Argument(load_slope1, "Slope dP/da of the contact law at state 1, > 0 [force/length^2]."),
    Argument(load_slope2, "Slope dP/da of the contact law at state 2, > 0 [force/length^2]."),
    Argument(L_I_slope1, "Slope L_I'(P) of the normal edge multiplier at state 1."),
    Argument(L_I_slope2, "Slope L_I'(P) of the normal edge multiplier at state 2."),
)
LENGTH = "[length]"


def _edge_shear(d: Derivation) -> None:
    d.emit_program(
        name="edge_shear",
        args=arguments(mu, lam, eta, a1, a2, L_I1, L_I2),
        steps=(
            Step("L_II1", "shear_edge_multiplier_proportional", ("lam", "eta", "a1", "L_I1")),
            Step("L_II2", "shear_edge_multiplier_proportional", ("lam", "eta", "a2", "L_I2")),
            Step("direction", "slip_direction", ("mu", "L_I2", "L_II2")),
        ),
        outputs=(
            Output("L_II1", MEANINGS[sympy.Symbol("L_II1", real=True)]),
            Output("L_II2", MEANINGS[sympy.Symbol("L_II2", real=True)]),
            Output("direction", "+1.0 forward, -1.0 backward, 0.0 no slip on loading."),
        ),
        summary="An edge's shear multipliers (21) at both states and its slip direction.",
        doc="For an edge of a symmetric contact, lam and eta in the edge's own frame (the left "
        "edge sees lambda -> -lambda, edge_symmetry E1).",
    )


def _edge_estimates(d: Derivation) -> None:
    estimate_args = (
        *arguments(mu),
        Argument(own_lam, "Load-path slope lambda = dQ/dP (18) in the edge's own frame."),
        Argument(own_eta, "Load-path slope eta = dsigma/dP (18) [1/length]."),
        *arguments(a1, a2, da, L_I1, L_I2, P1, dP),
        *SLOPES,
        Argument(direction, "The edge's slip direction in its own frame: +1, -1 or 0."),
        Argument(
            other_direction,
            "The other edge's slip direction in its own frame (the mirrored one): +1, -1 or 0.",
        ),
        ROUNDING,
    )
    lam_over_mu, eta_a1_mu, growth, multiplier, multiplier_slope, orientation = _symbols(
        "lam_mu eta_a1_mu growth multiplier multiplier_slope orientation"
    )
    steps = (
        # lam and eta in the edge's slip direction (edge_symmetry E2: backward slip is forward
        # slip with (lam, eta) -> (-lam, -eta)); an edge that does not slip keeps them as they
        # are (what it reports instead is the core's business): the direction, or 1 for 0.
        Step("orientation", expr=direction + 1 - sympy.Abs(direction)),
        Step("lam", expr=orientation * own_lam),
        Step("eta", expr=orientation * own_eta),
        # The other-edge factor of b2 (second_order_slip_zone.OTHER_EDGE): +1 where the other
        # edge slips the same way in the global frame -- its own-frame direction of the other
        # sign, the left edge's frame being mirrored -- or does not slip; -1 where it slips the
        # opposite way.
        Step("other_edge", expr=-direction * other_direction + 1 - sympy.Abs(other_direction)),
        Step("a_slope1", expr=1 / load_slope1),  # a'(P) = 1/(dP/da)
        Step("a_slope2", expr=1 / load_slope2),
        # (24), (27): the contact growth over the cycle, at its larger slope; (26) likewise.
        Step("worst_slope", expr=sympy.Max(a_slope1, a_slope2)),
        Step(
            "worst_multiplier_slope",
            expr=sympy.Max(sympy.Abs(L_I_slope1), sympy.Abs(L_I_slope2)),
        ),
        Step("paper_width", "slip_zone_width", ("mu", "lam", "eta", "a1", "da", "L_I1", "L_I2")),
        Step(
            "denominator",
            "stick_boundary_denominator",
            ("mu", "lam", "eta", "a1", "a2", "L_I1", "L_I2"),
        ),
        Step(
            "ratio_first_order",
            "stick_ratio_first_order",
            ("mu", "lam", "eta", "a1", "dP", "a_slope1"),
        ),
        Step("b_first_order", expr=a1 * ratio_first_order),
        # b2 in the groups of its derivation (second_order_slip_zone.GROUPS): each of order one
        # where the width is a double, though its dimensional terms overflow at loads of 1e300.
        Step("lam_mu", expr=lam / mu),
        Step("eta_a1_mu", expr=eta * a1 / mu),
        Step("growth", expr=a_slope1 * dP / a1),
        Step("root", expr=a1 ** sympy.Rational(3, 2)),
        Step("multiplier", expr=L_I1 * root / dP),
        Step("multiplier_slope", expr=L_I_slope1 * root),
        Step(
            "width_ratio",
            "slip_zone_width_second_order_dimensionless",
            ("lam_mu", "eta_a1_mu", "growth", "multiplier", "multiplier_slope", "other_edge"),
        ),
        Step("width", expr=a1 * width_ratio),
        Step(
            "corrective_stick_width",
            "corrective_stick_slip_zone_width",
            ("mu", "lam", "eta", "a1", "da", "L_I1", "dP"),
        ),
        Step("P_K", "permanent_stick_load", ("P1", "dP", "lam", "mu")),
        Step("eq24", "contact_growth_measure", ("dP", "worst_slope", "a1")),
        Step("eq26", "multiplier_growth_measure", ("dP", "worst_multiplier_slope", "L_I1")),
        Step(
            "eq27",
            "slip_zone_growth_measure",
            ("mu", "lam", "eta", "a1", "dP", "worst_slope"),
        ),
        Step("relative_growth", expr=da / a1),  # first: da**2 alone overflows at a1 ~ 1e150
        Step("accuracy", "stick_boundary_accuracy", ("relative_growth", "width")),
        Step("paper_accuracy", "paper_stick_boundary_accuracy", ("relative_growth", "width")),
        Step(
            "first_accuracy",
            "stick_boundary_accuracy_first_order",
            ("relative_growth", "width"),
        ),
        Step(
            "paper_limit",
            "disagreement_limit",
            ("accuracy", "paper_accuracy", "a1", "rounding"),
        ),
        Step(
            "first_limit",
            "disagreement_limit",
            ("accuracy", "first_accuracy", "a1", "rounding"),
        ),
        # (40) is first order too: its limit is (28)'s.
        Step("stick_limit", expr=first_limit),
        Step("exact_accuracy", expr=sympy.Integer(0)),  # a(P_K) is exact
        Step(
            "exact_limit",
            "disagreement_limit",
            ("accuracy", "exact_accuracy", "a1", "rounding"),
        ),
    )
    d.emit_program(
        name="edge_estimates",
        args=estimate_args,
        steps=steps,
        outputs=(
            Output("paper_width", f"a1 - b by (22), cancellation-free {LENGTH}."),
            Output("denominator", "(17)'s denominator mu (L_I1 + L_I2) + L_II1 - L_II2."),
            Output("b_first_order", f"b to first order, (28) {LENGTH}."),
            Output("width", f"a1 - b to second order, the headline b2 {LENGTH}."),
            Output("corrective_stick_width", f"a1 - b of the corrective stick (40) {LENGTH}."),
            Output("P_K", "The permanent-stick load of (33) [force/length]."),
            Output("eq24", "The contact-growth measure (24)."),
            Output("eq26", "The multiplier-growth measure (26)."),
            Output("eq27", "The necessary condition (27)."),
            Output("accuracy", f"The stated accuracy of b2 {LENGTH}."),
            Output("paper_limit", f"How far (22) may lie from b2 before they disagree {LENGTH}."),
            Output("first_limit", f"How far (28) may lie from b2 before they disagree {LENGTH}."),
            Output("stick_limit", f"How far (40) may lie from b2 before they disagree {LENGTH}."),
            Output("exact_limit", f"How far a(P_K) may lie from b2 before they disagree {LENGTH}."),
        ),
        summary="Every estimate of b at one edge, its validity measures and stated accuracies.",
        doc="For an edge of a symmetric contact, lam and eta in its own frame: the program "
        "orients them so that the edge slips forward (edge_symmetry E2) and finds the other "
        "edge's factor of b2 from the two directions.  What an edge that does not slip reports "
        "instead is the slip-zone core's business.",
    )


def _hertz_cycle_state(d: Derivation) -> None:
    d.emit_program(
        name="hertz_cycle_state",
        args=(
            *arguments(P1, dP),
            Argument(R, "Radius of the cylinder, R > 0 [length]."),
            Argument(E_star, MEANINGS[sympy.Symbol("E_star", positive=True)]),
        ),
        steps=(
            Step("P2", expr=P1 + dP),
            Step("a1", "hertz_half_width", ("P1", "R", "E_star")),
            Step("da", "hertz_half_width_growth", ("P1", "dP", "R", "E_star")),
            Step("a2", expr=a1 + da),  # a(P2) with a2 - a1 kept cancellation-free
            Step("L_I1", "hertz_normal_edge_multiplier", ("P1", "R", "E_star")),
            Step("L_I2", "hertz_normal_edge_multiplier", ("P2", "R", "E_star")),
            Step("load_slope1", "hertz_load_slope", ("a1", "R", "E_star")),
            Step("load_slope2", "hertz_load_slope", ("a2", "R", "E_star")),
            Step("L_I_slope1", "hertz_normal_edge_multiplier_slope", ("P1", "R", "E_star")),
            Step("L_I_slope2", "hertz_normal_edge_multiplier_slope", ("P2", "R", "E_star")),
        ),
        outputs=(
            Output("P2", "Normal load at state 2 [force/length]."),
            Output("a1", f"Contact half-width a(P1) {LENGTH}."),
            Output("a2", f"Contact half-width a(P2) {LENGTH}."),
            Output("da", f"a2 - a1, cancellation-free {LENGTH}."),
            Output("L_I1", "Normal edge multiplier L_I at state 1 (31)."),
            Output("L_I2", "Normal edge multiplier L_I at state 2 (31)."),
            Output("load_slope1", "dP/da at state 1."),
            Output("load_slope2", "dP/da at state 2."),
            Output("L_I_slope1", "L_I'(P) at state 1."),
            Output("L_I_slope2", "L_I'(P) at state 2."),
        ),
        summary="Every quantity of the Hertzian law a cycle P1 -> P1 + dP needs, in one call.",
        doc="The closed forms (29)-(31) at both states of the cycle: half-widths, their "
        "cancellation-free difference, the edge multipliers and the slopes.",
    )


def derive() -> Derivation:
    d = Derivation(__file__)
    _edge_shear(d)
    _edge_estimates(d)
    _hertz_cycle_state(d)
    return d
