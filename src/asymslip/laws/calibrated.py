"""The contact law of a calibrated contact: each edge with its own a(P) and L_I(P) from data.

A calibration (:class:`asymslip.calibration.Calibration`) holds, per edge and per load, the
edge's distance a from a fixed origin and its multiplier L_I, each with an error.
:class:`CalibratedLaw` turns them into one law per edge (:meth:`CalibratedLaw.for_edge`),
which is what the paper's method needs at that edge:

* a(P): the table law's monotone cubic fit of log a against log P
  (:class:`~asymslip.laws.table.LogLogCurve`), through the calibrated points: increasing,
  exact for power laws, a2 - a1 without cancellation;
* L_I(P): the same fit of log L_I against log P without the monotone limiter (L_I may fall
  with P, e.g. for a wedge).  L_I comes from the pressure data, not from (19): (19) assumes a
  symmetric contact whose increments carry no moment about its centre;
* L_II of the full-stick increment from the edge's own slope a'(P) and the contact width w
  (``asymslip_gen.asymmetric_edges.shear_edge_multiplier_asymmetric``, derived in
  ``derivations/asymmetric_edge_multipliers.py``, AS3): (21), L_II = (lam + pi eta a/4) L_I,
  holds for a symmetric contact only.

Error
-----
:meth:`CalibratedLaw.error_of` gives the error of any result computed from the law (e.g. the
stick boundary b of each edge): the table law's leave-one-out refits (2 times the largest
change; they measure the fit between the loads), plus the calibrated points' own errors
propagated by refitting with each point moved by its error (root sum of squares of the
changes; a_error and L_I_error of each load, each edge, one at a time).

Runtime needs NumPy only.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from dataclasses import dataclass
from functools import cached_property
from typing import Protocol

import numpy as np
from numpy.typing import ArrayLike, NDArray

from asymslip_gen.asymmetric_edges import (
    edge_moment_factor,
    edge_multiplier_balance,
    shear_edge_multiplier_asymmetric,
)

from ..errors import InputError, as_float_array, positive
from .base import BoolArray, LawState, Side
from .roots import invert_increasing
from .table import ERROR_SAFETY_FACTOR, LogLogCurve

FloatArray = NDArray[np.float64]
SIDES: tuple[Side, Side] = ("right", "left")


class CalibrationData(Protocol):
    """What the law needs of a calibration (:class:`asymslip.calibration.Calibration`).

    The law does not import the calibration package, which sits above the laws (it reads
    files and fits traces); any object with these members will do.
    """

    @property
    def source(self) -> str: ...

    @property
    def origin(self) -> float: ...

    @property
    def sides(self) -> tuple[Side, ...]: ...

    def columns(self, side: Side) -> dict[str, FloatArray]: ...

    def bound_loads(self, side: Side) -> tuple[float, ...]: ...


#: The fewest loads an edge law can be fitted through (a power law through two points).
MIN_LOADS = 2
#: Leave-one-out refits need at least this many loads (a refit through the others).
MIN_LOADS_FOR_REFITS = 3


@dataclass(frozen=True)
class _Points:
    """One edge's calibrated points: loads, distances a, multipliers and their errors."""

    P: FloatArray
    a: FloatArray
    a_error: FloatArray
    L_I: FloatArray
    L_I_error: FloatArray

    def without(self, k: int) -> _Points:
        keep = np.arange(self.P.size) != k
        return _Points(*(values[keep] for values in self._values()))

    def moved(self, name: str, k: int, change: float) -> _Points:
        values = dict(zip(("P", "a", "a_error", "L_I", "L_I_error"), self._values(), strict=True))
        moved = values[name].copy()
        moved[k] += change
        values[name] = moved
        return _Points(**values)

    def _values(self) -> tuple[FloatArray, ...]:
        return self.P, self.a, self.a_error, self.L_I, self.L_I_error


class CalibratedEdge:
    """One edge of a calibrated contact: a(P), L_I(P), and L_II of the full-stick increment.

    Obtained from :meth:`CalibratedLaw.for_edge`.  Distances a (and the stick boundary b the
    paper's formulas give from them) are measured from the calibration's origin along this
    edge's outward direction.  Every method broadcasts over arrays of loads.

    Not a :class:`~asymslip.laws.base.ContactLaw` on purpose: that class's defaults compute
    L_I from a(P) by (19), which does not hold at an edge of an asymmetric contact; every
    quantity here is this edge's own, and a caller that needs something else fails loudly.
    """

    name = "calibrated"
    #: Jaeger-Ciavarella's b_exact = a(P_K) does not exist for a calibrated edge: the exact
    #: stick zone of an asymmetric contact is the contact at P_K and the *mean rotation* of the
    #: two states, off the load path the data follow (derivations/asymmetric_edge_multipliers.py,
    #: AS7).  It is a(P_K) only when the moment factor is 1 all along the path.
    exact_stick_boundary_exists = False
    #: The array core reads b_exact = a(P_K) only from symmetric laws; a calibrated edge is not.
    symmetric = False
    #: Every load > 0 has an a(P) (beyond the calibrated loads, extrapolated and flagged).
    range_note = ""

    def __init__(
        self, law: CalibratedLaw, side: Side, points: _Points, *, cubic_ends: bool = False
    ) -> None:
        self.law = law
        self.side = side
        self.points = points
        u = np.log(points.P)
        self._positions = LogLogCurve(u, np.log(points.a), cubic_ends=cubic_ends)
        self._multipliers = LogLogCurve(
            u, np.log(points.L_I), cubic_ends=cubic_ends, monotone=False
        )

    def __repr__(self) -> str:
        low, high = self.load_range
        return (
            f"CalibratedEdge({self.side}, {self.points.P.size} loads in [{low:g}, {high:g}] "
            f"from {self.law.source})"
        )

    # --- a(P) -------------------------------------------------------------------------------
    def half_width(self, P: ArrayLike) -> FloatArray:
        """The edge's distance a(P) from the origin, along its outward direction.

        Raises
        ------
        InputError
            For a load so far beyond the calibrated ones that the extrapolated a(P) is no
            float (overflows to inf or underflows to 0): named with the calibrated range.
        """
        return self._representable(P, "a(P)", self._positions.evaluate(_log(P), 0)[0])

    def half_width_slope(self, P: ArrayLike) -> FloatArray:
        """a'(P) = (a/P) d(log a)/d(log P), > 0."""
        P = positive("P", P)
        s, ds = self._positions.evaluate(np.log(P))
        return self._representable(P, "a(P)", s) * ds / P

    def _representable(self, P: ArrayLike, quantity: str, log_value: FloatArray) -> FloatArray:
        """exp(log_value), refusing the loads where it is inf or 0 (no number can be right).

        An end power law of the fit extrapolated over hundreds of decades of load overflows;
        the result would be inf (or 0) with a NumPy warning, never a value to use.
        """
        with np.errstate(over="ignore", under="ignore"):
            value = np.exp(log_value)
        bad = ~((value > 0) & np.isfinite(value))
        if np.any(bad):
            loads = np.broadcast_to(np.asarray(P, dtype=np.float64), value.shape)
            load = float(loads[np.unravel_index(int(np.argmax(bad)), bad.shape)])
            low, high = self.load_range
            raise InputError(
                "P",
                f"P = {load:.6g} lies so far outside the calibrated loads [{low:.6g}, "
                f"{high:.6g}] of the {self.side} edge that its extrapolated {quantity} is not "
                "a representable number: give loads near the calibrated ones",
            )
        return value

    def half_width_growth(self, P1: ArrayLike, dP: ArrayLike) -> FloatArray:
        """a(P1 + dP) - a(P1), free of cancellation however small dP/P1 is."""
        P1 = positive("P1", P1)
        u1 = np.log(P1)
        change = as_float_array("dP", dP)
        if not np.all(change >= 0):
            raise InputError("dP", "must be >= 0 (the growth from P1 to P1 + dP)")
        increment = self._positions.increment(u1, np.log1p(change / P1))
        a1 = self._representable(P1, "a(P)", self._positions.evaluate(u1, 0)[0])
        self.half_width(P1 + change)  # refuses a P2 whose a(P2) is no number
        return a1 * np.expm1(increment)

    def load(self, a: ArrayLike) -> FloatArray:
        """P(a), inverting the fitted a(P) (it is strictly increasing)."""
        return invert_increasing(self.half_width, np.asarray(a, dtype=np.float64))

    def load_slope(self, a: ArrayLike) -> FloatArray:
        """dP/da = 1/a'(P) at P = P(a)."""
        return 1.0 / self.half_width_slope(self.load(a))

    def half_width_where_possible(self, P: ArrayLike) -> tuple[FloatArray, BoolArray]:
        """a(P) and a mask of the loads it exists for (P finite and > 0; NaN elsewhere)."""
        P = np.asarray(P, dtype=np.float64)
        usable = np.isfinite(P) & (P > 0)
        a = self.half_width(np.where(usable, P, 1.0))
        return np.where(usable, a, np.nan)[()], usable[()]

    def cycle_state(self, P1: ArrayLike, dP: ArrayLike) -> LawState:
        """Every law quantity of the cycles P1 -> P1 + dP at this edge, from the fitted curves.

        L_I is the calibrated multiplier, not (19).  The array core takes a1, a2, a2 - a1,
        L_I, dP/da = 1/a'(P) and dL_I/dP from here.
        """
        P1, dP = np.broadcast_arrays(
            np.asarray(P1, dtype=np.float64), np.asarray(dP, dtype=np.float64)
        )
        P2 = P1 + dP
        found1 = np.isfinite(P1) & (P1 > 0)
        found2 = found1 & np.isfinite(P2) & (dP >= 0)
        safe1, safe2 = np.where(found1, P1, 1.0), np.where(found2, P2, 1.0)
        safe_dP = np.where(found2, dP, 0.0)
        a1 = self.half_width(safe1)
        da = self.half_width_growth(safe1, safe_dP)

        def mark(values: FloatArray, found: BoolArray) -> FloatArray:
            return np.where(found, values, np.nan)[()]

        return LawState(
            P1=P1[()],
            P2=P2[()],
            a1=mark(a1, found1),
            a2=mark(self.half_width(safe2), found2),  # the fit's own a(P2), as a1 is a(P1)
            da=mark(da, found2),
            L_I1=mark(self.normal_multiplier(safe1), found1),
            L_I2=mark(self.normal_multiplier(safe2), found2),
            load_slope1=mark(1.0 / self.half_width_slope(safe1), found1),
            load_slope2=mark(1.0 / self.half_width_slope(safe2), found2),
            L_I_slope1=mark(self.normal_multiplier_slope(safe1), found1),
            L_I_slope2=mark(self.normal_multiplier_slope(safe2), found2),
            found1=found1[()],
            found2=found2[()],
        )

    # --- the multipliers --------------------------------------------------------------------
    def normal_multiplier(self, P: ArrayLike) -> FloatArray:
        """L_I(P) of (4), fitted to the multipliers of the pressure data (refused, as
        :meth:`half_width`, where its extrapolation is no number)."""
        return self._representable(P, "L_I(P)", self._multipliers.evaluate(_log(P), 0)[0])

    def normal_multiplier_slope(self, P: ArrayLike) -> FloatArray:
        """dL_I/dP = (L_I/P) d(log L_I)/d(log P), for the validity measure (26)."""
        P = positive("P", P)
        s, ds = self._multipliers.evaluate(np.log(P))
        return self._representable(P, "L_I(P)", s) * ds / P

    def contact_width(self, P: ArrayLike) -> FloatArray:
        """w(P) = a_right(P) + a_left(P); twice this edge's a if it is the only edge given."""
        other = self.law.other_edge(self.side)
        own = self.half_width(P)
        return own + (other.half_width(P) if other is not None else own)

    def shear_multiplier(self, P: ArrayLike, lam: ArrayLike, eta: ArrayLike) -> FloatArray:
        """L_II of the full-stick increment at load P on the path (lam, eta) seen from this edge.

        ``lam`` and ``eta`` are the slopes as this edge sees them: for the left edge the
        mirror image, lam -> -lam, eta kept (and both negated for backward slip), exactly as the
        core passes them to (21).  Derived in ``derivations/asymmetric_edge_multipliers.py``
        (AS3): 2 (lam + pi eta w/8) / (pi sqrt(w) a'(P)).
        """
        P = np.asarray(P, dtype=np.float64)
        # The kernel gives a NumPy scalar for scalar input: an array either way.
        return np.asarray(
            shear_edge_multiplier_asymmetric(
                lam, eta, self.contact_width(P), self.half_width_slope(P)
            ),
            dtype=np.float64,
        )

    def moment_factor(self, P: ArrayLike) -> FloatArray:
        """f = (pi sqrt w/2) L_I a'(P) = 1 + (4/w) dM_c/dP (AS4).

        1 when the contact's rotation does not change along the path (then (21) holds and
        b_exact = a(P_K) would exist); L_II/L_I = (lam + pi eta w/8)/f.
        """
        P = np.asarray(P, dtype=np.float64)
        return np.asarray(
            edge_moment_factor(
                self.contact_width(P), self.normal_multiplier(P), self.half_width_slope(P)
            ),
            dtype=np.float64,
        )

    # --- range, warnings, error -------------------------------------------------------------
    @property
    def load_range(self) -> tuple[float, float]:
        """The smallest and largest calibrated load of this edge."""
        return float(self.points.P[0]), float(self.points.P[-1])

    def outside_range(self, P: ArrayLike) -> NDArray[np.bool_]:
        """True where P lies outside this edge's calibrated loads (or the other edge's)."""
        P = np.asarray(P, dtype=np.float64)
        low, high = self.law.common_range if self.law.other_edge(self.side) else self.load_range
        return (P < low) | (P > high)

    def extrapolated(self, P: ArrayLike) -> NDArray[np.bool_]:
        """Alias of :meth:`outside_range`, the name the array core uses."""
        return self.outside_range(P)

    def extrapolation_note(self, label: str) -> str:
        """The warning for a load state outside the calibrated loads."""
        low, high = self.law.common_range if self.law.other_edge(self.side) else self.load_range
        return (
            f"{label} is outside the calibrated loads [{low:.6g}, {high:.6g}] "
            f"({self.law.source}): the {self.side} edge's a(P) and L_I(P) there are the end "
            "power laws, extrapolated"
        )

    def load_warnings(self, P1: float, P2: float) -> list[str]:
        """Messages for load states outside the calibrated loads, and the standing caveats."""
        notes = [
            self.extrapolation_note(label)
            for label, P in (("P1", P1), ("P2", P2))
            if bool(self.outside_range(P))
        ]
        if self.law.other_edge(self.side) is None:
            notes.append(
                f"only the {self.side} edge was calibrated: the contact is taken as "
                "symmetric about the origin for the width in L_II"
            )
        if self.points.P.size < MIN_LOADS_FOR_REFITS:
            notes.append(
                f"the {self.side} edge has {self.points.P.size} calibrated loads: the "
                "error of its fit between them cannot be estimated (only the data's "
                "own errors are propagated)"
            )
        bounds = self.law.calibration.bound_loads(self.side)
        if bounds:
            notes.append(
                f"the calibrated {self.side} edge's errors at P = "
                f"{', '.join(f'{P:.6g}' for P in bounds)} are bounds, not estimates (the "
                "calibration's notes say why): errors propagated from them are bounds too"
            )
        return notes

    def error_of(self, quantity: Callable[[CalibratedEdge], ArrayLike]) -> FloatArray:
        """Estimated error of ``quantity(edge)`` (see :meth:`CalibratedLaw.error_of`)."""
        return self.law.error_of(lambda law: quantity(law.for_edge(self.side)))

    def resolution_note(self, P1: ArrayLike, P2: ArrayLike) -> str:
        """Where the edge's error at P1 or P2 exceeds its advance a(P2) - a(P1), say so.

        Then the sign of (17)'s denominator is not decided by the data: the refusal is the
        calibrated law's answer, and finer data near the edge may give a partial-slip state.
        ``P1``, ``P2``: the refused cycles; one text serves them all, so it is given only
        when every one of them is unresolved (it names the largest error).
        """
        P1, P2 = np.broadcast_arrays(np.asarray(P1, np.float64), np.asarray(P2, np.float64))
        error = self.error_estimate(np.concatenate([P1.ravel(), P2.ravel()]))["a"]
        error = np.maximum(error[: P1.size], error[P1.size :])
        advance = np.abs(self.half_width(P2.ravel()) - self.half_width(P1.ravel()))
        if not np.all(~(error <= advance)):
            return ""
        k = int(np.argmax(error))
        return (
            f"; but the calibrated {self.side} edge is known only to +-{error[k]:.3g} at these "
            f"loads, more than its advance a2 - a1 = {advance[k]:.3g}: the data cannot resolve "
            "this load step (finer pressure data near the edge, or loads further apart)"
        )

    def error_estimate(self, P: ArrayLike) -> dict[str, FloatArray]:
        """Estimated errors of a(P), a'(P) and L_I(P) at loads P (keys a, a_slope, L_I)."""
        P = np.asarray(P, dtype=np.float64)
        return {
            "a": self.error_of(lambda edge: edge.half_width(P)),
            "a_slope": self.error_of(lambda edge: edge.half_width_slope(P)),
            "L_I": self.error_of(lambda edge: edge.normal_multiplier(P)),
        }


class CalibratedLaw:
    """The law of a calibrated contact: one :class:`CalibratedEdge` per edge.

    Parameters
    ----------
    calibration
        From :func:`~asymslip.calibration.calibrate` or
        :meth:`~asymslip.calibration.Calibration.load` (whose
        :meth:`~asymslip.calibration.Calibration.law` builds this).  Each
        edge with data needs at least 2 loads, and must advance (a increasing) with the load.

    Examples
    --------
    >>> import numpy as np
    >>> from asymslip import HertzLaw
    >>> from asymslip.calibration import Traces, calibrate
    >>> hertz = HertzLaw(R=1.0, E_star=1.0)
    >>> loads = [90.0, 100.0, 110.0, 120.0]
    >>> x = np.linspace(-15.0, 15.0, 121)
    >>> traces = Traces.from_arrays(np.repeat(loads, x.size), np.tile(x, len(loads)),
    ...                             np.concatenate([hertz.pressure(x, P) for P in loads]))
    >>> law = CalibratedLaw(calibrate(traces, origin=0.0))
    >>> edge = law.for_edge("right")
    >>> abs(float(edge.half_width(100.0)) / float(hertz.half_width(100.0)) - 1) < 1e-3
    True
    """

    name = "calibrated"
    #: The two edges have their own laws (the array core evaluates each).
    symmetric = False

    def __init__(self, calibration: CalibrationData) -> None:
        self.calibration = calibration
        self.source = calibration.source
        self.origin = calibration.origin
        points = {side: _points_of(calibration, side) for side in calibration.sides}
        self._edges = self._build(points)

    def _build(
        self, points: dict[Side, _Points], *, cubic_ends: bool = False
    ) -> dict[Side, CalibratedEdge]:
        return {
            side: CalibratedEdge(self, side, values, cubic_ends=cubic_ends)
            for side, values in points.items()
        }

    def _variant(self, points: dict[Side, _Points], *, cubic_ends: bool) -> CalibratedLaw:
        variant = object.__new__(CalibratedLaw)
        variant.calibration = self.calibration
        variant.source = self.source
        variant.origin = self.origin
        variant._edges = variant._build(points, cubic_ends=cubic_ends)
        return variant

    def __repr__(self) -> str:
        return f"CalibratedLaw({', '.join(map(repr, self._edges.values()))})"

    # --- the edges ----------------------------------------------------------------------------
    def for_edge(self, side: Side) -> CalibratedEdge:
        """The law of one edge, ``"right"`` or ``"left"``."""
        if side not in SIDES:
            raise InputError("edge", "must be 'right' or 'left'", side)
        if side in self._edges:
            return self._edges[side]
        (only,) = self._edges
        # One edge calibrated: the contact is taken as symmetric about the origin.
        return self._edges[only]

    def other_edge(self, side: Side) -> CalibratedEdge | None:
        """The edge opposite ``side``, or None when only one edge was calibrated."""
        other: Side = "left" if side == "right" else "right"
        return self._edges.get(other) if len(self._edges) == 2 else None

    @property
    def common_range(self) -> tuple[float, float]:
        """The loads where every calibrated edge has data."""
        lows, highs = zip(*(edge.load_range for edge in self._edges.values()), strict=True)
        return max(lows), min(highs)

    def multiplier_balance(self, P: ArrayLike) -> FloatArray:
        """(pi sqrt w/4)(L_I,r a_r' + L_I,l a_l'), which is exactly 1 for consistent data (AS6).

        A check of the data that needs no knowledge of the moment: a value off 1 by more than
        the error (``error_of(lambda law: law.multiplier_balance(P))``) means the two edges'
        a(P) and L_I(P) are not those of one contact.  Needs both edges.
        """
        if len(self._edges) != 2:
            raise InputError("calibration", "the multiplier balance needs both edges")
        right, left = self._edges["right"], self._edges["left"]
        P = np.asarray(P, dtype=np.float64)
        return np.asarray(
            edge_multiplier_balance(
                right.contact_width(P),
                right.normal_multiplier(P),
                right.half_width_slope(P),
                left.normal_multiplier(P),
                left.half_width_slope(P),
            ),
            dtype=np.float64,
        )

    # --- error --------------------------------------------------------------------------------
    @cached_property
    def _refits(self) -> tuple[CalibratedLaw, ...]:
        """Each edge refitted with each of its loads left out in turn (leave-one-out)."""
        points = {side: edge.points for side, edge in self._edges.items()}
        refits = []
        for side, values in points.items():
            if values.P.size < MIN_LOADS_FOR_REFITS:
                continue
            for k in range(values.P.size):
                refits.append(self._variant({**points, side: values.without(k)}, cubic_ends=True))
        return tuple(refits)

    @cached_property
    def _perturbed(self) -> tuple[_Ladder, ...]:
        """Each calibrated a and L_I moved by its error, one at a time.

        One entry per calibrated point: its variants (law, scale), largest move first.  The
        whole error comes first, then fractions of it (halving, both signs) with the change
        scaled back up (``scale``): a linear propagation of that point's error.  A fraction is
        skipped where the moved fit would stop the edge advancing; ``error_of`` also falls
        back to a smaller move where the quantity has no value for the larger one (e.g. the
        moved law admits no partial-slip state).
        """
        points = {side: edge.points for side, edge in self._edges.items()}
        ladders = []
        for side, values in points.items():
            for name, errors in (("a", values.a_error), ("L_I", values.L_I_error)):
                for k in range(values.P.size):
                    if errors[k] == 0:
                        continue
                    ladders.append(_Ladder(self, points, side, values, name, k, errors[k]))
        return tuple(ladders)

    def error_of(self, quantity: Callable[[CalibratedLaw], ArrayLike]) -> FloatArray:
        """Estimated error of any result computed from this law, e.g. each edge's stick boundary.

        ``ERROR_SAFETY_FACTOR`` (2) times the largest change of ``quantity(law)`` over the
        leave-one-out refits (the fit between the loads), plus the root sum of squares of its
        changes when each calibrated a and L_I is moved by its own error (the data).  A refit
        or a moved law for which ``quantity`` raises ``InputError`` (say the refit admits no
        partial-slip state for the cycle) makes the error infinite: the calibration cannot
        bound it, and says so -- unless a smaller move of the same point has an answer, in
        which case that move is propagated linearly.
        """
        reference = np.asarray(quantity(self), dtype=np.float64)
        fit = np.zeros_like(reference)
        for refit in self._refits:
            try:
                change = np.abs(np.asarray(quantity(refit), dtype=np.float64) - reference)
            except InputError:
                change = np.full_like(reference, np.inf)
            fit = np.maximum(fit, change)
        data = np.zeros_like(reference)
        for ladder in self._perturbed:
            change = np.zeros_like(reference)  # no move keeps the edge advancing: nothing
            for variant, scale in ladder:  # the largest move that answers
                try:
                    change = (np.asarray(quantity(variant), dtype=np.float64) - reference) * scale
                    break
                except InputError:
                    change = np.full_like(reference, np.inf)  # unbounded, unless a smaller one
            data = data + change**2
        return ERROR_SAFETY_FACTOR * fit + np.sqrt(data)


class _Ladder:
    """One calibrated point's moves that keep the edge advancing, largest first.

    Iterating gives (law, 1/|fraction|); each variant law is fitted only when first reached
    and then kept, so the usual case (the whole error answers) fits one law per point.
    """

    FRACTIONS = (1.0, -1.0, 0.5, -0.5, 0.25, -0.25, 0.125, -0.125)

    def __init__(
        self,
        law: CalibratedLaw,
        points: dict[Side, _Points],
        side: Side,
        values: _Points,
        name: str,
        k: int,
        error: float,
    ) -> None:
        self._make = (law, points, side, values, name, k, error)
        self._built: dict[float, CalibratedLaw | None] = {}

    def _variant(self, fraction: float) -> CalibratedLaw | None:
        if fraction not in self._built:
            law, points, side, values, name, k, error = self._make
            moved = values.moved(name, k, fraction * error)
            advancing = (
                bool(np.all(np.diff(moved.a) > 0) and np.all(moved.a > 0))
                if name == "a"
                else bool(moved.L_I[k] > 0)
            )
            self._built[fraction] = (
                law._variant({**points, side: moved}, cubic_ends=False) if advancing else None
            )
        return self._built[fraction]

    def __iter__(self) -> Iterator[tuple[CalibratedLaw, float]]:
        for fraction in self.FRACTIONS:
            variant = self._variant(fraction)
            if variant is not None:
                yield variant, 1.0 / abs(fraction)


def _log(P: ArrayLike) -> FloatArray:
    """log P, refusing loads that are not finite and > 0 (one InputError, no NumPy warning)."""
    return np.log(positive("P", P))


def _points_of(calibration: CalibrationData, side: Side) -> _Points:
    """One edge's points, checked: enough loads, an advancing edge, positive distances."""
    columns = calibration.columns(side)
    P, a = columns["P"], columns["a"]
    if P.size < MIN_LOADS:
        raise InputError(
            "calibration",
            f"{calibration.source}: the {side} edge has {P.size} "
            f"load(s); its law a(P) needs at least {MIN_LOADS}",
        )
    if not np.all(a > 0):
        k = int(np.flatnonzero(~(a > 0))[0])
        raise InputError(
            "calibration",
            f"{calibration.source}: the {side} edge at P = "
            f"{P[k]:.6g} is not beyond the origin x = {calibration.origin:.6g}",
        )
    step = np.diff(a)
    if not np.all(step > 0):
        k = int(np.flatnonzero(~(step > 0))[0])
        errors = columns["a_error"]
        resolved = -step[k] > errors[k] + errors[k + 1]
        why = (
            (
                "it recedes: a receding edge is outside the model (the state-2 contact must "
                "contain the state-1 contact near the edge)"
            )
            if resolved
            else (
                "the change is within the fits' errors: the loads are too close together for "
                "the mesh near this edge"
            )
        )
        raise InputError(
            "calibration",
            f"{calibration.source}: the {side} edge does not advance between P = {P[k]:.6g} "
            f"(a = {a[k]:.6g} +- {errors[k]:.2g}) and P = {P[k + 1]:.6g} (a = {a[k + 1]:.6g} +- "
            f"{errors[k + 1]:.2g}); {why}",
        )
    return _Points(P, a, columns["a_error"], columns["L_I"], columns["L_I_error"])
