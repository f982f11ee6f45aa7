"""Steady-state slip zone at the contact edges: the paper's Section 2, for people.

:func:`slip_zone` takes a law, a cycle (a :class:`~asymslip.cycle.LoadCycle`, whose fields may be
arrays) and friction coefficients, evaluates both edges through the slip-zone core
(:func:`asymslip.core.evaluation.evaluate`, re-exported here) and returns a
:class:`SlipZoneResult`: scalars in, scalars out, as NumPy does; invalid input raises
:class:`~asymslip.errors.InputError` (or, with ``invalid="mark"``, comes back as NaN with its
reason in ``errors``).  Warnings are kept as bit flags per element and turned into words only
when asked, so that 10^6 cycles cost no 10^6 lists of strings.
"""

from __future__ import annotations

import math
from typing import Literal, NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .core.edge_state import EdgeState, missing_edge
from .core.evaluation import Evaluation, evaluate, evaluate_arrays, evaluate_one
from .core.flags import MEASURE_KEYS, NUMBER_KEYS, warning_texts
from .cycle import LoadCycle
from .edge import LEFT, RIGHT, Edge
from .errors import InputError
from .laws.base import ContactLaw

__all__ = ["Evaluation", "SlipZoneResult", "evaluate", "slip_zone"]

FloatArray = NDArray[np.float64]


# --- the result ----------------------------------------------------------------------------------
class SlipZoneResult(NamedTuple):
    """Everything `asymslip slip-zone` reports for one edge; field names are the JSON keys.

    An immutable record (a named tuple: one cycle's result is built in a microsecond, where a
    frozen dataclass of 21 fields costs eight).

    Fields are floats for one cycle and arrays for many.  Lengths are in the units of the
    law's parameters.  ``b`` is measured from the contact centre along the edge's outward
    direction (for the left edge, the distance of the left stick boundary from the centre).
    ``b_exact`` is None (NaN in arrays) where no exact solution exists (eta != 0, an
    asymmetric contact); so are ``b_paper``, ``b_corrective_stick`` and ``P_K``-based values
    for an edge with its own multipliers (a calibrated contact), where they are not derived,
    and ``b_paper``, ``b_first_order`` and ``b_corrective_stick`` where they fall outside the
    contact (0, a2], which ``warnings`` then says.
    ``errors`` is None when every element is valid; with ``invalid="mark"`` it lists each
    element's reason (None where valid) and the invalid elements' numbers are NaN.
    """

    a1: FloatArray | float
    a2: FloatArray | float
    lam: FloatArray | float
    eta: FloatArray | float
    L_I1: FloatArray | float
    L_I2: FloatArray | float
    L_II1: FloatArray | float
    L_II2: FloatArray | float
    b: FloatArray | float
    slip_zone_width: FloatArray | float
    b_accuracy: FloatArray | float
    b_paper: FloatArray | float | None
    b_first_order: FloatArray | float | None
    b_exact: FloatArray | float | None
    b_corrective_stick: FloatArray | float | None
    slip_direction: FloatArray | float
    validity: dict[str, FloatArray | float]
    warning_flags: NDArray[np.int64] | int
    law: ContactLaw
    errors: list[str | None] | None = None
    left: SlipZoneResult | None = None

    @property
    def warnings(self) -> list[str] | list[list[str]]:
        """The warnings in words: a list for one cycle, a list of lists for many."""
        if np.ndim(self.warning_flags) == 0:
            return warning_texts(int(self.warning_flags), self.law)
        return [warning_texts(int(flags), self.law) for flags in np.ravel(self.warning_flags)]

    def to_dict(self) -> dict[str, object]:
        """The JSON object of one cycle: these keys, with ``left`` when both edges were asked."""
        if np.ndim(self.a1):
            raise InputError("cycle", "to_dict describes one cycle; this result holds many")
        data: dict[str, object] = {key: getattr(self, key) for key in NUMBER_KEYS}
        data["validity"] = dict(self.validity)
        data["warnings"] = self.warnings
        if self.left is not None:
            data["left"] = self.left.to_dict()
        return data


def _scalar_result(
    state: EdgeState,
    law: ContactLaw,
    valid: bool,
    errors: list[str | None] | None,
    left: SlipZoneResult | None = None,
) -> SlipZoneResult:
    """One cycle's edge; every number None (null in JSON) for an invalid cycle."""
    if not valid:
        state = _NOTHING
    elif type(state[0]) is not float or type(state[13]) is not float:
        state = _as_floats(state)
    # One unpacking, in the order of EdgeState's fields (a named tuple's attributes cost more).
    (
        a1,
        a2,
        lam,
        eta,
        L_I1,
        L_I2,
        L_II1,
        L_II2,
        b,
        width,
        accuracy,
        b_paper,
        b_first_order,
        b_exact,
        b_corrective_stick,
        direction,
        eq24,
        eq25,
        eq26,
        eq27,
        _,
        _,
        flags,
    ) = state
    # Built as the tuple it is (tuple.__new__), in field order: the named tuple's own __new__
    # binds 21 arguments one by one, and one cycle is timed in microseconds.
    return _new_result(
        SlipZoneResult,
        (
            a1,
            a2,
            lam,
            eta,
            L_I1,
            L_I2,
            L_II1,
            L_II2,
            b,
            width,
            accuracy,
            # None (null in JSON) for an estimate not derived here (NaN)
            b_paper if b_paper == b_paper else None,
            b_first_order if b_first_order == b_first_order else None,
            b_exact if b_exact == b_exact else None,
            b_corrective_stick if b_corrective_stick == b_corrective_stick else None,
            int(direction) if valid else math.nan,
            {"eq24": eq24, "eq25": eq25, "eq26": eq26, "eq27": eq27},
            flags,
            law,
            errors,
            left,
        ),
    )


def _as_floats(state: EdgeState) -> EdgeState:
    """An edge evaluated on NumPy scalars (where Python's float arithmetic raised), or with
    a(P_K) from a law that computes on NumPy, as Python floats and an int."""
    return EdgeState._make([*map(float, state[:22]), int(state[22])])


#: A named tuple built from its fields in order, without its __new__ (see _scalar_result).
_new_result = tuple.__new__


def _array_result(
    evaluation: Evaluation,
    edge: Edge,
    errors: list[str | None] | None,
    left: SlipZoneResult | None = None,
) -> SlipZoneResult:
    state = evaluation.edges[edge]
    verdict = evaluation.verdict
    invalid = ~verdict.valid
    shape = evaluation.shape

    def column(key: str) -> FloatArray:
        value = np.broadcast_to(np.asarray(getattr(state, key), dtype=np.float64), shape)
        return np.where(invalid, np.nan, value) if invalid.any() else np.array(value)

    numbers = {key: column(key) for key in NUMBER_KEYS}
    return SlipZoneResult(
        **numbers,
        validity={key: column(key) for key in MEASURE_KEYS},
        warning_flags=np.broadcast_to(np.asarray(state.flags, dtype=np.int64), shape).copy(),
        law=evaluation.law.for_edge(edge),
        errors=errors,
        left=left,
    )


def slip_zone(
    law: ContactLaw,
    cycle: LoadCycle,
    mu: ArrayLike,
    *,
    edge: Literal["right", "left", "both"] = "right",
    invalid: Literal["raise", "mark"] = "raise",
) -> SlipZoneResult:
    """Steady-state slip zone at the contact edges, for one cycle or arrays of them.

    Parameters
    ----------
    law
        The contact law, e.g. ``HertzLaw(R=1, E_star=1)``.
    cycle
        The load cycle (states 1 and 2, P2 > P1); its fields may be arrays.
    mu
        Coefficient of friction, > 0; broadcast against the cycle's fields.
    edge
        ``"right"`` (the paper's edge), ``"left"``, or ``"both"`` (right-edge fields at the
        top level and the left edge's in ``.left``).  Both edges are checked in every case:
        a cycle is a steady partial-slip state only if both are.
    invalid
        ``"raise"`` (default): an :class:`InputError` for the first invalid element, naming the
        parameter, the rule and how many elements break one.  ``"mark"``: invalid elements
        are NaN and ``result.errors`` gives each one's reason.  A :class:`LoadCycle` refuses
        its own bad elements (NaN, P2 <= P1) when built; to have them marked too, build it
        with :meth:`LoadCycle.unchecked`.

    Returns
    -------
    SlipZoneResult
        The headline b (b2: second order in dP with both edges and bulk tension) and its
        stated accuracy, the slip-zone width a1 - b (cancellation-free), the paper's (22) as
        ``b_paper``, b to first order (28),
        the corrective-stick b (40), the exact b = a(P_K) of (33) when eta = 0, the slip
        direction, the validity measures (24)-(27) and warnings.  Floats for one cycle,
        arrays for many.

    Raises
    ------
    InputError
        Naming the parameter and the rule (see :mod:`asymslip.rules`): non-finite or
        non-positive values, P2 <= P1, gross sliding at a state (|Q_i| >= mu P_i), a law that
        cannot carry a load or is not increasing, no steady partial-slip state ((17) has a
        non-positive denominator), a slip zone outside the contact, or the two edges' slip
        zones meeting.

    Examples
    --------
    >>> from asymslip import HertzLaw, LoadCycle, slip_zone
    >>> result = slip_zone(HertzLaw(R=1, E_star=1), LoadCycle(100, 0, 105, 1), mu=0.1)
    >>> round(result.slip_zone_width, 6), round(result.a1 - result.b_exact, 6)
    (0.141929, 0.14194)
    """
    if edge not in ("right", "left", "both"):
        raise InputError("edge", "must be 'right', 'left' or 'both'", edge)
    if invalid not in ("raise", "mark"):
        raise InputError("invalid", "must be 'raise' or 'mark'", invalid)
    one = evaluate_one(law, cycle, mu)
    if one is not None and not isinstance(one, Evaluation):  # one valid cycle, on floats
        right_edge, left_edge = one
        if edge == "right":
            return _scalar_result(right_edge, law.for_edge(RIGHT), True, None)
        if edge == "left":
            return _scalar_result(left_edge, law.for_edge(LEFT), True, None)
        return _scalar_result(
            right_edge,
            law.for_edge(RIGHT),
            True,
            None,
            _scalar_result(left_edge, law.for_edge(LEFT), True, None),
        )
    evaluation = evaluate_arrays(law, cycle, mu) if one is None else one
    errors = None
    valid = evaluation.valid
    if not valid:
        if invalid == "raise":
            evaluation.verdict.raise_first()
        errors = evaluation.verdict.messages()
    edges = evaluation.edges
    if evaluation.shape == ():
        evaluated = evaluation.law
        if edge == "left":
            return _scalar_result(edges[LEFT], evaluated.for_edge(LEFT), valid, errors)
        left = None
        if edge == "both":
            left = _scalar_result(edges[LEFT], evaluated.for_edge(LEFT), valid, errors)
        return _scalar_result(edges[RIGHT], evaluated.for_edge(RIGHT), valid, errors, left)
    if edge == "left":
        return _array_result(evaluation, LEFT, errors)
    left = _array_result(evaluation, LEFT, errors) if edge == "both" else None
    return _array_result(evaluation, RIGHT, errors, left)


#: The numbers of an invalid single cycle: none.
_NOTHING = missing_edge()
