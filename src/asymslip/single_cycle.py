"""One valid cycle on Python floats: the slip-zone core's fast path.

For many cycles :func:`asymslip.slip_zones.evaluate` works on arrays: every rule checked per
element, every branch a ``numpy.where``.  For one cycle that machinery costs a hundred times
its arithmetic, so :func:`slip_zone` first tries :func:`evaluate_one`: the same estimates
(:func:`~asymslip.edge_estimates.edge_estimates` on the ``math`` kernels), the same stated
accuracies and disagreement limits, the same warning flags, with ``if`` for ``numpy.where``.

It answers only what it can answer alone: a symmetric law (asymmetric and calibrated contacts
have edges of their own), a cycle that passed its rules, and a result that breaks none of the
rules of :mod:`asymslip.rules`.  Anything else -- a rule broken, an overflow, a load outside
the law's range -- gives None, and the array path evaluates the cycle again to name the rule
and the value in its message.  So the fast path never has to word an error, and
``tests/test_single_cycle.py`` checks that on every cycle it answers it returns exactly the
doubles and flags of the array path.

Examples
--------
>>> from asymslip import HertzLaw, LoadCycle
>>> right, left = evaluate_one(HertzLaw(1.0, 1.0), LoadCycle(100, 0, 105, 1), 0.1)
>>> round(right["slip_zone_width"], 6), right["slip_direction"], left["slip_direction"]
(0.141929, 1, -1)
>>> evaluate_one(HertzLaw(1.0, 1.0), LoadCycle(100, 0, 105, 20), 0.1) is None  # gross sliding
True
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike

from asymslip_gen import scalar as kernels

from .cycle import LoadCycle
from .edge_estimates import (
    DENOMINATOR_TOLERANCE,
    disagreement_limits,
    edge_estimates,
    slip_direction,
    stated_accuracy,
)
from .edge_flags import (
    DISAGREE_CORRECTIVE_STICK,
    DISAGREE_EXACT,
    DISAGREE_FIRST_ORDER,
    DISAGREE_PAPER,
    EXTRAPOLATED_P1,
    EXTRAPOLATED_P2,
    MEASURE_FLAGS,
    NO_SLIP,
    OTHER_EDGE_STICKS,
    OUTSIDE_FLAGS,
    VALIDITY_THRESHOLD,
)
from .laws.base import ContactLaw, LawState

EQ24_LARGE, EQ25_LARGE, EQ26_LARGE, EQ27_LARGE = (
    MEASURE_FLAGS[key] for key in ("eq24", "eq25", "eq26", "eq27")
)


def evaluate_one(
    law: ContactLaw, cycle: LoadCycle, mu: ArrayLike
) -> tuple[dict[str, object], dict[str, object]] | None:
    """The fields of the right and left edges' results (the numbers of
    :class:`~asymslip.slip_zones.SlipZoneResult`, its ``validity`` and ``warning_flags``), or
    None where the array path must answer.

    None for: many cycles, a cycle that was not checked (``LoadCycle.unchecked``), an
    asymmetric law, any rule of :mod:`asymslip.rules` broken, or a Python float operation that
    raises where NumPy would give inf or NaN.
    """
    numbers = cycle.numbers
    if (
        numbers is None
        or not cycle.checked
        or not law.symmetric
        or hasattr(law, "shear_multiplier")
    ):
        return None
    if type(mu) is not float:
        if type(mu) is not int and not (
            isinstance(mu, (np.floating, np.ndarray)) and np.ndim(mu) == 0
        ):
            return None
        mu = float(mu)
    P1, Q1, P2, Q2, sigma1, sigma2 = numbers
    # mu finite and > 0 and no gross sliding at either state (a NaN fails every comparison).
    if not (0.0 < mu < math.inf and abs(Q1) < mu * P1 and abs(Q2) < mu * P2):
        return None
    try:
        if law.floats_only:
            return _both_edges(law, mu, P1, P2, Q2 - Q1, sigma2 - sigma1)
        with np.errstate(all="ignore"):  # as in the array path: a law on NumPy never warns
            return _both_edges(law, mu, P1, P2, Q2 - Q1, sigma2 - sigma1)
    except (ZeroDivisionError, OverflowError, ValueError):
        return None  # the array path gives the infs and NaNs its rules then name


def _both_edges(
    law: ContactLaw, mu: float, P1: float, P2: float, dQ: float, dsigma: float
) -> tuple[dict[str, object], dict[str, object]] | None:
    dP = P2 - P1
    lam, eta = dQ / dP, dsigma / dP
    state = law.cycle_state(P1, dP)
    if type(state.a1) is not float:  # a law computed on NumPy: its 0-d results as floats
        state = state.as_floats()
    if not _law_answers(state):
        return None
    right = _shear(mu, lam, eta, state)
    left = _shear(mu, -lam, eta, state)
    # Where the law is known only over a range of loads (a table law): the same at both edges.
    extrapolated = (EXTRAPOLATED_P1 if law.extrapolated(P1) else 0) | (
        EXTRAPOLATED_P2 if law.extrapolated(state.P2) else 0
    )
    right_oriented = _oriented(lam, eta, right[2], left[2])
    left_oriented = _oriented(-lam, eta, left[2], right[2])
    right_estimates = edge_estimates(kernels, mu, *right_oriented[:2], state, dP, right_oriented[2])
    # Without bulk tension a symmetric contact is its own mirror image: where the two edges
    # slip opposite ways in their own frames, the left edge asks the kernels exactly what the
    # right one asked (the same oriented lam, eta = +-0 and other-edge factor), so it is
    # answered once (derivations/edge_symmetry.py).
    left_estimates = (
        right_estimates
        if left_oriented == right_oriented
        else edge_estimates(kernels, mu, *left_oriented[:2], state, dP, left_oriented[2])
    )
    right_edge = _edge(law, state, mu, lam, eta, right, left[2], extrapolated, right_estimates)
    if right_edge is None:
        return None
    left_edge = _edge(law, state, mu, -lam, eta, left, right[2], extrapolated, left_estimates)
    if left_edge is None or not right_edge["b"] + left_edge["b"] > 0:
        return None  # (slip_zones_meet)
    return right_edge, left_edge


def _law_answers(state: LawState) -> bool:
    """The law carries both loads, finitely, and increases there (law_range, law_finite,
    law_increasing)."""
    total = (
        state.a1
        + state.L_I1
        + state.load_slope1
        + state.a2
        + state.da
        + state.L_I2
        + state.load_slope2
    )
    return bool(
        state.found1
        and state.found2
        and total - total == 0
        and state.load_slope1 > 0
        and state.load_slope2 > 0
    )


def _shear(mu: float, lam: float, eta: float, state: LawState) -> tuple[float, float, float]:
    """L_II1, L_II2 by (21) and the slip direction at an edge (in its own frame)."""
    L_II1 = kernels.shear_edge_multiplier_proportional(lam, eta, state.a1, state.L_I1)
    L_II2 = kernels.shear_edge_multiplier_proportional(lam, eta, state.a2, state.L_I2)
    return L_II1, L_II2, slip_direction(mu, state.L_I2, L_II2)


def _oriented(
    lam: float, eta: float, direction: float, other_direction: float
) -> tuple[float, float, float]:
    """lam and eta in the edge's slip direction, and the other-edge factor of b2."""
    orientation = direction if direction != 0.0 else 1.0
    other_edge = 1.0 if other_direction == 0.0 else -direction * other_direction
    return orientation * lam, orientation * eta, other_edge


def _edge(
    law: ContactLaw,
    state: LawState,
    mu: float,
    lam: float,
    eta: float,
    shear: tuple[float, float, float],
    other_direction: float,
    extrapolated: int,
    estimates: tuple[float, ...],
) -> dict[str, object] | None:
    """The fields of one edge's result (every field of a SlipZoneResult), as
    :func:`asymslip.slip_zones._edge` and ``_finish_edge`` give them, or None if a rule is
    broken."""
    a1, a2, da, L_I1, L_I2, P1 = state.a1, state.a2, state.da, state.L_I1, state.L_I2, state.P1
    L_II1, L_II2, direction = shear
    slips = direction != 0.0
    paper_width, denominator, b_first_order, width, stick_width, P_K, eq24, eq26, eq27 = estimates
    if slips:
        # (17) has a steady partial-slip state only for a positive denominator (denominator).
        scale = 2 * mu * (L_I1 + L_I2) + abs(L_II1) + abs(L_II2)
        if not denominator > DENOMINATOR_TOLERANCE * scale:
            return None
        b_corrective_stick = a1 - stick_width
    else:
        paper_width = width = eq27 = 0.0
        P_K, b_first_order, b_corrective_stick = P1, a1, a1
    b = a1 - width
    # Jaeger-Ciavarella: b = a(P_K) is exact for a symmetric law without bulk tension.
    b_exact = float(law.half_width_near(P_K, P1, a1)) if eta == 0 else math.nan
    b_paper = a1 - paper_width
    accuracy = stated_accuracy(a1, da, width)
    eq25 = abs(width) / a1
    # Every result finite (result_finite) and the stick boundary inside the contact (b_range).
    total = b + width + b_first_order + L_II1 + L_II2 + eq24 + eq25 + eq26 + eq27
    if not (total - total == 0 and 0 < b <= a2):
        return None
    # The warnings, flag by flag as in slip_zones._edge and _finish_edge.
    flags = extrapolated
    if slips:
        paper_limit, first_limit, stick_limit, exact_limit = disagreement_limits(
            a1, da, width, accuracy
        )
        if abs(b_paper - b) > paper_limit:
            flags |= DISAGREE_PAPER
        if abs(b_first_order - b) > first_limit:
            flags |= DISAGREE_FIRST_ORDER
        if abs(b_corrective_stick - b) > stick_limit:
            flags |= DISAGREE_CORRECTIVE_STICK
        if abs(b_exact - b) > exact_limit:
            flags |= DISAGREE_EXACT
        if other_direction == 0.0:
            flags |= OTHER_EDGE_STICKS
    else:
        flags |= NO_SLIP
    if eq24 > VALIDITY_THRESHOLD:
        flags |= EQ24_LARGE
    if eq25 > VALIDITY_THRESHOLD:
        flags |= EQ25_LARGE
    if eq26 > VALIDITY_THRESHOLD:
        flags |= EQ26_LARGE
    if eq27 > VALIDITY_THRESHOLD:
        flags |= EQ27_LARGE
    # An estimate outside the contact (0, a2] is no answer: left out, and so is its
    # disagreement with b.
    if not 0 < b_paper <= a2 and b_paper == b_paper:
        b_paper = math.nan
        flags = (flags & ~DISAGREE_PAPER) | OUTSIDE_FLAGS["b_paper"]
    if not 0 < b_first_order <= a2 and b_first_order == b_first_order:
        b_first_order = math.nan
        flags = (flags & ~DISAGREE_FIRST_ORDER) | OUTSIDE_FLAGS["b_first_order"]
    if not 0 < b_corrective_stick <= a2 and b_corrective_stick == b_corrective_stick:
        b_corrective_stick = math.nan
        flags = (flags & ~DISAGREE_CORRECTIVE_STICK) | OUTSIDE_FLAGS["b_corrective_stick"]
    # The fields of the edge's SlipZoneResult, in its order (slip_zones.SlipZoneResult); None
    # for an estimate not derived here (NaN).
    return {
        "a1": a1,
        "a2": a2,
        "lam": lam,
        "eta": eta,
        "L_I1": L_I1,
        "L_I2": L_I2,
        "L_II1": L_II1,
        "L_II2": L_II2,
        "b": b,
        "slip_zone_width": width,
        "b_accuracy": accuracy,
        "b_paper": b_paper if b_paper == b_paper else None,
        "b_first_order": b_first_order if b_first_order == b_first_order else None,
        "b_exact": b_exact if b_exact == b_exact else None,
        "b_corrective_stick": b_corrective_stick
        if b_corrective_stick == b_corrective_stick
        else None,
        "slip_direction": int(direction),
        "validity": {"eq24": eq24, "eq25": eq25, "eq26": eq26, "eq27": eq27},
        "warning_flags": flags,
        "law": law,
        "errors": None,
        "left": None,
    }
