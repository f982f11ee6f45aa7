"""Steady-state slip zone at the contact edges: the paper's Section 2 on arrays of cycles.

:func:`evaluate` is the one evaluation model behind the API, the tractions, the figures and
the sweep.  It takes a law, cycles (a :class:`~asymslip.cycle.LoadCycle` whose fields may be
arrays) and friction coefficients (broadcast together), and

1. checks every element against the rules of :mod:`asymslip.rules`, marking each invalid
   element with the first rule it breaks instead of raising on the first;
2. asks the law once per cycle for everything the cycle needs
   (:meth:`~asymslip.laws.base.ContactLaw.cycle_state`: a1, a2, a2 - a1, L_I and the slopes),
   shared by both edges (for a symmetric law) and by every estimate;
3. evaluates both edges -- always both, since a cycle is a steady partial-slip state only if
   both edges are (their slip zones must not meet) -- with the generated kernels.

:func:`slip_zone` wraps it for people: scalars in, scalars out, as NumPy does; invalid input
raises :class:`~asymslip.errors.InputError` (or, with ``invalid="mark"``, comes back as NaN
with its reason in ``errors``).  A single valid cycle of a symmetric law is answered on Python
floats by :mod:`asymslip.single_cycle` (the same estimates and flags, without the machinery of
arrays); anything it cannot answer comes here.  Warnings are kept as bit flags per element
and turned into words only when asked, so that 10^6 cycles cost no 10^6 lists of strings.

Edges and slip direction (``derivations/edge_symmetry.py``): the left edge is the right edge of
the mirrored cycle (lam -> -lam, eta kept); backward slip is forward slip with
(lam, eta) -> (-lam, -eta).  The paper's formulas are evaluated on these oriented slopes.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from types import ModuleType
from typing import Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

import asymslip_gen
from asymslip_gen import scalar as scalar_kernels

from .cycle import LoadCycle
from .edge_estimates import (
    DENOMINATOR_TOLERANCE,
    DISAGREEMENTS,
    EdgeValues,
    disagreement_limits,
    edge_estimates,
    larger,
    slip_direction,
    stated_accuracy,
)
from .edge_flags import (
    ESTIMATES_CHECKED,
    EXTRAPOLATED_P1,
    EXTRAPOLATED_P2,
    MEASURE_FLAGS,
    MEASURE_KEYS,
    NO_SLIP,
    NUMBER_KEYS,
    OTHER_EDGE_STICKS,
    OUTSIDE_FLAGS,
    VALIDITY_THRESHOLD,
    warning_texts,
)
from .errors import InputError, as_numbers
from .laws.base import ContactLaw, LawState
from .rules import Verdict, check_denominator, check_friction, check_partial_slip, finite
from .single_cycle import evaluate_one

FloatArray = NDArray[np.float64]
Side = Literal["right", "left"]
SIDES: tuple[Side, Side] = ("right", "left")


# --- the evaluation -----------------------------------------------------------------------------
@dataclass
class Evaluation:
    """Both edges of every cycle, with each element's verdict."""

    law: ContactLaw
    shape: tuple[int, ...]
    verdict: Verdict
    edges: dict[str, EdgeValues]


def _where(condition: ArrayLike, yes: ArrayLike, no: ArrayLike) -> ArrayLike:
    """``numpy.where``, without its cost for a single cycle (plain Python then)."""
    if isinstance(condition, (bool, np.bool_)):
        return yes if condition else no
    return np.where(condition, yes, no)


def _is_array(value: object) -> bool:
    return isinstance(value, np.ndarray) and value.ndim > 0


def _shear_multipliers(
    law: ContactLaw,
    state: LawState,
    mu: FloatArray,
    lam: FloatArray,
    eta: FloatArray,
    kernels: ModuleType,
) -> tuple[FloatArray, FloatArray, FloatArray]:
    """L_II1, L_II2 and the slip direction of one edge (in its own frame).

    By (21) for a symmetric contact; an edge that knows its own shear multiplier (an
    asymmetric contact's, AS3 of derivations/asymmetric_edge_multipliers.py) gives it itself.
    """
    own = getattr(law, "shear_multiplier", None)
    if own is not None:
        L_II1, L_II2 = own(state.P1, lam, eta), own(state.P2, lam, eta)
    else:
        L_II1 = kernels.shear_edge_multiplier_proportional(lam, eta, state.a1, state.L_I1)
        L_II2 = kernels.shear_edge_multiplier_proportional(lam, eta, state.a2, state.L_I2)
    return L_II1, L_II2, slip_direction(mu, state.L_I2, L_II2)


def _edge(
    law: ContactLaw,
    state: LawState,
    mu: FloatArray,
    lam: FloatArray,
    eta: FloatArray,
    dP: FloatArray,
    verdict: Verdict,
    side: Side,
    shear: tuple[FloatArray, FloatArray, FloatArray],
    other_direction: FloatArray,
    kernels: ModuleType,
) -> EdgeValues:
    a1, a2, da, L_I1, L_I2 = state.a1, state.a2, state.da, state.L_I1, state.L_I2
    L_II1, L_II2, direction = shear
    slips = direction != 0
    orientation = _where(slips, direction, 1.0)
    lam_o, eta_o = orientation * lam, orientation * eta
    if hasattr(law, "shear_multiplier"):
        return _edge_with_own_multipliers(
            law, state, mu, lam, eta, dP, verdict, side, shear, slips, orientation, kernels
        )
    # The other edge slips the same way in the global frame when the two own-frame directions
    # differ in sign (the left edge's frame is mirrored); +1 too where it does not slip
    # (derivations/second_order_slip_zone.py).
    other_edge = _where(other_direction == 0, 1.0, -direction * other_direction)
    (paper_width, denominator, b_first_order, width, stick_width, P_K, eq24, eq26, eq27) = (
        edge_estimates(kernels, mu, lam_o, eta_o, state, dP, other_edge)
    )
    # (22), the paper's headline, and its cancellation-free width a1 - b.
    paper_width = _where(slips, paper_width, 0.0)
    # The headline: b to second order with both edges and bulk tension (b2), the estimate the
    # evidence supports (README, "How far to trust b").
    width = _where(slips, width, 0.0)
    b = a1 - width
    # Jaeger-Ciavarella: b = a(P_K) is exact for a symmetric law without bulk tension.
    exact = (eta == 0) & law.symmetric
    P_K = _where(slips, P_K, state.P1)
    if exact is True or (_is_array(exact) and exact.any()):
        b_exact = _where(
            exact, law.half_width_near(_where(exact, P_K, state.P1), state.P1, a1), np.nan
        )
    else:
        b_exact = np.full(np.shape(a1), np.nan) if _is_array(a1) else np.nan
    accuracy = stated_accuracy(a1, da, width)
    values = {
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
        "b_paper": a1 - paper_width,
        "b_first_order": _where(slips, b_first_order, a1),
        "b_exact": b_exact,
        "b_corrective_stick": _where(slips, a1 - stick_width, a1),
        "slip_direction": direction,
        "P_K": P_K,
        "paper_width": paper_width,
        "b_consistent": a1 - paper_width,  # (17)/(22): the b for which (15) solves (12)
        "eq24": eq24,
        "eq25": abs(width) / a1,
        "eq26": eq26,
        "eq27": _where(slips, eq27, 0.0),
    }
    disagree = 0
    limits = disagreement_limits(a1, da, width, accuracy)
    for (key, bit), limit in zip(DISAGREEMENTS, limits, strict=True):
        disagree = disagree | _where(slips & (abs(values[key] - b) > limit), bit, 0)
    disagree = disagree | _where(slips & (other_direction == 0), OTHER_EDGE_STICKS, 0)
    return _finish_edge(law, state, mu, verdict, side, values, denominator, slips, disagree)


def _finish_edge(
    law: ContactLaw,
    state: LawState,
    mu: FloatArray,
    verdict: Verdict,
    side: Side,
    values: dict[str, FloatArray],
    denominator: FloatArray,
    slips: ArrayLike,
    disagree: ArrayLike,
) -> EdgeValues:
    """What the asymptotic solution can answer at this edge (the rules), and the warnings."""
    L_I1, L_I2, L_II1, L_II2 = values["L_I1"], values["L_I2"], values["L_II1"], values["L_II2"]
    b, a2 = values["b"], values["a2"]
    scale = 2 * mu * (L_I1 + L_I2) + abs(L_II1) + abs(L_II2)
    tolerance = DENOMINATOR_TOLERANCE * scale
    admits = (
        ~slips | (denominator > tolerance)
        if not isinstance(slips, (bool, np.bool_))
        else (not slips) or denominator > tolerance
    )
    refused = ~np.asarray(admits)
    note = (
        law.resolution_note(
            np.broadcast_to(state.P1, refused.shape)[refused],
            np.broadcast_to(state.P2, refused.shape)[refused],
        )
        if refused.any()
        else ""
    )
    check_denominator(verdict, admits, mu, denominator, values, side=side, note=note)
    # Non-finite results first: a b that overflowed is not "outside the contact".
    checked = ("b", "slip_zone_width", "b_first_order", "L_II1", "L_II2", *MEASURE_KEYS)
    total = sum(values[key] for key in checked)
    if not (finite(total).all() if _is_array(total) else finite(total)):
        for key in checked:
            verdict.require(
                "result_finite", finite(values[key]), None, side=side, law=law.name, quantity=key
            )
    verdict.require(
        "b_range",
        (b > 0) & (b <= a2),
        None,
        side=side,
        b=b,
        eq25=values["eq25"],
        eq24=values["eq24"],
        eq27=values["eq27"],
    )
    flags = _where(slips, 0, NO_SLIP) | disagree
    for key, bit in MEASURE_FLAGS.items():
        flags = flags | _where(values[key] > VALIDITY_THRESHOLD, bit, 0)
    flags = flags | _where(law.extrapolated(state.P1), EXTRAPOLATED_P1, 0)
    flags = flags | _where(law.extrapolated(state.P2), EXTRAPOLATED_P2, 0)
    for key, (_, disagreement) in ESTIMATES_CHECKED.items():
        inside = (values[key] > 0) & (values[key] <= a2) | (values[key] != values[key])
        if not (inside.all() if _is_array(inside) else inside):  # NaN: not derived here
            values[key] = _where(inside, values[key], np.nan)
            flags = _where(inside, flags, (flags & ~disagreement) | OUTSIDE_FLAGS[key])
    return EdgeValues(values, flags)


def _edge_with_own_multipliers(
    law: ContactLaw,
    state: LawState,
    mu: FloatArray,
    lam: FloatArray,
    eta: FloatArray,
    dP: FloatArray,
    verdict: Verdict,
    side: Side,
    shear: tuple[FloatArray, FloatArray, FloatArray],
    slips: ArrayLike,
    orientation: ArrayLike,
    kernels: ModuleType,
) -> EdgeValues:
    """An edge whose multipliers are its own (an asymmetric or calibrated contact).

    b is (17) in the edge's own L_I and L_II: (21), and so (22), do not hold at an edge of an
    asymmetric contact (AS3, AS4), and neither do the second-order b2, the corrective-stick
    (40) or a(P_K) (AS7): those are reported as missing (NaN, null in JSON).  The first-order
    b is the first-order term of (17), which is (28) with lambda/mu + pi eta a1/(4 mu)
    replaced by the edge's own L_II1/(mu L_I1).  Stated accuracy: first order,
    2 (da/a1) |a1 - b|: (17) with AS3 agrees with an exact asymmetric solution to second order
    in dP without tension, but with bulk tension its dP^2 term is the one erratum 22-T finds
    spurious for symmetric contacts, and no correction is derived for asymmetric ones.
    """
    a1, a2, da, L_I1, L_I2 = state.a1, state.a2, state.da, state.L_I1, state.L_I2
    L_II1, L_II2, direction = shear
    L_II1_o, L_II2_o = orientation * L_II1, orientation * L_II2
    width = _where(
        slips, kernels.slip_zone_width_from_multipliers(mu, da, L_I1, L_I2, L_II1_o, L_II2_o), 0.0
    )
    b = a1 - width
    denominator = kernels.stick_boundary_denominator_from_multipliers(
        mu, L_I1, L_I2, L_II1_o, L_II2_o
    )
    worst_slope = larger(state.a_slope1, state.a_slope2)
    worst_multiplier_slope = larger(abs(state.L_I_slope1), abs(state.L_I_slope2))
    ratio = L_II1_o / L_I1  # the edge's own lambda + pi eta a1/4
    first_order = a1 * kernels.stick_ratio_first_order(mu, ratio, 0.0, a1, dP, state.a_slope1)
    missing = np.full(np.shape(a1), np.nan) if _is_array(a1) else np.nan
    values = {
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
        "b_accuracy": 2 * da / a1 * abs(width),
        "b_paper": missing,
        "b_first_order": _where(slips, first_order, a1),
        "b_exact": missing,
        "b_corrective_stick": missing,
        "slip_direction": direction,
        "P_K": missing,
        "paper_width": missing,
        "b_consistent": b,  # b is (17) in the edge's own multipliers
        "eq24": kernels.contact_growth_measure(dP, worst_slope, a1),
        "eq25": abs(width) / a1,
        "eq26": kernels.multiplier_growth_measure(dP, worst_multiplier_slope, L_I1),
        "eq27": _where(
            slips, kernels.slip_zone_growth_measure(mu, ratio, 0.0, a1, dP, worst_slope), 0.0
        ),
    }
    return _finish_edge(law, state, mu, verdict, side, values, denominator, slips, 0)


def _check_law(verdict: Verdict, state: LawState, law: ContactLaw) -> None:
    """The law at the cycle's loads: defined, finite, increasing."""
    name = law.name
    verdict.require("law_range_1", state.found1, state.P1, law=name, range=law.range_note)
    verdict.require("law_range_2", state.found2, state.P2, law=name, range=law.range_note)
    for number, quantities in (
        ("1", (state.a1, state.L_I1, state.load_slope1)),
        ("2", (state.a2, state.da, state.L_I2, state.load_slope2)),
    ):
        verdict.require(
            f"law_finite_{number}", finite(sum(quantities)), getattr(state, f"P{number}"), law=name
        )
    slope = -larger(-state.load_slope1, -state.load_slope2)
    verdict.require("law_increasing", slope > 0, slope, law=name, slope=slope)


def evaluate(law: ContactLaw, cycle: LoadCycle, mu: ArrayLike) -> Evaluation:
    """Both edges of every cycle, each element checked and marked, nothing raised.

    Invalid elements are evaluated on harmless stand-in values (so that no NumPy warning is
    raised) and their results are meaningless: look at ``verdict`` before using them.
    """
    with np.errstate(all="ignore"):  # what overflows is marked in the verdict, never warned
        try:
            return _evaluate(law, cycle, mu, float)
        except (ZeroDivisionError, OverflowError, ValueError):
            # A single cycle runs on Python floats and math (fast), which raise where NumPy
            # gives inf or NaN; such a cycle is evaluated again on NumPy scalars and kernels,
            # so that the rules see the infs and NaNs and name them.
            return _evaluate(law, cycle, mu, np.float64)


def _evaluate(law: ContactLaw, cycle: LoadCycle, mu: ArrayLike, scalar: type[float]) -> Evaluation:
    mu = as_numbers("mu", mu)
    shape = (
        () if cycle.shape == () and mu.shape == () else np.broadcast_shapes(cycle.shape, mu.shape)
    )
    verdict = (
        cycle.verdict(shape) if not cycle.checked or shape != cycle.shape else Verdict(shape)
    )  # a checked cycle of this shape already passed its rules
    if shape == ():
        # One cycle: scalars through the kernels cost a fraction of 0-d arrays.
        mu = scalar(mu)
        values = {name: scalar(value) for name, value in cycle.values().items()}
    else:
        mu = np.broadcast_to(mu, shape)
        values = {name: np.broadcast_to(value, shape) for name, value in cycle.values().items()}
    check_friction(verdict, mu)
    check_partial_slip(verdict, mu, values)
    # Stand-in values where a rule is already broken: the law and the kernels see valid input.
    P1, P2 = values["P1"], values["P2"]
    dQ, dsigma = values["Q2"] - values["Q1"], values["sigma2"] - values["sigma1"]
    if verdict.any_invalid:
        ok = verdict.valid
        P1, P2 = np.where(ok, P1, 1.0), np.where(ok, P2, 2.0)
        dQ, dsigma = np.where(ok, dQ, 0.0), np.where(ok, dsigma, 0.0)
        mu = np.where(ok, mu, 1.0)
        if shape == ():
            P1, P2, dQ, dsigma, mu = (scalar(v) for v in (P1, P2, dQ, dsigma, mu))
    dP = P2 - P1
    lam, eta = dQ / dP, dsigma / dP
    states: dict[str, LawState] = {}
    for side in SIDES if not law.symmetric else SIDES[:1]:
        edge_law = law.for_edge(side)
        state = edge_law.cycle_state(P1, dP)
        if shape == ():  # plain scalars from here (kernels return NumPy scalars or 0-d arrays)
            state = state.as_floats(scalar)
        _check_law(verdict, state, edge_law)
        states[side] = state
    if law.symmetric:
        states["left"] = states["right"]
    # One cycle on Python floats uses the math kernels (NumPy's per-call cost would dominate).
    kernels = scalar_kernels if scalar is float and shape == () else asymslip_gen
    shear = {
        side: _shear_multipliers(law.for_edge(side), states[side], mu, sign * lam, eta, kernels)
        for side, sign in (("right", 1.0), ("left", -1.0))
    }
    edges: dict[str, EdgeValues] = {}
    for side, sign, other in (("right", 1.0, "left"), ("left", -1.0, "right")):
        edges[side] = _edge(
            law.for_edge(side),
            states[side],
            mu,
            sign * lam,
            eta,
            dP,
            verdict,
            side,
            shear[side],
            shear[other][2],
            kernels,
        )
    b_sum = edges["right"].values["b"] + edges["left"].values["b"]
    verdict.require("slip_zones_meet", b_sum > 0, None, b_sum=b_sum)
    return Evaluation(law, shape, verdict, edges)


# --- the result ----------------------------------------------------------------------------------
@dataclass(frozen=True)
class SlipZoneResult:
    """Everything `asymslip slip-zone` reports for one edge; field names are the JSON keys.

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
    b_first_order: FloatArray | float
    b_exact: FloatArray | float | None
    b_corrective_stick: FloatArray | float | None
    slip_direction: FloatArray | float
    validity: dict[str, FloatArray | float]
    warning_flags: NDArray[np.int64] | int = field(repr=False)
    law: ContactLaw = field(repr=False)
    errors: list[str | None] | None = field(default=None, repr=False)
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


def _one_result(fields: dict[str, object]) -> SlipZoneResult:
    """One cycle's edge as a result, from all its fields (the dictionary becomes its own)."""
    # Every field set at once, where the dataclass's __init__ would set them one by one (it
    # checks nothing), at a fraction of its cost for 21 fields: one cycle is timed in
    # microseconds.
    result = object.__new__(SlipZoneResult)
    object.__setattr__(result, "__dict__", fields)
    return result


def _edge_result(
    evaluation: Evaluation, side: str, scalar: bool, errors: list[str | None] | None
) -> SlipZoneResult:
    edge = evaluation.edges[side]
    law = evaluation.law.for_edge(side)  # type: ignore[arg-type]
    if scalar:  # Python floats (NumPy scalars where a cycle fell back on them), None for NaN
        fields: dict[str, object] = {}
        for key in NUMBER_KEYS:
            value = float(edge.values[key])
            fields[key] = value if value == value else None
        fields["slip_direction"] = int(edge.values["slip_direction"])
        fields["validity"] = {key: float(edge.values[key]) for key in MEASURE_KEYS}
        fields.update(warning_flags=int(edge.flags), law=law, errors=errors, left=None)
        return _one_result(fields)
    invalid = ~evaluation.verdict.valid
    shape = evaluation.shape

    def column(key: str) -> FloatArray:
        value = np.broadcast_to(np.asarray(edge.values[key], dtype=np.float64), shape)
        return np.where(invalid, np.nan, value) if invalid.any() else np.array(value)

    return SlipZoneResult(
        **{key: column(key) for key in NUMBER_KEYS},
        validity={key: column(key) for key in MEASURE_KEYS},
        warning_flags=np.broadcast_to(np.asarray(edge.flags, dtype=np.int64), shape).copy(),
        law=law,
        errors=errors,
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
        are NaN and ``result.errors`` gives each one's reason.

    Returns
    -------
    SlipZoneResult
        b from (22), the slip-zone width a1 - b (cancellation-free), b to first order (28),
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
    one = evaluate_one(law, cycle, mu)  # one valid cycle of a symmetric law: floats, no arrays
    if one is not None:
        right_edge, left_edge = one
        if edge == "left":
            return _one_result(left_edge)
        if edge == "both":
            right_edge["left"] = _one_result(left_edge)
        return _one_result(right_edge)
    evaluation = evaluate(law, cycle, mu)
    errors = None
    if evaluation.verdict.any_invalid:
        if invalid == "raise":
            evaluation.verdict.raise_first()
        errors = evaluation.verdict.messages()
    scalar = evaluation.shape == ()
    if edge == "left":
        return _edge_result(evaluation, "left", scalar, errors)
    right = _edge_result(evaluation, "right", scalar, errors)
    if edge == "both":
        object.__setattr__(right, "left", _edge_result(evaluation, "left", scalar, errors))
    return right
