"""Both edges of every cycle: the one evaluation behind the API, the tractions and the sweep.

:func:`evaluate` takes a law, cycles (a :class:`~asymslip.cycle.LoadCycle` whose fields may be
arrays) and friction coefficients (broadcast together), and

1. checks every element against the rules of :mod:`asymslip.rules`;
2. asks the law once per cycle for everything the cycle needs
   (:meth:`~asymslip.laws.base.ContactLaw.cycle_state`: a1, a2, a2 - a1, L_I and the slopes),
   shared by both edges (for a symmetric law) and by every estimate;
3. evaluates both edges -- always both, since a cycle is a steady partial-slip state only if
   both edges are (their slip zones must not meet) -- through the one edge pipeline of
   :mod:`asymslip.core.edge_state`.

One valid cycle runs on Python floats and the ``math`` kernels (NumPy's cost per call would
be a hundred times its arithmetic); its first broken rule ends it and is named from the same
fields the array path marks.  Many cycles run on arrays, every element marked with the first
rule it breaks and evaluated on harmless stand-in values from there (no NumPy warning), so a
sweep's bad row does not stop the others.  A cycle on floats is evaluated again, on NumPy
scalars, only where Python's float arithmetic raises (an overflow, a division by zero) where
NumPy gives the inf or NaN that the rules then name.

Without bulk tension a symmetric contact is its own mirror image: where the two edges slip
opposite ways in their own frames, the left edge of one cycle is the right one with lam, L_II
and the slip direction negated (``derivations/edge_symmetry.py``), and is not computed again.

Examples
--------
>>> from asymslip import HertzLaw, LoadCycle
>>> evaluation = evaluate(HertzLaw(1.0, 1.0), LoadCycle(100, 0, 105, 1), 0.1)
>>> round(evaluation.edges[Edge.RIGHT].slip_zone_width, 6), evaluation.valid
(0.141929, True)
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike

from ..cycle import LoadCycle
from ..edge import EDGES, LEFT, RIGHT, Edge
from ..errors import InputError, as_numbers
from ..laws.base import (
    ContactLaw,
    LawState,
    LawTraits,
    Number,
    computes_on_floats,
    is_law,
    law_traits,
)
from ..rules import Verdict, check_friction, check_partial_slip, finite
from .edge_state import (
    EdgeState,
    Shear,
    both_edges_estimates,
    edge_state,
    mirrored,
    missing_edge,
    shear_multipliers,
)
from .estimates import EdgeEstimates, edge_estimates
from .operations import FLOATS, ArrayOperations, Operations, RuleBroken


class Evaluation(NamedTuple):
    """Both edges of every cycle, with each element's verdict (an immutable record)."""

    law: ContactLaw
    shape: tuple[int, ...]
    edges: Mapping[Edge, EdgeState]
    #: The array path's verdict; for one cycle on floats, the rule it broke (None: valid).
    checked: Verdict | RuleBroken | None = None

    @property
    def verdict(self) -> Verdict:
        """Each element's first broken rule (see :class:`~asymslip.rules.Verdict`)."""
        if isinstance(self.checked, Verdict):
            return self.checked
        if isinstance(self.checked, RuleBroken):
            return self.checked.verdict()
        return Verdict(())

    @property
    def valid(self) -> bool:
        """True when every element is valid."""
        if isinstance(self.checked, Verdict):
            return not self.checked.any_invalid
        return self.checked is None


def evaluate(law: ContactLaw, cycle: LoadCycle, mu: ArrayLike) -> Evaluation:
    """Both edges of every cycle, each element checked and marked, nothing raised for a rule.

    Invalid elements of arrays are evaluated on stand-in values and their numbers are
    meaningless (an invalid single cycle's are NaN): look at ``verdict`` before using them.

    Raises
    ------
    InputError
        Only for what is no cycle at all: ``law`` not a contact law, ``cycle`` not a
        :class:`~asymslip.cycle.LoadCycle`, ``mu`` not numbers or not broadcastable.
    """
    one = evaluate_one(law, cycle, mu)
    if one is not None and not isinstance(one, Evaluation):  # valid: (right, left)
        right, left = one
        return Evaluation(law, (), {RIGHT: right, LEFT: left})
    if one is not None:
        return one
    return evaluate_arrays(law, cycle, mu)


def evaluate_one(
    law: ContactLaw, cycle: LoadCycle, mu: ArrayLike
) -> tuple[EdgeState, EdgeState] | Evaluation | None:
    """One checked cycle on Python floats: its right and left edges where it is valid, its
    evaluation (the rule it broke) where it is not, or None where :func:`evaluate_arrays` must
    take it (many cycles, a cycle not checked, a friction coefficient or a state the rules
    refuse, float arithmetic that raises where NumPy gives inf or NaN, or no law at all)."""
    numbers = cycle.numbers if type(cycle) is LoadCycle else None
    if numbers is None or not cycle.checked or not is_law(law):
        return None
    friction = mu if type(mu) is float else _one_number(mu)
    if friction is None:
        return None
    return _one_cycle(law, numbers, friction)


def evaluate_arrays(law: ContactLaw, cycle: LoadCycle, mu: ArrayLike) -> Evaluation:
    """:func:`evaluate` on arrays: many cycles, or one that :func:`evaluate_one` left."""
    if not is_law(law):
        raise InputError(
            "law", "must be a contact law (HertzLaw, PowerLaw, ...; see asymslip.laws)", law
        )
    if not isinstance(cycle, LoadCycle):
        raise InputError(
            "cycle", "must be a LoadCycle(P1, Q1, P2, Q2[, sigma1, sigma2])", _shown(cycle)
        )
    return _arrays(law, cycle, mu)


def _one_number(value: object) -> float | None:
    """A friction coefficient given as one real number, as a float (None otherwise)."""
    if type(value) is float:
        return value
    if type(value) is int or (isinstance(value, np.floating | np.integer)):
        try:
            return float(value)
        except OverflowError:
            return None  # as_numbers names it
    if isinstance(value, np.ndarray) and value.ndim == 0 and value.dtype.kind in "fiu":
        return float(value)
    return None


def _shown(value: object) -> object:
    """What a message shows of a value of the wrong type: its type for anything long."""
    text = repr(value)
    return value if len(text) <= 60 else f"a {type(value).__name__}"


def _one_cycle(
    law: ContactLaw, numbers: tuple[float, ...], mu: float
) -> tuple[EdgeState, EdgeState] | Evaluation | None:
    """One checked cycle on Python floats (see :func:`evaluate_one`)."""
    P1, Q1, P2, Q2, sigma1, sigma2 = numbers
    # check_friction and check_partial_slip on floats (a NaN fails every comparison).
    if not (0.0 < mu < math.inf and abs(Q1) < mu * P1 and abs(Q2) < mu * P2):
        return None
    dP = P2 - P1
    try:
        if computes_on_floats(law):
            return _both_edges(FLOATS, law, mu, P1, dP, (Q2 - Q1) / dP, (sigma2 - sigma1) / dP)
        with np.errstate(all="ignore"):  # as on arrays: a law on NumPy never warns
            return _both_edges(FLOATS, law, mu, P1, dP, (Q2 - Q1) / dP, (sigma2 - sigma1) / dP)
    except RuleBroken as broken:
        return Evaluation(law, (), _MISSING_EDGES, broken)
    except (ZeroDivisionError, OverflowError, ValueError):
        return None


def _arrays(law: ContactLaw, cycle: LoadCycle, mu: ArrayLike) -> Evaluation:
    """Many cycles (or one the float path left), every element checked and marked."""
    friction = as_numbers("mu", mu)
    try:
        shape = np.broadcast_shapes(cycle.shape, friction.shape)
    except ValueError:
        raise InputError(
            "mu",
            f"has shape {friction.shape}, which does not broadcast with the cycle's shape "
            f"{cycle.shape}",
        ) from None
    # A checked cycle of this shape already passed its own rules.
    verdict = cycle.verdict(shape) if not cycle.checked or shape != cycle.shape else Verdict(shape)
    values = {
        name: np.broadcast_to(np.asarray(value, dtype=np.float64), shape)
        for name, value in cycle.values().items()
    }
    friction = np.broadcast_to(friction, shape)
    with np.errstate(all="ignore"):  # what overflows is marked in the verdict, never warned
        check_friction(verdict, friction)
        check_partial_slip(verdict, friction, values)
        # Stand-in values where a rule is already broken: the law and the kernels see valid
        # input.
        P1, P2 = values["P1"], values["P2"]
        dQ, dsigma = values["Q2"] - values["Q1"], values["sigma2"] - values["sigma1"]
        if verdict.any_invalid:
            ok = verdict.valid
            P1, P2 = np.where(ok, P1, 1.0), np.where(ok, P2, 2.0)
            dQ, dsigma = np.where(ok, dQ, 0.0), np.where(ok, dsigma, 0.0)
            friction = np.where(ok, friction, 1.0)
        dP = P2 - P1
        ops = ArrayOperations(verdict)
        right, left = _both_edges(ops, law, friction, P1, dP, dQ / dP, dsigma / dP)
    return Evaluation(law, shape, {RIGHT: right, LEFT: left}, verdict)


def _both_edges(
    ops: Operations, law: ContactLaw, mu: Number, P1: Number, dP: Number, lam: Number, eta: Number
) -> tuple[EdgeState, EdgeState]:
    """The pipeline: the law's state of the cycle, each edge's shear, estimates and checks;
    the right edge and the left one."""
    symmetric = law.symmetric
    right_law = law.for_edge(RIGHT)
    left_law = right_law if symmetric else law.for_edge(LEFT)
    right_state = _law_state(ops, right_law, P1, dP)
    left_state = right_state if symmetric else _law_state(ops, left_law, P1, dP)
    right_traits = law_traits(right_law)
    left_traits = right_traits if symmetric else law_traits(left_law)
    own = right_traits.own_shear_multipliers
    # The left edge is the right edge of the mirrored cycle: lam -> -lam, eta kept.
    if ops.scalar and symmetric and not own and eta != 0:
        # One cycle under bulk tension: no mirror image; both edges in one program, the law's
        # quantities shared.  (Arrays take each edge alone: the pair's intermediates of both
        # edges alive at once cost more memory than the calls it saves -- 6 % slower at 10^6
        # cycles of the rounded flat.)
        right_shear, left_shear, right_estimates, left_estimates = both_edges_estimates(
            ops, mu, lam, eta, right_state, dP
        )
        # Each edge straight from its estimates (what _edge does once it has them).
        extrapolates = right_traits.extrapolates
        right = edge_state(
            ops,
            right_law,
            right_state,
            mu,
            lam,
            eta,
            dP,
            RIGHT,
            right_shear,
            left_shear[2],
            right_estimates,
            extrapolates,
        )
        left = edge_state(
            ops,
            right_law,
            right_state,
            mu,
            -lam,
            eta,
            dP,
            LEFT,
            left_shear,
            right_shear[2],
            left_estimates,
            extrapolates,
        )
        _check_meeting(ops, right, left)
        return right, left
    right_shear = shear_multipliers(ops, right_law, right_state, mu, lam, eta, own)
    # A symmetric contact without bulk tension whose right edge slips is its own mirror
    # image (derivations/edge_symmetry.py): the left edge slips the other way in its own
    # frame, is asked exactly what the right edge was (the same oriented lam and
    # other-edge factor), and is the right edge with lam, L_II and the direction negated
    # -- not computed again.
    mirror = symmetric and not own and ops.everywhere((eta == 0) & (right_shear[2] != 0))
    left_shear = (
        right_shear
        if mirror
        else shear_multipliers(
            ops, left_law, left_state, mu, -lam, eta, left_traits.own_shear_multipliers
        )
    )
    right = _edge(
        ops,
        right_law,
        right_state,
        right_traits,
        mu,
        lam,
        eta,
        dP,
        RIGHT,
        right_shear,
        -right_shear[2] if mirror else left_shear[2],
    )
    if mirror:
        left = mirrored(right)
    else:
        left = _edge(
            ops,
            left_law,
            left_state,
            left_traits,
            mu,
            -lam,
            eta,
            dP,
            LEFT,
            left_shear,
            right_shear[2],
        )
    _check_meeting(ops, right, left)
    return right, left


def _law_state(ops: Operations, law: ContactLaw, P1: Number, dP: Number) -> LawState:
    """The law's quantities of the cycle at one edge, checked."""
    state = law.cycle_state(P1, dP)
    if ops.scalar and type(state.a1) is not float:  # a law on NumPy: 0-d results
        state = state.as_floats()
    _check_law(ops, state, law)
    return state


def _edge(
    ops: Operations,
    law: ContactLaw,
    state: LawState,
    traits: LawTraits,
    mu: Number,
    lam: Number,
    eta: Number,
    dP: Number,
    edge: Edge,
    shear: Shear,
    other_direction: Number,
) -> EdgeState:
    """One edge through the pipeline (``other_direction``: the other edge's slip direction in
    its own frame)."""
    own, extrapolates = traits
    estimates: EdgeEstimates | None = None  # an edge with its own multipliers has none of (21)'s
    if not own:
        estimates = edge_estimates(ops, mu, lam, eta, state, dP, shear[2], other_direction)
    return edge_state(
        ops, law, state, mu, lam, eta, dP, edge, shear, other_direction, estimates, extrapolates
    )


def _check_meeting(ops: Operations, right: EdgeState, left: EdgeState) -> None:
    """The two slip zones must leave a stick zone between them."""
    b_sum = right.b + left.b
    if not ops.everywhere(b_sum > 0):
        ops.require("slip_zones_meet", b_sum > 0, None, b_sum=b_sum)


def _check_law(ops: Operations, state: LawState, law: ContactLaw) -> None:
    """The law at the cycle's loads: defined, finite, increasing."""
    first = state.a1 + state.L_I1 + state.load_slope1
    second = state.a2 + state.da + state.L_I2 + state.load_slope2
    increasing = (state.load_slope1 > 0) & (state.load_slope2 > 0)
    if ops.everywhere(state.found1 & state.found2 & finite(first + second) & increasing):
        return  # the common case: one test
    name = law.name
    ops.require("law_range_1", state.found1, state.P1, law=name, range=law.range_note)
    ops.require("law_range_2", state.found2, state.P2, law=name, range=law.range_note)
    ops.require("law_finite_1", finite(first), state.P1, law=name)
    ops.require("law_finite_2", finite(second), state.P2, law=name)
    slope = -ops.maximum(-state.load_slope1, -state.load_slope2)
    ops.require("law_increasing", slope > 0, slope, law=name, slope=slope)


#: Both edges of a single cycle that broke a rule: nothing to report.
_MISSING_EDGES: Mapping[Edge, EdgeState] = {edge: missing_edge() for edge in EDGES}
