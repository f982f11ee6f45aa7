"""The few operations in which one cycle on Python floats and many cycles on arrays differ.

The edge pipeline (:mod:`asymslip.core.edge_state`) is written once over an
:class:`Operations`: which kernels answer (``asymslip_gen.scalar``, plain ``math``, for one cycle;
the NumPy ``asymslip_gen`` for arrays), how a branch is taken (``if`` or ``numpy.where``), and
what a broken rule does.  On arrays every element is checked and marked in a
:class:`~asymslip.rules.Verdict` and the evaluation goes on (a sweep keeps its other rows); on
one cycle the first broken rule ends the evaluation (:class:`RuleBroken`), since nothing after it
can be reported, and the evaluation names it from the same fields.

Examples
--------
>>> import numpy as np
>>> from asymslip.rules import Verdict
>>> FLOATS.where(2.0 > 1.0, 3.0, 4.0), ArrayOperations(Verdict((2,))).where(
...     np.array([True, False]), 3.0, 4.0).tolist()
(3.0, [3.0, 4.0])
"""

from __future__ import annotations

import math
from types import ModuleType
from typing import Any, Protocol, TypeAlias

import numpy as np
from numpy.typing import NDArray

import asymslip_gen
from asymslip_gen import programs as array_programs
from asymslip_gen import scalar as scalar_kernels
from asymslip_gen import scalar_programs

from ..laws.base import Number
from ..rules import Verdict

#: A condition: a bool for one cycle, a boolean array for many (unchecked, like a Number).
Condition: TypeAlias = Any
#: Warning flags: an int for one cycle, an integer array for many.
Flags: TypeAlias = Any
#: What a rule's message names: numbers (per element) or text.
Field = Number | str


class RuleBroken(Exception):
    """One cycle broke a rule: its key, the value to show and the fields its text names."""

    def __init__(self, key: str, shown: Number | None, fields: dict[str, Field]) -> None:
        super().__init__(key)
        self.key = key
        self.shown = shown
        self.fields = fields

    def verdict(self) -> Verdict:
        """The verdict of the one cycle, as the array path would have marked it."""
        verdict = Verdict(())
        verdict.require(self.key, False, self.shown, **self.fields)
        return verdict


class Operations(Protocol):
    """What the edge pipeline asks of its numbers."""

    #: The generated kernels: ``asymslip_gen`` (arrays) or ``asymslip_gen.scalar`` (floats).
    kernels: ModuleType
    #: The generated programs (several kernels in one call): ``asymslip_gen.programs`` or
    #: ``asymslip_gen.scalar_programs``.
    programs: ModuleType
    #: True for one cycle on Python floats.
    scalar: bool

    def where(self, condition: Condition, yes: Number, no: Number) -> Number: ...

    def keep_flags(self, condition: Condition, yes: Flags, no: Flags) -> Flags: ...

    def maximum(self, first: Number, second: Number) -> Number: ...

    def everywhere(self, condition: Condition) -> bool: ...

    def somewhere(self, condition: Condition) -> bool: ...

    def missing(self, like: Number) -> Number: ...

    def require(
        self, key: str, ok: Condition, shown: Number | None = None, **fields: Field
    ) -> None: ...

    def refused(self, admits: Condition, *loads: Number) -> tuple[NDArray[np.float64], ...]: ...


class FloatOperations:
    """One cycle on Python floats: ``if`` for ``numpy.where``, the ``math`` kernels, and the
    first broken rule raised as :class:`RuleBroken`."""

    kernels: ModuleType = scalar_kernels
    programs: ModuleType = scalar_programs
    scalar: bool = True

    def where(self, condition: Condition, yes: Number, no: Number) -> Number:
        return yes if condition else no

    def keep_flags(self, condition: Condition, yes: Flags, no: Flags) -> Flags:
        return yes if condition else no

    def maximum(self, first: Number, second: Number) -> Number:
        return first if first >= second else second

    # A condition on one cycle is a bool already: the builtin answers (no Python call).
    everywhere = staticmethod(bool)
    somewhere = staticmethod(bool)

    def missing(self, like: Number) -> Number:
        return math.nan

    def require(
        self, key: str, ok: Condition, shown: Number | None = None, **fields: Field
    ) -> None:
        if not ok:
            raise RuleBroken(key, shown, fields)

    def refused(self, admits: Condition, *loads: Number) -> tuple[NDArray[np.float64], ...]:
        return tuple(np.array([load], dtype=np.float64) for load in loads)


class ArrayOperations:
    """Many cycles (or one on NumPy scalars): ``numpy.where``, the NumPy kernels, and every
    element's first broken rule marked in ``verdict``."""

    kernels: ModuleType = asymslip_gen
    programs: ModuleType = array_programs
    scalar: bool = False

    def __init__(self, verdict: Verdict) -> None:
        self.verdict = verdict

    def where(self, condition: Condition, yes: Number, no: Number) -> Number:
        if isinstance(condition, (bool, np.bool_)):  # a condition the same for every element
            return yes if condition else no
        return np.where(condition, yes, no)

    def keep_flags(self, condition: Condition, yes: Flags, no: Flags) -> Flags:
        return np.where(condition, yes, no)

    def maximum(self, first: Number, second: Number) -> Number:
        return np.maximum(first, second)

    def everywhere(self, condition: Condition) -> bool:
        return bool(np.all(condition))

    def somewhere(self, condition: Condition) -> bool:
        return bool(np.any(condition))

    def missing(self, like: Number) -> Number:
        return np.full(np.shape(like), np.nan) if np.ndim(like) else math.nan

    def require(
        self, key: str, ok: Condition, shown: Number | None = None, **fields: Field
    ) -> None:
        self.verdict.require(key, ok, shown, **fields)

    def refused(self, admits: Condition, *loads: Number) -> tuple[NDArray[np.float64], ...]:
        refused = ~np.broadcast_to(np.asarray(admits), self.verdict.shape)
        return tuple(np.broadcast_to(load, refused.shape)[refused] for load in loads)


#: The one instance one-cycle evaluations share (it holds no state).
FLOATS = FloatOperations()
