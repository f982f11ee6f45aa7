"""The paper's estimates at one edge of a cycle: each generated kernel called once.

Everything is in the edge's own frame and slip direction (``lam``, ``eta`` oriented so that the
edge slips forward; see :mod:`asymslip.core.edge_state`); what an edge that does not slip
reports instead is the pipeline's business.

Examples
--------
The Fig. 5 cycle (Hertz, R = E* = 1, P 100 -> 105, lambda = 0.2, mu = 0.1) at its right edge:

>>> from asymslip.core.operations import FLOATS
>>> from asymslip.laws.hertz import HertzLaw
>>> state = HertzLaw(1.0, 1.0).cycle_state(100.0, 5.0)
>>> estimates = edge_estimates(FLOATS, 0.1, 0.2, 0.0, state, 5.0, 1.0)
>>> round(estimates.width, 6), round(estimates.P_K, 6)
(0.141929, 97.5)
"""

from __future__ import annotations

import sys
from typing import NamedTuple

from ..laws.base import LawState, Number
from .flags import (
    DISAGREE_CORRECTIVE_STICK,
    DISAGREE_EXACT,
    DISAGREE_FIRST_ORDER,
    DISAGREE_PAPER,
)
from .operations import Operations

#: (17)'s denominator counts as zero below this many units in the last place of its terms.
DENOMINATOR_TOLERANCE = 64 * sys.float_info.epsilon


class EdgeEstimates(NamedTuple):
    """Every estimate of one forward-slipping edge, as the generated kernels give them."""

    #: a1 - b by (22), cancellation-free (25).
    paper_width: Number
    #: (17)'s denominator mu (L_I1 + L_I2) + L_II1 - L_II2 in (21)'s multipliers.
    denominator: Number
    #: b to first order (28).
    b_first_order: Number
    #: a1 - b to second order, both edges, bulk tension (b2): the headline.
    width: Number
    #: a1 - b of the corrective-stick estimate (40).
    corrective_stick_width: Number
    #: The permanent-stick load of (33).
    P_K: Number
    #: The validity measures (24), (26), (27).
    eq24: Number
    eq26: Number
    eq27: Number


def edge_estimates(
    ops: Operations,
    mu: Number,
    lam: Number,
    eta: Number,
    state: LawState,
    dP: Number,
    other_edge: Number,
) -> EdgeEstimates:
    """Every estimate of one edge, ``lam`` and ``eta`` oriented so that the edge slips forward.

    Parameters
    ----------
    ops
        One cycle's float operations or the array ones (:mod:`asymslip.core.operations`).
    mu, lam, eta, dP
        Friction coefficient, the oriented load-path slopes (18) and the load change.
    state
        The law's quantities of the cycle (a1, a2, L_I and slopes at both states).
    other_edge
        +1 when the other edge slips the same way in the global frame or does not slip, -1
        when it slips the opposite way (``derivations/second_order_slip_zone.py``).
    """
    kernels = ops.kernels
    a1, a2, da, L_I1, L_I2 = state.a1, state.a2, state.da, state.L_I1, state.L_I2
    a_slope1 = 1.0 / state.load_slope1
    worst_slope = ops.maximum(a_slope1, 1.0 / state.load_slope2)
    worst_multiplier_slope = ops.maximum(abs(state.L_I_slope1), abs(state.L_I_slope2))
    # b2 in the dimensionless groups of its derivation (derivations/second_order_slip_zone.py):
    # each is of order one where the width is representable, though its dimensional terms
    # (a1^3 eta^2 dL_I/dP dP, mu^2 ...) overflow for loads of 1e300 or mu = 1e-300.
    root = a1**1.5
    return EdgeEstimates(  # positional, in field order: a third of the cost of keywords
        kernels.slip_zone_width(mu, lam, eta, a1, da, L_I1, L_I2),
        kernels.stick_boundary_denominator(mu, lam, eta, a1, a2, L_I1, L_I2),
        a1 * kernels.stick_ratio_first_order(mu, lam, eta, a1, dP, a_slope1),
        a1
        * kernels.slip_zone_width_second_order_dimensionless(
            lam / mu,
            eta * a1 / mu,
            a_slope1 * dP / a1,
            L_I1 * root / dP,
            state.L_I_slope1 * root,
            other_edge,
        ),
        kernels.corrective_stick_slip_zone_width(mu, lam, eta, a1, da, L_I1, dP),
        kernels.permanent_stick_load(state.P1, dP, lam, mu),
        kernels.contact_growth_measure(dP, worst_slope, a1),
        kernels.multiplier_growth_measure(dP, worst_multiplier_slope, L_I1),
        kernels.slip_zone_growth_measure(mu, lam, eta, a1, dP, worst_slope),
    )


def stated_accuracy(a1: Number, da: Number, width: Number) -> Number:
    """How far b (b2) may lie from the true stick boundary: (da/a1)^2 |a1 - b|.

    Measured |C| <= 0.78 against the exact steady-state conditions, within 1.2 solver
    elements (README, "How far to trust b").
    """
    growth = da / a1
    return growth * growth * abs(width)


def first_order_accuracy(a1: Number, da: Number, width: Number) -> Number:
    """The stated accuracy of a first-order estimate ((28), (40), and (17) in an edge's own
    multipliers): 2 (da/a1) |a1 - b|."""
    return 2 * (da / a1) * abs(width)


#: The estimates checked against b, in the order of :func:`disagreement_limits`, each with the
#: warning flag it sets where it disagrees.
DISAGREEMENTS = (
    ("b_paper", DISAGREE_PAPER),
    ("b_first_order", DISAGREE_FIRST_ORDER),
    ("b_corrective_stick", DISAGREE_CORRECTIVE_STICK),
    ("b_exact", DISAGREE_EXACT),
)


def disagreement_limits(
    a1: Number, da: Number, width: Number, accuracy: Number
) -> tuple[Number, Number, Number, Number]:
    """How far each estimate of :data:`DISAGREEMENTS` may lie from b before they disagree.

    The two stated accuracies added -- a second-order formula within twice b's, a first-order
    one within 2 (da/a1) |a1 - b|, a(P_K) exact -- and 1e-12 a1 for rounding.
    """
    rounding = 1e-12 * a1
    first_order_limit = first_order_accuracy(a1, da, width) + accuracy + rounding
    return (
        2 * accuracy + accuracy + rounding,
        first_order_limit,
        first_order_limit,
        accuracy + rounding,
    )


def slip_direction(mu: Number, L_I2: Number, L_II2: Number) -> Number:
    """+1 (forward), -1 (backward) or 0 (no slip) on loading at an edge.

    Next to the state-2 edge (a1 < x < a2) the state-1 traction is zero, so loading slips there
    iff |L_II2| > mu L_I2 (derivations/edge_symmetry.py).
    """
    capacity = mu * L_I2
    direction: Number = 1.0 * (L_II2 > capacity) - 1.0 * (L_II2 < -capacity)
    return direction
