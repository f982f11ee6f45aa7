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
    cycle_lam,
) = _symbols(
    "load_slope1 load_slope2 L_I_slope1 L_I_slope2 a_slope1 a_slope2 ratio_first_order root "
    "width_ratio direction other_direction own_lam own_eta cycle_lam"
)
cycle_eta = sympy.Symbol("cycle_eta", real=True)

SLOPES = (
    Argument(load_slope1, "Slope dP/da of the contact law at state 1, > 0 [force/length^2]."),
    Argument(load_slope2, "Slope dP/da of the contact law at state 2, > 0 [force/length^2]."),
    Argument(L_I_slope1, "Slope L_I'(P) of the normal edge multiplier at state 1."),
    Argument(L_I_slope2, "Slope L_I'(P) of the normal edge multiplier at state 2."),
)
LENGTH = "[length]"
#: The law's quantities of the cycle, as the core passes them to every edge program.
LAW_ARGUMENTS = (*arguments(a1, a2, da, L_I1, L_I2, P1, dP), *SLOPES)


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


def _var(name: str) -> sympy.Symbol:
    """The program variable ``name`` in a glue expression."""
    return sympy.Symbol(name, real=True)


def _law_steps() -> tuple[Step, ...]:
    """What the estimates need of the law alone: the same at both edges of a symmetric law."""
    return (
        Step("a_slope1", expr=1 / load_slope1),  # a'(P) = 1/(dP/da)
        Step("a_slope2", expr=1 / load_slope2),
        # (24), (27): the contact growth over the cycle, at its larger slope; (26) likewise.
        Step("worst_slope", expr=sympy.Max(a_slope1, a_slope2)),
        Step(
            "worst_multiplier_slope",
            expr=sympy.Max(sympy.Abs(L_I_slope1), sympy.Abs(L_I_slope2)),
        ),
        # b2 in the groups of its derivation (second_order_slip_zone.GROUPS): each of order one
        # where the width is a double, though its dimensional terms overflow at loads of 1e300.
        Step("growth", expr=a_slope1 * dP / a1),
        Step("root", expr=a1 ** sympy.Rational(3, 2)),
        Step("multiplier", expr=L_I1 * root / dP),
        Step("multiplier_slope", expr=L_I_slope1 * root),
        Step("eq24", "contact_growth_measure", ("dP", "worst_slope", "a1")),
        Step("eq26", "multiplier_growth_measure", ("dP", "worst_multiplier_slope", "L_I1")),
        Step("relative_growth", expr=da / a1),  # first: da**2 alone overflows at a1 ~ 1e150
    )


def _shear_steps(edge: str, own_lam: str, own_eta: str) -> tuple[Step, ...]:
    """(21) at both states and the slip direction of an edge, lam and eta in its own frame."""
    return (
        Step(
            f"{edge}L_II1", "shear_edge_multiplier_proportional", (own_lam, own_eta, "a1", "L_I1")
        ),
        Step(
            f"{edge}L_II2", "shear_edge_multiplier_proportional", (own_lam, own_eta, "a2", "L_I2")
        ),
        Step(f"{edge}direction", "slip_direction", ("mu", "L_I2", f"{edge}L_II2")),
    )


def _estimate_steps(
    edge: str, own_lam: str, own_eta: str, direction: str, other_direction: str
) -> tuple[Step, ...]:
    """Every estimate of one edge, its names prefixed with ``edge``, from lam and eta in its
    own frame and the two edges' slip directions (after :func:`_law_steps`)."""
    lam_, eta_ = f"{edge}lam", f"{edge}eta"
    orientation, first_limit_ = _var(f"{edge}orientation"), _var(f"{edge}first_limit")
    d, other = _var(direction), _var(other_direction)
    return (
        # lam and eta in the edge's slip direction (edge_symmetry E2: backward slip is forward
        # slip with (lam, eta) -> (-lam, -eta)); an edge that does not slip keeps them as they
        # are (what it reports instead is the core's business): the direction, or 1 for 0.
        Step(f"{edge}orientation", expr=d + 1 - sympy.Abs(d)),
        Step(lam_, expr=orientation * _var(own_lam)),
        Step(eta_, expr=orientation * _var(own_eta)),
        # The other-edge factor of b2 (second_order_slip_zone.OTHER_EDGE): +1 where the other
        # edge slips the same way in the global frame -- its own-frame direction of the other
        # sign, the left edge's frame being mirrored -- or does not slip; -1 where it slips the
        # opposite way.
        Step(f"{edge}other_edge", expr=-d * other + 1 - sympy.Abs(other)),
        Step(
            f"{edge}paper_width",
            "slip_zone_width",
            ("mu", lam_, eta_, "a1", "da", "L_I1", "L_I2"),
        ),
        Step(
            f"{edge}denominator",
            "stick_boundary_denominator",
            ("mu", lam_, eta_, "a1", "a2", "L_I1", "L_I2"),
        ),
        Step(
            f"{edge}ratio_first_order",
            "stick_ratio_first_order",
            ("mu", lam_, eta_, "a1", "dP", "a_slope1"),
        ),
        Step(f"{edge}b_first_order", expr=a1 * _var(f"{edge}ratio_first_order")),
        Step(f"{edge}lam_mu", expr=_var(lam_) / mu),
        Step(f"{edge}eta_a1_mu", expr=_var(eta_) * a1 / mu),
        Step(
            f"{edge}width_ratio",
            "slip_zone_width_second_order_dimensionless",
            (
                f"{edge}lam_mu",
                f"{edge}eta_a1_mu",
                "growth",
                "multiplier",
                "multiplier_slope",
                f"{edge}other_edge",
            ),
        ),
        Step(f"{edge}width", expr=a1 * _var(f"{edge}width_ratio")),
        Step(
            f"{edge}corrective_stick_width",
            "corrective_stick_slip_zone_width",
            ("mu", lam_, eta_, "a1", "da", "L_I1", "dP"),
        ),
        Step(f"{edge}P_K", "permanent_stick_load", ("P1", "dP", lam_, "mu")),
        Step(
            f"{edge}eq27",
            "slip_zone_growth_measure",
            ("mu", lam_, eta_, "a1", "dP", "worst_slope"),
        ),
        Step(
            f"{edge}accuracy",
            "stick_boundary_accuracy",
            ("relative_growth", f"{edge}width"),
        ),
        Step(
            f"{edge}paper_accuracy",
            "paper_stick_boundary_accuracy",
            ("relative_growth", f"{edge}width"),
        ),
        Step(
            f"{edge}first_accuracy",
            "stick_boundary_accuracy_first_order",
            ("relative_growth", f"{edge}width"),
        ),
        Step(
            f"{edge}paper_limit",
            "disagreement_limit",
            (f"{edge}accuracy", f"{edge}paper_accuracy", "a1", "rounding"),
        ),
        Step(
            f"{edge}first_limit",
            "disagreement_limit",
            (f"{edge}accuracy", f"{edge}first_accuracy", "a1", "rounding"),
        ),
        # (40) is first order too: its limit is (28)'s.
        Step(f"{edge}stick_limit", expr=first_limit_),
        Step(f"{edge}exact_accuracy", expr=sympy.Integer(0)),  # a(P_K) is exact
        Step(
            f"{edge}exact_limit",
            "disagreement_limit",
            (f"{edge}accuracy", f"{edge}exact_accuracy", "a1", "rounding"),
        ),
    )


#: The estimates of one edge, in the order the core's EdgeEstimates reads them.
_ESTIMATES = (
    ("paper_width", f"a1 - b by (22), cancellation-free {LENGTH}."),
    ("denominator", "(17)'s denominator mu (L_I1 + L_I2) + L_II1 - L_II2."),
    ("b_first_order", f"b to first order, (28) {LENGTH}."),
    ("width", f"a1 - b to second order, the headline b2 {LENGTH}."),
    ("corrective_stick_width", f"a1 - b of the corrective stick (40) {LENGTH}."),
    ("P_K", "The permanent-stick load of (33) [force/length]."),
    ("eq24", "The contact-growth measure (24)."),
    ("eq26", "The multiplier-growth measure (26)."),
    ("eq27", "The necessary condition (27)."),
    ("accuracy", f"The stated accuracy of b2 {LENGTH}."),
    ("paper_limit", f"How far (22) may lie from b2 before they disagree {LENGTH}."),
    ("first_limit", f"How far (28) may lie from b2 before they disagree {LENGTH}."),
    ("stick_limit", f"How far (40) may lie from b2 before they disagree {LENGTH}."),
    ("exact_limit", f"How far a(P_K) may lie from b2 before they disagree {LENGTH}."),
)
#: Shared by the two edges (the law's quantities alone).
_LAW_ESTIMATES = ("eq24", "eq26")


def _estimate_outputs(edge: str, whose: str) -> tuple[Output, ...]:
    return tuple(
        Output(name if name in _LAW_ESTIMATES else f"{edge}{name}", f"{whose}{meaning}")
        for name, meaning in _ESTIMATES
    )


def _edge_estimates(d: Derivation) -> None:
    d.emit_program(
        name="edge_estimates",
        args=(
            *arguments(mu),
            Argument(own_lam, "Load-path slope lambda = dQ/dP (18) in the edge's own frame."),
            Argument(own_eta, "Load-path slope eta = dsigma/dP (18) [1/length]."),
            *LAW_ARGUMENTS,
            Argument(direction, "The edge's slip direction in its own frame: +1, -1 or 0."),
            Argument(
                other_direction,
                "The other edge's slip direction in its own frame (the mirrored one): +1, -1 or 0.",
            ),
            ROUNDING,
        ),
        steps=(
            *_law_steps(),
            *_estimate_steps("", "own_lam", "own_eta", "direction", "other_direction"),
        ),
        outputs=_estimate_outputs("", ""),
        summary="Every estimate of b at one edge, its validity measures and stated accuracies.",
        doc="For an edge of a symmetric contact, lam and eta in its own frame: the program "
        "orients them so that the edge slips forward (edge_symmetry E2) and finds the other "
        "edge's factor of b2 from the two directions.  What an edge that does not slip reports "
        "instead is the slip-zone core's business.",
    )


def _both_edges(d: Derivation) -> None:
    d.emit_program(
        name="both_edges",
        args=(
            *arguments(mu),
            Argument(cycle_lam, "Load-path slope lambda = dQ/dP (18) of the cycle, either sign."),
            Argument(cycle_eta, "Load-path slope eta = dsigma/dP (18), either sign [1/length]."),
            *LAW_ARGUMENTS,
            ROUNDING,
        ),
        steps=(
            # The left edge is the right edge of the mirrored cycle: lambda -> -lambda with
            # eta kept (edge_symmetry E1), the law's quantities the same (a symmetric law).
            Step("mirrored_lam", expr=-cycle_lam),
            *_shear_steps("right_", "cycle_lam", "cycle_eta"),
            *_shear_steps("left_", "mirrored_lam", "cycle_eta"),
            *_law_steps(),
            *_estimate_steps(
                "right_", "cycle_lam", "cycle_eta", "right_direction", "left_direction"
            ),
            *_estimate_steps(
                "left_", "mirrored_lam", "cycle_eta", "left_direction", "right_direction"
            ),
        ),
        outputs=(
            Output("right_L_II1", "The right edge's L_II at state 1 (21)."),
            Output("right_L_II2", "The right edge's L_II at state 2 (21)."),
            Output("right_direction", "The right edge's slip direction: +1, -1 or 0."),
            Output("left_L_II1", "The left edge's L_II at state 1 (21), in its own frame."),
            Output("left_L_II2", "The left edge's L_II at state 2 (21), in its own frame."),
            Output("left_direction", "The left edge's slip direction, in its own frame."),
            *_estimate_outputs("right_", "The right edge's: "),
            *_estimate_outputs("left_", "The left edge's: "),
        ),
        summary="Both edges of a symmetric contact at once: shear, slip direction, estimates.",
        doc="The right edge as edge_shear and edge_estimates give it, then the left edge (the "
        "right edge of the mirrored cycle), the law's quantities computed once for both.  For "
        "a cycle whose left edge is not the right one mirrored (bulk tension).",
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
    _both_edges(d)
    _hertz_cycle_state(d)
    return d
