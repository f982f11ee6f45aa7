"""The paper's estimates at one edge of a cycle: each generated kernel called once, with the
arguments the slip-zone core gives it.

One function serves both evaluation paths: arrays of cycles (the NumPy kernels of
``asymslip_gen``) and a single cycle on Python floats (the ``math`` twins of
``asymslip_gen.scalar``), so which kernel answers which question, and in which units, is written
once.  Everything is in the edge's own frame and slip direction (``lam``, ``eta`` oriented so
that the edge slips forward; see :mod:`asymslip.slip_zones`); what an edge that does not slip
reports instead is the caller's business.

Examples
--------
The Fig. 5 cycle (Hertz, R = E* = 1, P 100 -> 105, lambda = 0.2, mu = 0.1) at its right edge:

>>> from asymslip_gen import scalar
>>> from asymslip.laws.hertz import HertzLaw
>>> state = HertzLaw(1.0, 1.0).cycle_state(100.0, 5.0)
>>> estimates = dict(zip(ESTIMATES, edge_estimates(scalar, 0.1, 0.2, 0.0, state, 5.0, 1.0)))
>>> round(estimates["width"], 6), round(estimates["P_K"], 6)
(0.141929, 97.5)
"""

from __future__ import annotations

import sys
from dataclasses import dataclass
from types import ModuleType

import numpy as np
from numpy.typing import NDArray

from .edge_flags import (
    DISAGREE_CORRECTIVE_STICK,
    DISAGREE_EXACT,
    DISAGREE_FIRST_ORDER,
    DISAGREE_PAPER,
)
from .laws.base import LawState

Number = NDArray | float

#: (17)'s denominator counts as zero below this many units in the last place of its terms.
DENOMINATOR_TOLERANCE = 64 * sys.float_info.epsilon


@dataclass
class EdgeValues:
    """One edge, elementwise: every number of the result, and the warning flags."""

    values: dict[str, Number]
    flags: NDArray[np.int64] | int


#: What :func:`edge_estimates` returns, in order (a plain tuple: one cycle's fast path builds one
#: per edge, and a NamedTuple costs more than the arithmetic of half its entries).
ESTIMATES = (
    "paper_width",  # a1 - b by (22), cancellation-free (25)
    "denominator",  # (17)'s mu (L_I1 + L_I2) + L_II1 - L_II2 in (21)'s multipliers
    "b_first_order",  # b to first order (28)
    "width",  # a1 - b to second order, both edges, bulk tension (b2)
    "corrective_stick_width",  # a1 - b of the corrective stick zone (40)
    "P_K",  # the permanent-stick load of (33)
    "eq24",
    "eq26",
    "eq27",  # the validity measures
)


def edge_estimates(
    kernels: ModuleType,
    mu: Number,
    lam: Number,
    eta: Number,
    state: LawState,
    dP: Number,
    other_edge: Number,
) -> tuple[Number, ...]:
    """Every estimate of one edge (:data:`ESTIMATES`), ``lam`` and ``eta`` oriented so that the
    edge slips forward.

    Parameters
    ----------
    kernels
        ``asymslip_gen`` (arrays) or ``asymslip_gen.scalar`` (one cycle on Python floats).
    mu, lam, eta, dP
        Friction coefficient, the oriented load-path slopes (18) and the load change.
    state
        The law's quantities of the cycle (a1, a2, L_I and slopes at both states).
    other_edge
        +1 when the other edge slips the same way in the global frame or does not slip, -1
        when it slips the opposite way (``derivations/second_order_slip_zone.py``).
    """
    a1, a2, da, L_I1, L_I2 = state.a1, state.a2, state.da, state.L_I1, state.L_I2
    a_slope1 = 1.0 / state.load_slope1
    worst_slope = larger(a_slope1, 1.0 / state.load_slope2)
    worst_multiplier_slope = larger(abs(state.L_I_slope1), abs(state.L_I_slope2))
    # The b2 kernel is a polynomial whose terms (a1^3 eta^2 dL_I/dP dP, mu^2 ...) overflow or
    # underflow for loads of 1e300 or mu = 1e-300 though the width does not; it depends on
    # lam and eta through lam/mu and eta/mu and is homogeneous in length and load, so it is
    # evaluated with mu = 1 in units of a1 and dP (the same digits at ordinary values) and
    # scaled back.
    root = a1**1.5
    width = a1 * kernels.slip_zone_width_second_order_from_multiplier(
        1.0,
        lam / mu,
        eta * a1 / mu,
        1.0,
        a_slope1 * dP / a1,
        L_I1 * root / dP,
        state.L_I_slope1 * root,
        1.0,
        other_edge,
    )
    return (
        kernels.slip_zone_width(mu, lam, eta, a1, da, L_I1, L_I2),
        kernels.stick_boundary_denominator(mu, lam, eta, a1, a2, L_I1, L_I2),
        a1 * kernels.stick_ratio_first_order(mu, lam, eta, a1, dP, a_slope1),
        width,
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
    first_order = 2 * (da / a1) * abs(width)
    rounding = 1e-12 * a1
    first_order_limit = first_order + accuracy + rounding
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
    return 1.0 * (L_II2 > capacity) - 1.0 * (L_II2 < -capacity)


def larger(first: Number, second: Number) -> Number:
    """The larger, elementwise: ``numpy.maximum`` for arrays, plain Python for floats."""
    if isinstance(first, float) and isinstance(second, float):  # np.float64 is a float
        return first if first >= second else second
    return np.maximum(first, second)
