"""One edge of a cycle, written once for one cycle on floats and for arrays of cycles.

The steps, in the edge's own frame (``derivations/edge_symmetry.py``: the left edge is the
right edge of the mirrored cycle, lam -> -lam with eta kept; backward slip is forward slip with
(lam, eta) -> (-lam, -eta)):

1. :func:`shear_multipliers` -- L_II1, L_II2 by (21) (or the edge's own, for an asymmetric
   contact) and the slip direction;
2. :func:`edge_state` -- every estimate (:mod:`asymslip.core.estimates`), what an edge that
   does not slip reports instead, and the disagreements between estimates;
3. the rules the asymptotic solution must meet at the edge (a steady state, finite results,
   b inside the contact) and the warning flags.

Every branch goes through an :class:`~asymslip.core.operations.Operations`, so the same lines
run on Python floats (one cycle) and on arrays.

Examples
--------
The Fig. 5 cycle's right edge slips forward (L_II2 > mu L_I2), its left edge backward:

>>> from asymslip.core.operations import FLOATS
>>> from asymslip.laws.hertz import HertzLaw
>>> state = HertzLaw(1.0, 1.0).cycle_state(100.0, 5.0)
>>> law = HertzLaw(1.0, 1.0)
>>> [shear_multipliers(FLOATS, law, state, 0.1, lam, 0.0).direction for lam in (0.2, -0.2)]
[1.0, -1.0]
"""

from __future__ import annotations

import math
from typing import NamedTuple

from ..edge import Edge
from ..laws.base import ContactLaw, LawState, Number
from ..rules import denominator_checks, finite
from .estimates import DENOMINATOR_TOLERANCE, DISAGREEMENT_ROUNDING, EdgeEstimates
from .flags import (
    BEYOND_A1,
    DISAGREE_CORRECTIVE_STICK,
    DISAGREE_EXACT,
    DISAGREE_FIRST_ORDER,
    DISAGREE_PAPER,
    ESTIMATES_CHECKED,
    EXTRAPOLATED_P1,
    EXTRAPOLATED_P2,
    MEASURE_FLAGS,
    NO_SLIP,
    OTHER_EDGE_STICKS,
    OUTSIDE_FLAGS,
    OWN_MULTIPLIERS_TENSION,
    VALIDITY_THRESHOLD,
    WITH_TENSION,
)
from .operations import Flags, Operations

EQ24_LARGE, EQ25_LARGE, EQ26_LARGE, EQ27_LARGE = MEASURE_FLAGS.values()
_B_BEYOND_A1, _PAPER_BEYOND_A1, _FIRST_BEYOND_A1, _STICK_BEYOND_A1, _EXACT_BEYOND_A1 = (
    BEYOND_A1.values()
)


class Shear(NamedTuple):
    """The shear multipliers of one edge and its slip direction (in its own frame)."""

    L_II1: Number
    L_II2: Number
    #: +1 forward, -1 backward, 0 no slip on loading.
    direction: Number


class EdgeState(NamedTuple):
    """One edge of every cycle: each number of its result, and its warning flags.

    The first sixteen fields and the four validity measures are the result's
    (:data:`~asymslip.core.flags.NUMBER_KEYS`, :data:`~asymslip.core.flags.MEASURE_KEYS`);
    the rest are what the tractions need besides.
    """

    a1: Number
    a2: Number
    lam: Number
    eta: Number
    L_I1: Number
    L_I2: Number
    L_II1: Number
    L_II2: Number
    b: Number
    slip_zone_width: Number
    b_accuracy: Number
    b_paper: Number
    b_first_order: Number
    b_exact: Number
    b_corrective_stick: Number
    slip_direction: Number
    eq24: Number
    eq25: Number
    eq26: Number
    eq27: Number
    #: The permanent-stick load of (33) (P1 where the edge does not slip).
    P_K: Number
    #: The b of (17) in the edge's multipliers, for which the density (15) solves (12).
    b_consistent: Number
    flags: Flags


def missing_edge() -> EdgeState:
    """An edge with no numbers (NaN) and no flags: what a single invalid cycle reports."""
    nothing = math.nan
    return EdgeState._make([*(nothing for _ in EdgeState._fields[:-1]), 0])


def mirrored(edge: EdgeState) -> EdgeState:
    """The other edge of a symmetric contact without bulk tension, where the two edges slip
    opposite ways in their own frames: the mirror image (``derivations/edge_symmetry.py``).

    Every number is the same but lam, L_II1, L_II2 and the slip direction, which change sign
    exactly (L_II = lam L_I by (21) with eta = 0); the checks and flags are the same.
    """
    values = list(edge)
    values[_LAM] = -values[_LAM]
    values[_L_II1] = -values[_L_II1]
    values[_L_II2] = -values[_L_II2]
    values[_DIRECTION] = -values[_DIRECTION]
    return _new(EdgeState, values)


#: Where :func:`mirrored` changes sign, by position in :class:`EdgeState`.
_LAM, _L_II1, _L_II2, _DIRECTION = (
    EdgeState._fields.index(name) for name in ("lam", "L_II1", "L_II2", "slip_direction")
)


def shear_multipliers(
    ops: Operations,
    law: ContactLaw,
    state: LawState,
    mu: Number,
    lam: Number,
    eta: Number,
    own: bool = False,
) -> Shear:
    """L_II1, L_II2 and the slip direction of one edge (``lam`` in its own frame).

    By (21) for a symmetric contact; an edge that knows its own shear multiplier (``own``: an
    asymmetric contact's, AS3 of derivations/asymmetric_edge_multipliers.py) gives it itself.
    """
    if not own:  # (21), and the direction: one generated program (edge_programs.py)
        return _new(
            Shear,
            ops.programs.edge_shear(mu, lam, eta, state.a1, state.a2, state.L_I1, state.L_I2),
        )
    L_II1: Number = law.shear_multiplier(state.P1, lam, eta)
    L_II2: Number = law.shear_multiplier(state.P2, lam, eta)
    if ops.scalar:  # a law on NumPy: 0-d results
        L_II1, L_II2 = float(L_II1), float(L_II2)
    return _new(Shear, (L_II1, L_II2, ops.kernels.slip_direction(mu, state.L_I2, L_II2)))


def both_edges_estimates(
    ops: Operations, mu: Number, lam: Number, eta: Number, state: LawState, dP: Number
) -> tuple[Shear, Shear, EdgeEstimates, EdgeEstimates]:
    """Both edges of a symmetric contact whose left edge is not the right one mirrored (bulk
    tension): each edge's shear multipliers, slip direction and estimates, in its own frame.

    One call of the generated program ``both_edges`` (``derivations/edge_programs.py``): the
    steps of ``edge_shear`` and ``edge_estimates`` for each edge, the law's quantities once.
    """
    values = ops.programs.both_edges(
        mu,
        lam,
        eta,
        state.a1,
        state.a2,
        state.da,
        state.L_I1,
        state.L_I2,
        state.P1,
        dP,
        state.load_slope1,
        state.load_slope2,
        state.L_I_slope1,
        state.L_I_slope2,
        DISAGREEMENT_ROUNDING,
    )
    return (
        _new(Shear, values[:3]),
        _new(Shear, values[3:6]),
        _new(EdgeEstimates, values[6:20]),
        _new(EdgeEstimates, values[20:]),
    )


def edge_state(
    ops: Operations,
    law: ContactLaw,
    state: LawState,
    mu: Number,
    lam: Number,
    eta: Number,
    dP: Number,
    edge: Edge,
    shear: Shear,
    other_direction: Number,
    estimates: EdgeEstimates | None,
    extrapolates: bool = True,
) -> EdgeState:
    """One edge from its estimates (None for an edge with its own multipliers), checked
    against the rules of :mod:`asymslip.rules` and flagged.

    ``other_direction``: the other edge's slip direction in its own frame (0: it sticks, which
    the edge's warnings say).  ``extrapolates``: False for a law known everywhere (no load of
    it is extrapolated), so that its ``extrapolated`` is not asked.
    """
    if estimates is None:
        return _own_multipliers_edge(ops, law, state, mu, lam, eta, dP, edge, shear, extrapolates)
    a1, P1 = state.a1, state.P1
    direction = shear[2]
    slips = direction != 0
    # (22), the paper's headline, and the headline b2, as widths a1 - b (no cancellation);
    # where the edge does not slip: no slip zone, b = a1, and P_K = P1 (no permanent stick).
    (
        paper_width,
        denominator,
        b_first_order,
        width,
        corrective_stick_width,
        P_K,
        eq24,
        eq26,
        eq27,
        accuracy,
        paper_limit,
        first_limit,
        stick_limit,
        exact_limit,
    ) = estimates
    b_corrective_stick = a1 - corrective_stick_width
    if not ops.everywhere(slips):
        paper_width, width = ops.where(slips, paper_width, 0.0), ops.where(slips, width, 0.0)
        P_K, eq27 = ops.where(slips, P_K, P1), ops.where(slips, eq27, 0.0)
        b_first_order = ops.where(slips, b_first_order, a1)
        b_corrective_stick = ops.where(slips, b_corrective_stick, a1)
        accuracy = ops.where(slips, accuracy, 0.0)
    b = a1 - width
    # Jaeger-Ciavarella: b = a(P_K) is exact for a symmetric law without bulk tension.
    exact = (eta == 0) & law.symmetric
    if ops.everywhere(exact):  # one cycle, or arrays without tension: a(P_K) throughout
        b_exact = law.half_width_near(P_K, P1, a1)
    elif ops.somewhere(exact):
        at_P_K = law.half_width_near(ops.where(exact, P_K, P1), P1, a1)
        b_exact = ops.where(exact, at_P_K, ops.missing(a1))
    else:
        b_exact = ops.missing(a1)
    b_paper = a1 - paper_width
    # A flag is its bit times its condition: an int for one cycle, an array for many.
    disagree: Flags = WITH_TENSION * (eta != 0) | slips * (
        OTHER_EDGE_STICKS * (other_direction == 0)
        | _EXACT_BEYOND_A1 * (b_exact > a1)
        | DISAGREE_PAPER * (abs(b_paper - b) > paper_limit)
        | DISAGREE_FIRST_ORDER * (abs(b_first_order - b) > first_limit)
        | DISAGREE_CORRECTIVE_STICK * (abs(b_corrective_stick - b) > stick_limit)
        | DISAGREE_EXACT * (abs(b_exact - b) > exact_limit)
    )
    eq25 = abs(width) / a1
    b_paper, b_first_order, b_corrective_stick, flags = _checked(
        ops,
        law,
        state,
        mu,
        lam,
        eta,
        edge,
        shear,
        denominator,
        b,
        width,
        eq24,
        eq25,
        eq26,
        eq27,
        b_paper,
        b_first_order,
        b_corrective_stick,
        disagree | _extrapolation_flags(law, state) if extrapolates else disagree,
    )
    # Built as the tuple it is, in the order of the fields (tuple.__new__): a record of 23
    # built through its __new__ binds 23 arguments one by one, and one cycle is timed in
    # microseconds.
    return _new(
        EdgeState,
        (
            a1,
            state.a2,
            lam,
            eta,
            state.L_I1,
            state.L_I2,
            shear[0],  # L_II1
            shear[1],  # L_II2
            b,
            width,  # slip_zone_width
            accuracy,  # b_accuracy
            b_paper,
            b_first_order,
            b_exact,
            b_corrective_stick,
            direction,  # slip_direction
            eq24,
            eq25,
            eq26,
            eq27,
            P_K,
            a1 - paper_width,  # b_consistent: (17)/(22), the b for which (15) solves (12)
            flags,
        ),
    )


def _extrapolation_flags(law: ContactLaw, state: LawState) -> Flags:
    """The flags of the loads where the law is extrapolated (a table law beyond its data)."""
    return EXTRAPOLATED_P1 * law.extrapolated(state.P1) | EXTRAPOLATED_P2 * law.extrapolated(
        state.P2
    )


def _own_multipliers_edge(
    ops: Operations,
    law: ContactLaw,
    state: LawState,
    mu: Number,
    lam: Number,
    eta: Number,
    dP: Number,
    edge: Edge,
    shear: Shear,
    extrapolates: bool,
) -> EdgeState:
    """An edge whose multipliers are its own (an asymmetric or calibrated contact).

    b is (17) in the edge's own L_I and L_II: (21), and so (22), do not hold at an edge of an
    asymmetric contact (AS3, AS4), and neither do the second-order b2, the corrective-stick
    (40) or a(P_K) (AS7): those are reported as missing (NaN, null in JSON).  The first-order
    b is the first-order term of (17) in the edge's own multipliers.  Stated accuracy: first
    order, 2 (da/a1) |a1 - b|: (17) with AS3 agrees with an exact asymmetric solution to second
    order in dP without tension, but with bulk tension its dP^2 term is the one erratum 22-T
    finds spurious for symmetric contacts, and no correction is derived for asymmetric ones.
    """
    kernels = ops.kernels
    a1, da, L_I1, L_I2 = state.a1, state.da, state.L_I1, state.L_I2
    slips = shear.direction != 0
    orientation = ops.where(slips, shear.direction, 1.0)
    L_II1, L_II2 = orientation * shear.L_II1, orientation * shear.L_II2
    width = ops.where(
        slips, kernels.slip_zone_width_from_multipliers(mu, da, L_I1, L_I2, L_II1, L_II2), 0.0
    )
    b = a1 - width
    denominator = kernels.stick_boundary_denominator_from_multipliers(mu, L_I1, L_I2, L_II1, L_II2)
    worst_slope = ops.maximum(state.a_slope1, state.a_slope2)
    worst_multiplier_slope = ops.maximum(abs(state.L_I_slope1), abs(state.L_I_slope2))
    first_order = a1 * kernels.stick_ratio_first_order_from_multipliers(
        mu, L_I1, L_II1, a1, dP, state.a_slope1
    )
    missing = ops.missing(a1)
    eq24 = kernels.contact_growth_measure(dP, worst_slope, a1)
    eq25 = abs(width) / a1
    eq26 = kernels.multiplier_growth_measure(dP, worst_multiplier_slope, L_I1)
    eq27 = ops.where(
        slips,
        kernels.slip_zone_growth_measure_from_multipliers(mu, L_I1, L_II1, a1, dP, worst_slope),
        0.0,
    )
    _, b_first_order, _, flags = _checked(
        ops,
        law,
        state,
        mu,
        lam,
        eta,
        edge,
        shear,
        denominator,
        b,
        width,
        eq24,
        eq25,
        eq26,
        eq27,
        missing,
        ops.where(slips, first_order, a1),
        missing,
        OWN_MULTIPLIERS_TENSION * (slips & (eta != 0))
        | (_extrapolation_flags(law, state) if extrapolates else 0),
    )
    return _new(
        EdgeState,
        (
            a1,
            state.a2,
            lam,
            eta,
            L_I1,
            L_I2,
            shear.L_II1,
            shear.L_II2,
            b,
            width,  # slip_zone_width
            kernels.stick_boundary_accuracy_first_order(da / a1, width),  # b_accuracy
            missing,  # b_paper
            b_first_order,
            missing,  # b_exact
            missing,  # b_corrective_stick
            shear.direction,  # slip_direction
            eq24,
            eq25,
            eq26,
            eq27,
            missing,  # P_K
            b,  # b_consistent: b is (17) in the edge's own multipliers
            flags,
        ),
    )


#: What the rules leave of an edge's estimates (b_paper, b_first_order, b_corrective_stick) and
#: its warning flags.
_Checked = tuple[Number, Number, Number, Flags]


def _checked(
    ops: Operations,
    law: ContactLaw,
    state: LawState,
    mu: Number,
    lam: Number,
    eta: Number,
    edge: Edge,
    shear: Shear,
    denominator: Number,
    b: Number,
    width: Number,
    eq24: Number,
    eq25: Number,
    eq26: Number,
    eq27: Number,
    b_paper: Number,
    b_first_order: Number,
    b_corrective_stick: Number,
    flags: Flags,
) -> _Checked:
    """The rules the asymptotic solution must meet at this edge, and the warnings.

    ``eq24``-``eq27`` are the validity measures; ``b_paper``, ``b_first_order`` and
    ``b_corrective_stick`` are each left out (NaN) where they fall outside the contact, and
    with each its disagreement flag in ``flags`` (the flags found so far).
    """
    L_II1, L_II2, direction = shear
    sticks, slips = direction == 0, direction != 0
    scale = 2 * mu * (state.L_I1 + state.L_I2) + abs(L_II1) + abs(L_II2)
    admits = sticks | (denominator > DENOMINATOR_TOLERANCE * scale)
    if not ops.everywhere(admits):
        note = law.resolution_note(*ops.refused(admits, state.P1, state.P2))
        # Named by the load change to blame (the tension's or the shear force's), not mu.
        for key, ok in denominator_checks(admits, mu, lam, eta, state.L_I1, state.L_I2):
            ops.require(key, ok, None, side=edge, denominator=denominator, mu=mu, note=note)
    # Non-finite results first: a b that overflowed is not "outside the contact".
    total = b + width + b_first_order + L_II1 + L_II2 + eq24 + eq25 + eq26 + eq27
    if not ops.everywhere(total - total == 0):  # finite
        for key, value in (
            ("b", b),
            ("slip_zone_width", width),
            ("b_first_order", b_first_order),
            ("L_II1", L_II1),
            ("L_II2", L_II2),
            *zip(MEASURE_FLAGS, (eq24, eq25, eq26, eq27), strict=True),
        ):
            ops.require("result_finite", finite(value), None, side=edge, law=law.name, quantity=key)
    a1, a2 = state.a1, state.a2
    inside = (b > 0) & (b <= a2)
    if not ops.everywhere(inside):
        # A calibrated law that cannot resolve the load step says so (as for the denominator).
        note = law.resolution_note(*ops.refused(inside, state.P1, state.P2))
        ops.require(
            "b_range", inside, None, side=edge, b=b, eq25=eq25, eq24=eq24, eq27=eq27, note=note
        )
    flags = (
        flags
        | NO_SLIP * sticks
        | EQ24_LARGE * (eq24 > VALIDITY_THRESHOLD)
        | EQ25_LARGE * (eq25 > VALIDITY_THRESHOLD)
        | EQ26_LARGE * (eq26 > VALIDITY_THRESHOLD)
        | EQ27_LARGE * (eq27 > VALIDITY_THRESHOLD)
        | _B_BEYOND_A1 * (slips & (b > a1))
    )
    # An estimate outside the contact (0, a2] is no answer: left out (NaN), and so is its
    # disagreement with b (NaN, not derived here, is no estimate to leave out).
    if not ops.everywhere(
        ((b_paper > 0) & (b_paper <= a2) | (b_paper != b_paper))
        & ((b_first_order > 0) & (b_first_order <= a2) | (b_first_order != b_first_order))
        & (
            (b_corrective_stick > 0) & (b_corrective_stick <= a2)
            | (b_corrective_stick != b_corrective_stick)
        )
    ):
        kept = [b_paper, b_first_order, b_corrective_stick]
        for index, (key, (_, disagreement)) in enumerate(ESTIMATES_CHECKED.items()):
            value = kept[index]
            inside = ((value > 0) & (value <= a2)) | (value != value)
            kept[index] = ops.where(inside, value, ops.missing(value))
            flags = ops.keep_flags(inside, flags, (flags & ~disagreement) | OUTSIDE_FLAGS[key])
        b_paper, b_first_order, b_corrective_stick = kept
    # A stick boundary beyond a1 where the edge slips: no slip zone inside a1 (in words).
    flags = flags | slips * (
        _PAPER_BEYOND_A1 * (b_paper > a1)
        | _FIRST_BEYOND_A1 * (b_first_order > a1)
        | _STICK_BEYOND_A1 * (b_corrective_stick > a1)
    )
    return b_paper, b_first_order, b_corrective_stick, flags


#: A named tuple built from its fields in order, without its __new__ (see :func:`edge_state`).
_new = tuple.__new__
