"""The contact-law interface: everything the paper's method needs from a contact.

Section 2 needs only the law a(P) and the edge multiplier L_I of (19).  A law supplies P(a)
and dP/da; the rest has defaults that a law overrides where it knows better (a closed-form
inverse, a cancellation-free growth a(P1 + dP) - a(P1), a pressure distribution).

A cycle asks its law once for everything it needs (:meth:`ContactLaw.cycle_state`): a1, a2,
a2 - a1, L_I and the slopes at both states, shared by both edges and every estimate.  The
default costs one root solve (a1), a few Newton steps from a tangent guess (a2) and one
cancellation-free correction of a2 - a1 (see :func:`~asymslip.laws.roots.growth_from`).

Examples
--------
A law needs only P(a) and dP/da; a(P), L_I of (19) and the rest follow.  The cylinder of (29)
with R = E* = 1, for which L_I = sqrt(a/2) by (31):

>>> import numpy as np
>>> from asymslip.laws.base import ContactLaw
>>> class Cylinder(ContactLaw):
...     name = "cylinder"
...     def load(self, a):
...         return np.pi * np.asarray(a) ** 2 / 4
...     def load_slope(self, a):
...         return np.pi * np.asarray(a) / 2
>>> law = Cylinder()
>>> a = law.half_width(100.0)
>>> round(float(a), 12), round(float(law.normal_multiplier(100.0) / np.sqrt(a / 2)), 12)
(11.283791670955, 1.0)
"""

from __future__ import annotations

import abc
from dataclasses import dataclass
from typing import Any, ClassVar, Literal, NamedTuple, Protocol, TypeAlias, runtime_checkable

import numpy as np
from numpy.typing import ArrayLike, NDArray

from asymslip_gen.edge_multipliers import normal_edge_multiplier

from ..edge import Edge
from ..errors import InputError
from .roots import (
    growth_from,
    invert_increasing_where_possible,
    load_difference,
    newton_from,
)

FloatArray = NDArray[np.float64]
BoolArray = NDArray[np.bool_]
Side = Literal["right", "left"]
#: A number of a cycle: a Python float for one cycle, a float64 array for many.  NumPy's type
#: stubs cannot type arithmetic that mixes the two (every ``float * ndarray`` is an overload
#: error), so numbers are not checked; the records, their fields and the laws' methods are.
Number: TypeAlias = Any


@dataclass(slots=True)
class LawState:
    """The contact-law quantities of a load cycle, computed once per cycle.

    All arrays broadcast to the cycles' shape.  ``found1``/``found2`` are False where the
    law has no half-width carrying P1/P2 (a user law whose loads are bounded); the other
    fields are NaN there.
    """

    P1: Number
    P2: Number
    a1: Number
    a2: Number
    da: Number
    L_I1: Number
    L_I2: Number
    load_slope1: Number
    load_slope2: Number
    L_I_slope1: Number
    L_I_slope2: Number
    found1: Number
    found2: Number

    def as_floats(self, number: type[float] = float) -> LawState:
        """One cycle's state with every number as ``number`` (Python floats by default) and
        the found flags as bools: a law computed on NumPy returns 0-d arrays."""
        return LawState(
            number(self.P1),
            number(self.P2),
            number(self.a1),
            number(self.a2),
            number(self.da),
            number(self.L_I1),
            number(self.L_I2),
            number(self.load_slope1),
            number(self.load_slope2),
            number(self.L_I_slope1),
            number(self.L_I_slope2),
            bool(self.found1),
            bool(self.found2),
        )

    @property
    def a_slope1(self) -> Number:
        """a'(P1) = 1/(dP/da)."""
        return 1.0 / self.load_slope1

    @property
    def a_slope2(self) -> Number:
        """a'(P2) = 1/(dP/da)."""
        return 1.0 / self.load_slope2


class ContactLaw(abc.ABC):
    """A symmetric incomplete contact: its law P(a) and what follows from it.

    Optional capabilities are declared here with their defaults, so that the core asks for
    them by name: :meth:`load_and_slope` (P and dP/da sharing their costly parts),
    :meth:`shear_multiplier` (an edge's own L_II, for an asymmetric contact; a subclass that
    defines it has :attr:`own_shear_multipliers` set) and :attr:`E_star` (the modulus, for
    the slip displacement).
    """

    #: Short name used by the command line (``--law NAME``) and in results.
    name: str = "contact law"

    #: The plane-strain modulus E* when the law knows it (None for a law known only as a(P),
    #: such as a table).
    E_star: float | None = None

    #: True when the law gives each edge's shear multiplier itself (:meth:`shear_multiplier`),
    #: instead of (21) from L_I.  Set for every subclass that defines it.
    own_shear_multipliers: ClassVar[bool] = False

    def __init_subclass__(cls, **kwargs: Any) -> None:
        super().__init_subclass__(**kwargs)
        cls.own_shear_multipliers = cls.shear_multiplier is not ContactLaw.shear_multiplier

    # --- what every law defines ------------------------------------------------------------
    @abc.abstractmethod
    def load(self, a: ArrayLike) -> FloatArray:
        """Normal load P(a) that gives contact half-width a."""

    @abc.abstractmethod
    def load_slope(self, a: ArrayLike) -> FloatArray:
        """dP/da of the law at half-width a; > 0 for an incomplete contact."""

    def load_and_slope(self, a: FloatArray) -> tuple[FloatArray, FloatArray]:
        """P(a) and dP/da together; laws whose two share costly parts override it."""
        return self.load(a), self.load_slope(a)

    def shear_multiplier(self, P: ArrayLike, lam: ArrayLike, eta: ArrayLike) -> FloatArray:
        """The edge's own shear multiplier L_II at load P on a path of slopes lam, eta (18).

        Only an edge that cannot use (21) defines it (an asymmetric contact's, AS3 of
        ``derivations/asymmetric_edge_multipliers.py``); see :attr:`own_shear_multipliers`.
        """
        raise NotImplementedError(f"the {self.name} law takes L_II from (21)")

    # --- in terms of the half-width (no root solve) -----------------------------------------
    def normal_multiplier_at(self, a: ArrayLike, load_slope: ArrayLike) -> Number:
        """L_I of (19) at half-width a, given dP/da there."""
        return normal_edge_multiplier(a, load_slope)

    def normal_multiplier_slope_at(self, a: ArrayLike, load_slope: ArrayLike) -> Number:
        """dL_I/dP at half-width a: (dL_I/da)/(dP/da), by central differences in a.

        Laws with a closed form override it; it only enters the validity measure (26).
        """
        a = np.asarray(a, dtype=np.float64)
        step = 1e-5 * a
        upper, lower = a + step, a - step
        change = self.normal_multiplier_at(
            upper, self.load_slope(upper)
        ) - self.normal_multiplier_at(lower, self.load_slope(lower))
        return change / (2 * step) / np.asarray(load_slope, dtype=np.float64)

    def load_difference(self, a: ArrayLike, d: ArrayLike) -> FloatArray:
        """P(a + d) - P(a) without cancellation (see :func:`~.roots.load_difference`)."""
        return load_difference(self.load_slope, self.load, a, d)

    # --- in terms of the load ---------------------------------------------------------------
    def half_width_where_possible(self, P: ArrayLike) -> tuple[FloatArray, BoolArray]:
        """a(P), and a mask of the loads the law can carry (NaN elsewhere)."""
        return invert_increasing_where_possible(
            self.load, np.asarray(P, dtype=np.float64), self.load_slope
        )

    def half_width(self, P: ArrayLike) -> FloatArray:
        """Contact half-width a(P), the inverse of :meth:`load`."""
        a, found = self.half_width_where_possible(P)
        if not np.all(found):
            loads = np.asarray(P, dtype=np.float64)
            shown = float(loads.ravel()[int(np.flatnonzero(~np.asarray(found).ravel())[0])])
            raise InputError(
                "P",
                f"no contact half-width of the {self.name} law carries this "
                "load: it is outside the law's range",
                shown,
            )
        return a

    def half_width_near(self, P: ArrayLike, P_ref: ArrayLike, a_ref: ArrayLike) -> FloatArray:
        """a(P) for loads near P_ref, where a(P_ref) = a_ref is known (e.g. a(P_K) from a1).

        Newton from the tangent at a_ref, with the bracketing inverse where it does not settle.
        """
        P = np.asarray(P, dtype=np.float64)
        a_ref = np.asarray(a_ref, dtype=np.float64)
        with np.errstate(all="ignore"):
            guess = a_ref + (P - P_ref) / self.load_slope(a_ref)
        a, converged = newton_from(self.load, self.load_slope, P, guess, both=self.load_and_slope)
        if not np.all(converged):
            a = np.array(a, dtype=float)
            retry = ~np.asarray(converged)
            a[retry] = self.half_width_where_possible(np.broadcast_to(P, a.shape)[retry])[0]
            a = a[()] if a.ndim == 0 else a
        return a

    def half_width_growth(self, P1: ArrayLike, dP: ArrayLike) -> Number:
        """a(P1 + dP) - a(P1), with full relative precision however small dP/P1 is."""
        return self.cycle_state(P1, dP).da

    def half_width_slope(self, P: ArrayLike) -> FloatArray:
        """a'(P) = 1 / (dP/da)."""
        return 1.0 / self.load_slope(self.half_width(P))

    def normal_multiplier(self, P: ArrayLike) -> Number:
        """Edge multiplier L_I of the contact pressure at load P, from (19)."""
        a = self.half_width(P)
        return self.normal_multiplier_at(a, self.load_slope(a))

    def normal_multiplier_slope(self, P: ArrayLike) -> Number:
        """dL_I/dP at load P."""
        a = self.half_width(P)
        return self.normal_multiplier_slope_at(a, self.load_slope(a))

    def cycle_state(self, P1: ArrayLike, dP: ArrayLike) -> LawState:
        """Every law quantity a cycle from P1 to P1 + dP needs, computed once.

        One root solve for a1; a2 - a1 by :func:`~.roots.growth_from` (Newton from a1 and one
        cancellation-free correction); multipliers and slopes from the half-widths.  Loads the
        law cannot carry are marked in ``found1``/``found2``, not raised.
        """
        P1 = np.asarray(P1, dtype=np.float64)
        dP = np.asarray(dP, dtype=np.float64)
        P1, dP = np.broadcast_arrays(P1, dP)
        P2 = P1 + dP
        a1, found1 = self.half_width_where_possible(P1)
        with np.errstate(all="ignore"):
            start = np.where(found1, a1, 1.0)
            da, found2 = growth_from(
                self.load,
                self.load_slope,
                self.load_difference,
                start,
                P2,
                dP,
                both=self.load_and_slope,
            )
            found2 = found2 & found1
            a2 = a1 + da
        return self._state_from_half_widths(P1, P2, a1, a2, da, found1, found2)

    def quantities_at(self, a: FloatArray) -> tuple[FloatArray, FloatArray, FloatArray]:
        """dP/da, L_I and dL_I/dP at half-widths a, for a cycle's two states.

        Laws whose three share costly parts (the rounded flat's corner angle) override it.
        """
        slope = self.load_slope(a)
        return (
            slope,
            self.normal_multiplier_at(a, slope),
            self.normal_multiplier_slope_at(a, slope),
        )

    def _state_from_half_widths(
        self,
        P1: FloatArray,
        P2: FloatArray,
        a1: FloatArray,
        a2: FloatArray,
        da: FloatArray,
        found1: BoolArray,
        found2: BoolArray,
    ) -> LawState:
        """The multipliers and slopes at known half-widths (NaN where a load has no a)."""
        with np.errstate(all="ignore"):  # unfound elements are NaN and marked, not warned
            (slope1, L_I1, L_I_slope1), (slope2, L_I2, L_I_slope2) = (
                self.quantities_at(np.where(found, a, self.stand_in_half_width))
                for a, found in ((a1, found1), (a2, found2))
            )

        def mark(values: ArrayLike, found: BoolArray) -> FloatArray:
            return np.where(found, values, np.nan)

        return LawState(
            P1=P1,
            P2=P2,
            a1=mark(a1, found1),
            a2=mark(a2, found2),
            da=mark(da, found2),
            L_I1=mark(L_I1, found1),
            L_I2=mark(L_I2, found2),
            load_slope1=mark(slope1, found1),
            load_slope2=mark(slope2, found2),
            L_I_slope1=mark(L_I_slope1, found1),
            L_I_slope2=mark(L_I_slope2, found2),
            found1=np.asarray(found1),
            found2=np.asarray(found2),
        )

    #: A half-width where the law is defined, evaluated in place of a load it cannot carry.
    stand_in_half_width: float = 1.0

    #: True when :meth:`cycle_state`, :meth:`half_width_near` and :meth:`extrapolated` of one
    #: cycle on Python floats compute on Python floats alone (the ``math`` kernels), so that
    #: they raise where NumPy would warn; a law on NumPy is called inside
    #: ``numpy.errstate(all="ignore")`` and its overflows are named by the rules.
    floats_only: bool = False

    # --- the rest ------------------------------------------------------------------------------
    #: Appended to the message for a load the law cannot carry (a user law's known range).
    range_note: str = ""

    def resolution_note(self, P1: ArrayLike, P2: ArrayLike) -> str:
        """Appended where (17) has no partial-slip state: why the law may not resolve the cycle.

        A closed-form law is exact, so nothing (the default); a law known from data says when
        its own error at the loads exceeds the edge's advance between them.
        """
        return ""

    def for_edge(self, side: Edge | Side) -> ContactLaw:
        """The law of one edge: a symmetric contact has the same law at both."""
        return self

    @property
    def symmetric(self) -> bool:
        """True when both edges share one law (so a cycle's law quantities are shared)."""
        return True

    def pressure(self, x: ArrayLike, P: ArrayLike) -> FloatArray:
        """Contact pressure p(x, P) over the whole contact (zero outside it)."""
        raise NotImplementedError(f"the {self.name} law has no pressure distribution")

    def extrapolated(self, P: ArrayLike) -> BoolArray | bool:
        """True where the law is extrapolated at load P (default: nowhere)."""
        return np.zeros(P.shape, dtype=bool) if isinstance(P, np.ndarray) and P.ndim else False

    def extrapolation_note(self, label: str) -> str:
        """The warning for a load outside the range where the law is known (``label``: P1/P2)."""
        return f"{label} lies outside the range where the {self.name} law is known"

    def load_warnings(self, P1: float, P2: float) -> list[str]:
        """Messages for the load states where the law is extrapolated."""
        return [
            self.extrapolation_note(label)
            for label, P in (("P1", P1), ("P2", P2))
            if bool(self.extrapolated(P))
        ]


@runtime_checkable
class EdgeLawLike(Protocol):
    """A law known per edge outside the :class:`ContactLaw` family (a calibrated contact's
    :class:`~asymslip.laws.calibrated.CalibratedLaw`): what the slip-zone core asks of it."""

    name: str

    @property
    def symmetric(self) -> bool: ...

    def for_edge(self, side: Side) -> Any: ...


@runtime_checkable
class _GivesShearMultiplier(Protocol):
    def shear_multiplier(self, P: ArrayLike, lam: ArrayLike, eta: ArrayLike) -> FloatArray: ...


def is_law(law: object) -> bool:
    """True for a contact law the core can evaluate: a :class:`ContactLaw`, or a law known per
    edge (:class:`EdgeLawLike`)."""
    kind = type(law)
    known = _LAWS.get(kind)
    if known is None:  # once per class, as above
        known = _LAWS[kind] = isinstance(law, ContactLaw) or isinstance(law, EdgeLawLike)
    return known


_LAWS: dict[type, bool] = {}


class LawTraits(NamedTuple):
    """What the slip-zone core asks of an edge's law class, decided once per class."""

    #: The law gives its edges' own L_II (:meth:`ContactLaw.shear_multiplier`).
    own_shear_multipliers: bool
    #: The law may be extrapolated at a load (:meth:`ContactLaw.extrapolated` overridden, or
    #: a law known per edge): False for a closed-form law, whose ``extrapolated`` is never
    #: asked.
    extrapolates: bool


def law_traits(law: object) -> LawTraits:
    """The :class:`LawTraits` of ``law``'s class (an ABC's and a protocol's isinstance cost
    microseconds, so each class is examined once)."""
    kind = type(law)
    traits = _TRAITS.get(kind)
    if traits is None:
        if issubclass(kind, ContactLaw):
            own = kind.own_shear_multipliers
            extrapolates = kind.extrapolated is not ContactLaw.extrapolated
        else:
            own = isinstance(law, _GivesShearMultiplier)
            extrapolates = True
        traits = _TRAITS[kind] = LawTraits(own, extrapolates)
    return traits


_TRAITS: dict[type, LawTraits] = {}


def gives_own_shear_multipliers(law: object) -> bool:
    """True when an edge's law gives its own L_II (:meth:`ContactLaw.shear_multiplier`)."""
    return law_traits(law).own_shear_multipliers


def modulus_of(law: object) -> float | None:
    """The law's own modulus E* (:attr:`ContactLaw.E_star`), None where it has none."""
    return law.E_star if isinstance(law, ContactLaw) else None


def computes_on_floats(law: object) -> bool:
    """True when a law computes one cycle on Python floats alone (``ContactLaw.floats_only``)."""
    kind = type(law)
    floats = _FLOATS_ONLY.get(kind)
    if floats is None:  # once per class, as above
        floats = _FLOATS_ONLY[kind] = issubclass(kind, ContactLaw) and kind.floats_only
    return floats


_FLOATS_ONLY: dict[type, bool] = {}
