"""The paper's estimates at one edge of a cycle: one call of the generated edge program.

Everything is in the edge's own frame, and the program orients ``lam`` and ``eta`` so that the
edge slips forward (see :mod:`asymslip.core.edge_state`); what an edge that does not slip
reports instead is the pipeline's business.

Examples
--------
The Fig. 5 cycle (Hertz, R = E* = 1, P 100 -> 105, lambda = 0.2, mu = 0.1) at its right edge:

>>> from asymslip.core.operations import FLOATS
>>> from asymslip.laws.hertz import HertzLaw
>>> state = HertzLaw(1.0, 1.0).cycle_state(100.0, 5.0)
>>> estimates = edge_estimates(FLOATS, 0.1, 0.2, 0.0, state, 5.0, 1.0, -1.0)
>>> round(estimates.width, 6), round(estimates.P_K, 6)
(0.141929, 97.5)
"""

from __future__ import annotations

import sys
from typing import NamedTuple

from asymslip_gen.edge_symmetry import slip_direction

from ..laws.base import LawState, Number
from .operations import Operations

__all__ = [
    "DENOMINATOR_TOLERANCE",
    "DISAGREEMENT_ROUNDING",
    "EdgeEstimates",
    "edge_estimates",
    "slip_direction",
]

#: (17)'s denominator counts as zero below this many units in the last place of its terms.
DENOMINATOR_TOLERANCE = 64 * sys.float_info.epsilon
#: Two estimates of b this close, relative to a1, do not disagree (a few units in the last
#: place of the slip-zone width's arithmetic; ``disagreement_limit`` of stated_accuracy.py).
DISAGREEMENT_ROUNDING = 1e-12


class EdgeEstimates(NamedTuple):
    """Every estimate of one forward-slipping edge, as the generated program gives them."""

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
    #: The stated accuracy of b2, (da/a1)^2 |a1 - b| (derivations/stated_accuracy.py).
    accuracy: Number
    #: How far (22), (28), (40) and a(P_K) may lie from b2 before they disagree: the two
    #: stated accuracies added, and the rounding allowance.
    paper_limit: Number
    first_order_limit: Number
    corrective_stick_limit: Number
    exact_limit: Number


def edge_estimates(
    ops: Operations,
    mu: Number,
    lam: Number,
    eta: Number,
    state: LawState,
    dP: Number,
    direction: Number,
    other_direction: Number,
) -> EdgeEstimates:
    """Every estimate of one edge, ``lam`` and ``eta`` in its own frame.

    One call of the generated program ``edge_estimates`` (``derivations/edge_programs.py``):
    lam and eta oriented so that the edge slips forward, the other edge's factor of b2, and
    the formulas of (22), (28), (40), (33), b2, (24)-(27) and the stated accuracies, in one
    text printed for NumPy and for Python floats.

    Parameters
    ----------
    ops
        One cycle's float operations or the array ones (:mod:`asymslip.core.operations`).
    mu, lam, eta, dP
        Friction coefficient, the load-path slopes (18) in the edge's own frame and the load
        change.
    state
        The law's quantities of the cycle (a1, a2, L_I and slopes at both states).
    direction, other_direction
        The slip directions of this edge and of the other one, each in its own frame (+1, -1
        or 0): the other edge slips the same way in the global frame when they differ in sign
        (``derivations/second_order_slip_zone.py``).
    """
    return _new(
        EdgeEstimates,
        ops.programs.edge_estimates(
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
            direction,
            other_direction,
            DISAGREEMENT_ROUNDING,
        ),
    )


#: A named tuple built from its fields in order, without its __new__.
_new = tuple.__new__
