"""The one table of rules an input must satisfy, checked per element.

Every entry point -- :class:`~asymslip.cycle.LoadCycle`, :func:`~asymslip.slip_zones.slip_zone`,
the tractions, the sweep -- checks its inputs against the rules below and nothing else.  A rule
is checked on whole arrays: a :class:`Verdict` records, for each element, the first rule it
breaks (in the order of :data:`RULES`) and the value to show.  The Python API then raises an
:class:`~asymslip.errors.InputError` for the first broken element; the sweep writes each row's
message in its ``error`` column and goes on with the others.  So a rule is stated once, and a
row of a sweep gets exactly the message the API would raise for it.

The rules are of three kinds, checked in this order: the inputs themselves (finite, positive,
ordered); the physics of steady partial slip (no gross sliding at either state); and what the
contact law and the asymptotic solution can answer (a law defined at the loads, a stick boundary
inside the contact, a stick zone left between the two edges' slip zones).

Examples
--------
>>> import numpy as np
>>> from asymslip.rules import Verdict, check_friction
>>> verdict = Verdict((3,))
>>> check_friction(verdict, np.array([0.3, 0.0, -0.2]))
>>> verdict.messages()
[None, 'mu: must be > 0 (got 0.0)', 'mu: must be > 0 (got -0.2)']
>>> verdict.raise_first()
Traceback (most recent call last):
    ...
asymslip.errors.InputError: mu: must be > 0 (got 0.0; at element 1; 2 of 3 elements break a rule)
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any, TypeAlias

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .errors import InputError

FloatArray = NDArray[np.float64]
BoolArray = NDArray[np.bool_]
#: A number of a cycle: a Python float for one cycle, a float64 array for many (unchecked, as
#: :data:`asymslip.laws.base.Number`: NumPy's stubs cannot type arithmetic mixing the two).
Number: TypeAlias = Any


@dataclass(frozen=True)
class Rule:
    """One rule: the parameter it is about and what it says.

    ``text`` may name values of the element that broke it, as ``{name}`` fields filled from
    the values the check supplies (``{P1}``, ``{mu_P1}``, ``{side}`` ...); they are formatted
    with 6 significant digits.
    """

    code: int
    parameter: str
    text: str

    def message(self, shown: float | None, values: Mapping[str, object]) -> InputError:
        """The error for one element that broke this rule."""
        fields = {
            key: (_number_text(value) if isinstance(value, float) else value)
            for key, value in values.items()
        }
        return InputError(self.parameter, self.text.format(**fields), shown)


def _number_text(value: float) -> str:
    """A value named in a message: 6 digits, or in words where it is not a finite number (a
    message never prints inf or nan as though they were numbers)."""
    if math.isfinite(value):
        return f"{value:.6g}"
    if math.isnan(value):
        return "undefined in double precision"
    return ("a negative number" if value < 0 else "a number") + " beyond double precision"


def _rule_table() -> dict[str, Rule]:
    texts: list[tuple[str, str, str]] = []
    for name in ("P1", "Q1", "P2", "Q2", "sigma1", "sigma2", "mu"):
        texts.append((f"{name}_finite", name, "must be finite (not inf or nan)"))
    texts += [
        ("P1_positive", "P1", "must be > 0"),
        ("P2_positive", "P2", "must be > 0"),
        (
            "P_order",
            "P2",
            "must exceed P1: state 2 is the state with the larger normal load "
            "(swap the two states; for P2 == P1 the paper's analysis does not apply)",
        ),
        ("mu_positive", "mu", "must be > 0"),
        ("dQ_finite", "Q2", "Q2 - Q1 overflows double precision"),
        ("dsigma_finite", "sigma2", "sigma2 - sigma1 overflows double precision"),
        (
            "lam_finite",
            "Q2",
            "lambda = (Q2 - Q1)/(P2 - P1) overflows double precision: the "
            "load change is too small for the shear change",
        ),
        (
            "eta_finite",
            "sigma2",
            "eta = (sigma2 - sigma1)/(P2 - P1) overflows double precision: "
            "the load change is too small for the tension change",
        ),
        (
            "sliding_1",
            "Q1",
            "|Q1| = {abs_Q1} must be < mu P1 = {mu_P1}: at state 1 the contact "
            "would slide as a whole (gross sliding), not slip partially",
        ),
        (
            "sliding_2",
            "Q2",
            "|Q2| = {abs_Q2} must be < mu P2 = {mu_P2}: at state 2 the contact "
            "would slide as a whole (gross sliding), not slip partially",
        ),
        # The contact law at the loads of the cycle.
        (
            "law_range_1",
            "P1",
            "no contact half-width of the {law} law carries this load "
            "(P(a) = P1 has no root a > 0 where P increases with a): the load is outside the "
            "law's range{range}",
        ),
        (
            "law_range_2",
            "P2",
            "no contact half-width of the {law} law carries this load "
            "(P(a) = P2 has no root a > 0 where P increases with a): the load is outside the "
            "law's range{range}",
        ),
        (
            "law_finite_1",
            "P1",
            "the {law} law gives a non-finite contact half-width or edge "
            "multiplier at this load (overflow in double precision)",
        ),
        (
            "law_finite_2",
            "P2",
            "the {law} law gives a non-finite contact half-width or edge "
            "multiplier at this load (overflow in double precision)",
        ),
        (
            "law_increasing",
            "law",
            "the {law} contact law must be increasing (dP/da > 0) over "
            "the cycle; dP/da = {slope} at one of its loads",
        ),
        # What the asymptotic solution can answer, per edge.
        # The denominator of (17) is named by the load change that makes it non-positive (the
        # tension change where the cycle without it would have a state), not by mu.
        (
            "denominator_tension",
            "sigma2",
            "the bulk-tension change sigma2 - sigma1 is too large for mu = {mu}: at the {side} "
            "edge the denominator of (17), mu (L_I1 + L_I2) + L_II1 - L_II2, is not positive "
            "({denominator}), so no steady partial-slip state exists (the stick boundary would "
            "lie beyond a2){note}",
        ),
        (
            "denominator_shear",
            "Q2",
            "the shear-force change Q2 - Q1 is too large for mu = {mu}: at the {side} edge the "
            "denominator of (17), mu (L_I1 + L_I2) + L_II1 - L_II2, is not positive "
            "({denominator}), so no steady partial-slip state exists (the stick boundary would "
            "lie beyond a2){note}",
        ),
        (
            "result_finite",
            "cycle",
            "the {law} law gives a non-finite {quantity} at the {side} "
            "edge (overflow in double precision)",
        ),
        (
            "b_range",
            "cycle",
            "at the {side} edge the stick boundary b = {b} lies outside the "
            "contact (0, a2]: the asymptotic solution is outside its range, eq25 = "
            "|b - a1|/a1 = {eq25} is not small (eq24 = {eq24}, eq27 = {eq27}){note}",
        ),
        (
            "slip_zones_meet",
            "cycle",
            "the slip zones of the two edges meet (b_right + b_left = "
            "{b_sum} <= 0): no stick zone is left, so the contact cannot be in steady partial "
            "slip",
        ),
    ]
    return {
        key: Rule(code, parameter, text)
        for code, (key, parameter, text) in enumerate(texts, start=1)
    }


#: Every rule, by key, in the order elements are checked against them.
RULES: dict[str, Rule] = _rule_table()
_BY_CODE: dict[int, Rule] = {rule.code: rule for rule in RULES.values()}


class Verdict:
    """Per element: the first rule broken (0: none) and what to show with it.

    Rules must be applied in the order of :data:`RULES` for the first broken one to be
    reported, which is what the callers do.  Broken elements keep only their first rule.
    """

    def __init__(self, shape: tuple[int, ...]) -> None:
        self.shape = shape
        self.code = np.zeros(shape, dtype=np.int16)
        self.shown = np.full(shape, np.nan)
        self.has_shown = np.zeros(shape, dtype=bool)
        self._fields: dict[int, dict[str, ArrayLike]] = {}

    @property
    def valid(self) -> BoolArray:
        valid: BoolArray = self.code == 0  # NumPy's stubs type == on arrays as Any
        return valid

    @property
    def any_invalid(self) -> bool:
        return bool(self.code.any())

    def require(
        self,
        key: str,
        ok: ArrayLike | bool,
        shown: ArrayLike | None = None,
        **fields: ArrayLike | str,
    ) -> None:
        """Mark the still-valid elements where ``ok`` fails as breaking rule ``key``.

        ``fields`` are the values the rule's text names (arrays broadcast to the shape, or
        plain strings such as the law's name).  Cheap when the rule holds everywhere, which is
        the common case (one check for a single cycle, one reduction for an array).
        """
        if isinstance(ok, np.ndarray) and ok.ndim:
            if ok.all():
                return
            broken = ~np.broadcast_to(ok, self.shape)
        elif ok:
            return
        else:
            broken = np.ones(self.shape, dtype=bool)
        new = broken & (self.code == 0)
        if not new.any():
            return
        rule = RULES[key]
        self.code[new] = rule.code
        if shown is not None:
            self.shown[new] = np.broadcast_to(np.asarray(shown, dtype=np.float64), self.shape)[new]
            self.has_shown[new] = True
        stored = self._fields.setdefault(rule.code, {})
        for name, value in fields.items():
            if isinstance(value, str):
                stored[name] = value
                continue
            column = stored.get(name)
            if column is None or isinstance(column, str):
                column = np.full(self.shape, np.nan)
            column = np.array(column, dtype=np.float64)
            column[new] = np.broadcast_to(np.asarray(value, dtype=np.float64), self.shape)[new]
            stored[name] = column

    def error(self, index: int | tuple[int | np.integer[Any], ...]) -> InputError | None:
        """The error of one element, or None where it is valid."""
        if not self.shape:
            index = ()
        code = int(self.code[index])
        if code == 0:
            return None
        rule = _BY_CODE[code]
        values = {
            name: (column if isinstance(column, str) else float(np.asarray(column)[index]))
            for name, column in self._fields.get(code, {}).items()
        }
        shown = float(self.shown[index]) if self.has_shown[index] else None
        if shown is not None and not np.isfinite(shown):
            shown = None  # the rule says what is wrong; never print inf or nan as a number
        return rule.message(shown, values)

    def first_error(self) -> InputError | None:
        """The error of the first invalid element (C order), naming its index for arrays."""
        invalid = np.flatnonzero(self.code.ravel())
        if invalid.size == 0:
            return None
        flat = int(invalid[0])
        index = np.unravel_index(flat, self.shape) if self.shape else ()
        error = self.error(index)
        assert error is not None
        if self.shape:
            where = (
                f"at element {flat}"
                if len(self.shape) == 1
                else f"at element {tuple(int(i) for i in index)}"
            )
            if invalid.size > 1:
                where += f"; {invalid.size} of {self.code.size} elements break a rule"
            error = InputError(error.parameter, error.rule, error.value, where)
        return error

    def raise_first(self) -> None:
        """Raise the first element's error, if any."""
        error = self.first_error()
        if error is not None:
            raise error

    def messages(self) -> list[str | None]:
        """Each element's message (None where valid), flattened in C order."""
        out: list[str | None] = [None] * self.code.size
        for flat in np.flatnonzero(self.code.ravel()).tolist():
            index = np.unravel_index(flat, self.shape) if self.shape else ()
            out[flat] = str(self.error(index))
        return out


def finite(value: Number) -> Number:
    """True where finite: ``x - x == 0`` is False for inf and NaN, for arrays and floats alike
    (and, unlike ``numpy.isfinite``, costs nothing for a Python float).  Call it inside
    ``numpy.errstate(invalid="ignore")``: inf - inf is the NaN it looks for."""
    return value - value == 0


def check_cycle_inputs(verdict: Verdict, values: Mapping[str, FloatArray]) -> None:
    """The rules on the cycle's own numbers: finite, P1, P2 > 0, P2 > P1.

    ``values`` holds ``P1, Q1, P2, Q2, sigma1, sigma2`` (broadcast to the verdict's shape, or
    Python floats for a single cycle).
    """
    for name in ("P1", "Q1", "P2", "Q2", "sigma1", "sigma2"):
        verdict.require(f"{name}_finite", finite(values[name]), values[name])
    verdict.require("P1_positive", values["P1"] > 0, values["P1"])
    verdict.require("P2_positive", values["P2"] > 0, values["P2"])
    verdict.require("P_order", values["P2"] > values["P1"], values["P2"])


def check_changes(
    verdict: Verdict,
    dQ: FloatArray,
    dsigma: FloatArray,
    lam: FloatArray,
    eta: FloatArray,
    values: Mapping[str, FloatArray],
) -> None:
    """Overflow of the load changes and the path slopes (18)."""
    verdict.require("dQ_finite", finite(dQ), values["Q2"])
    verdict.require("dsigma_finite", finite(dsigma), values["sigma2"])
    verdict.require("lam_finite", finite(lam), values["Q2"])
    verdict.require("eta_finite", finite(eta), values["sigma2"])


def check_friction(verdict: Verdict, mu: FloatArray) -> None:
    """mu finite and > 0."""
    verdict.require("mu_finite", finite(mu), mu)
    verdict.require("mu_positive", mu > 0, mu)


def check_partial_slip(verdict: Verdict, mu: FloatArray, values: Mapping[str, FloatArray]) -> None:
    """No gross sliding at either state: |Q_i| < mu P_i.

    The admissible states form the cone |Q| < mu P, which is convex, so a straight path
    between two admissible states stays admissible: checking the ends is enough.  Bulk tension
    adds no net shear force, so it does not enter this condition.  (mu P beyond the double
    range is simply very large: call inside ``numpy.errstate(over="ignore")``.)
    """
    for state in ("1", "2"):
        capacity = mu * values[f"P{state}"]
        shear = abs(values[f"Q{state}"])
        below = shear < capacity
        if not (below.all() if isinstance(below, np.ndarray) else below):
            below = below | _below_subnormal_capacity(shear, mu, values[f"P{state}"], capacity)
        verdict.require(
            f"sliding_{state}",
            below,
            None,
            **{f"abs_Q{state}": shear, f"mu_P{state}": capacity},
        )


_SMALLEST_NORMAL = float(np.finfo(np.float64).smallest_normal)


def _below_subnormal_capacity(
    shear: FloatArray, mu: FloatArray, P: FloatArray, capacity: FloatArray
) -> BoolArray:
    """|Q| < mu P where mu P falls below the normal doubles and is rounded (to 0 for a subnormal
    P1 times mu = 0.1, which made |Q1| = 0 "gross sliding").

    mu and P are scaled by powers of two into the normal range (exactly), their product
    compared with |Q| scaled by the same power (exact, or beyond the doubles and so not
    below): the comparison is as precise as for ordinary loads.
    """
    mu, P = np.asarray(mu, dtype=np.float64), np.asarray(P, dtype=np.float64)
    shear = np.asarray(shear, dtype=np.float64)
    with np.errstate(all="ignore"):
        tiny = (capacity < _SMALLEST_NORMAL) & (mu > 0) & (P > 0)
        _, mu_exponent = np.frexp(mu)
        _, P_exponent = np.frexp(P)
        mu_scale = np.where(tiny, np.maximum(0, -mu_exponent), 0)
        P_scale = np.where(tiny, np.maximum(0, -P_exponent), 0)
        scaled = np.ldexp(mu, mu_scale) * np.ldexp(P, P_scale)
        underflows: BoolArray = tiny & (np.ldexp(shear, mu_scale + P_scale) < scaled)
        return underflows


def denominator_checks(
    admits: Number,
    mu: Number,
    lam: Number,
    eta: Number,
    L_I1: Number,
    L_I2: Number,
) -> tuple[tuple[str, Number], tuple[str, Number]]:
    """The rules of (17)'s denominator, each with where it holds, in the order to require them.

    (17) has a steady partial-slip state only where its denominator is positive (``admits``).
    Where it is not, the message names the load change to blame: the bulk tension's where the
    same cycle without it (eta = 0; the shear term lambda (L_I2 - L_I1) of (21) alone) would
    have a positive denominator, else the shear force's.  Works on one cycle's floats (the
    conditions are then NumPy booleans: ``~True`` on a Python bool is -2) and on arrays.
    """
    with np.errstate(all="ignore"):
        without_tension = mu * (L_I1 + L_I2) - abs(lam) * abs(L_I2 - L_I1)
        tension = np.logical_and(eta != 0, without_tension > 0)
    return (
        ("denominator_tension", np.logical_or(admits, np.logical_not(tension))),
        ("denominator_shear", admits),
    )
