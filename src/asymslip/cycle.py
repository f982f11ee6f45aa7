"""The steady-state load cycle of the paper's Fig. 3: a straight line between states 1 and 2."""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .errors import InputError, as_numbers
from .laws.base import Number
from .rules import Verdict, check_changes, check_cycle_inputs

FloatArray = NDArray[np.float64]
FIELDS = ("P1", "Q1", "P2", "Q2", "sigma1", "sigma2")


@dataclass(frozen=True)
class _Loads:
    """A cycle's six loads as float arrays, their broadcast shape, and one cycle's floats."""

    P1: FloatArray
    Q1: FloatArray
    P2: FloatArray
    Q2: FloatArray
    sigma1: FloatArray
    sigma2: FloatArray
    #: True when the cycle's constructor checked its rules (so every element passed them).
    checked: bool
    shape: tuple[int, ...]
    numbers: tuple[float, ...] | None


def _loads(loads: tuple[ArrayLike, ...], checked: bool) -> _Loads:
    arrays = [as_numbers(name, value) for name, value in zip(FIELDS, loads, strict=True)]
    shape = _broadcast_shape(arrays)
    numbers = tuple(float(value) for value in arrays) if shape == () else None
    P1, Q1, P2, Q2, sigma1, sigma2 = arrays
    return _Loads(P1, Q1, P2, Q2, sigma1, sigma2, checked, shape, numbers)


class LoadCycle:
    """Load states (P1, Q1, sigma1) and (P2, Q2, sigma2) joined by a straight line (2)-(3).

    Loads are per unit length of the contact (plane strain); any consistent units.  Attributes
    may be arrays (broadcast together) to describe many cycles at once.  A cycle is immutable:
    its loads are read-only attributes.

    Parameters
    ----------
    P1, P2
        Normal loads at the two ends, 0 < P1 < P2.  The paper takes state 2 as the one with
        the larger normal load; a cycle given the other way round must be entered with its
        states swapped (the steady state does not depend on the direction of travel).
    Q1, Q2
        Shear forces at the two ends.
    sigma1, sigma2
        Differential bulk tensions at the two ends (default 0) [force/length^2].

    Raises
    ------
    InputError
        Naming the first element that breaks a rule of :mod:`asymslip.rules` (non-finite,
        P1 <= 0, P2 <= P1, a change that overflows), a value that is not a number (None is
        missing), or two loads whose shapes do not broadcast.

    Examples
    --------
    >>> cycle = LoadCycle(P1=100, Q1=0, P2=105, Q2=1)
    >>> float(cycle.lam), float(cycle.eta)
    (0.2, 0.0)
    """

    __slots__ = ("_loads",)
    _loads: _Loads

    def __init__(
        self,
        P1: ArrayLike,
        Q1: ArrayLike,
        P2: ArrayLike,
        Q2: ArrayLike,
        sigma1: ArrayLike = 0.0,
        sigma2: ArrayLike = 0.0,
    ) -> None:
        self._loads = _loads((P1, Q1, P2, Q2, sigma1, sigma2), checked=False)
        self.verdict().raise_first()
        self._loads = replace(self._loads, checked=True)

    @classmethod
    def unchecked(
        cls,
        P1: ArrayLike,
        Q1: ArrayLike,
        P2: ArrayLike,
        Q2: ArrayLike,
        sigma1: ArrayLike = 0.0,
        sigma2: ArrayLike = 0.0,
    ) -> LoadCycle:
        """A cycle whose invalid elements are kept, to be marked per element by the core.

        For many cycles at once (the sweep), where one bad row must not stop the others; see
        :meth:`verdict`.
        """
        cycle = cls.__new__(cls)
        cycle._loads = _loads((P1, Q1, P2, Q2, sigma1, sigma2), checked=False)
        return cycle

    def __repr__(self) -> str:
        loads = ", ".join(f"{name}={getattr(self._loads, name)!r}" for name in FIELDS)
        return f"LoadCycle({loads})"

    @property
    def P1(self) -> FloatArray:
        """Normal load at state 1."""
        return self._loads.P1

    @property
    def Q1(self) -> FloatArray:
        """Shear force at state 1."""
        return self._loads.Q1

    @property
    def P2(self) -> FloatArray:
        """Normal load at state 2 (> P1)."""
        return self._loads.P2

    @property
    def Q2(self) -> FloatArray:
        """Shear force at state 2."""
        return self._loads.Q2

    @property
    def sigma1(self) -> FloatArray:
        """Differential bulk tension at state 1."""
        return self._loads.sigma1

    @property
    def sigma2(self) -> FloatArray:
        """Differential bulk tension at state 2."""
        return self._loads.sigma2

    @property
    def checked(self) -> bool:
        """True when the constructor checked the cycle's rules (and so every element passed)."""
        return self._loads.checked

    @property
    def shape(self) -> tuple[int, ...]:
        """The broadcast shape of the six loads (() for one cycle)."""
        return self._loads.shape

    @property
    def numbers(self) -> tuple[float, ...] | None:
        """One cycle's six loads as Python floats, in the order of :data:`FIELDS` (None for
        many)."""
        return self._loads.numbers

    def values(self) -> dict[str, Number]:
        """The six loads, broadcast to :attr:`shape` (Python floats for a single cycle)."""
        if self.shape == ():
            return {name: float(getattr(self, name)) for name in FIELDS}
        return {name: np.broadcast_to(getattr(self, name), self.shape) for name in FIELDS}

    def verdict(self, shape: tuple[int, ...] | None = None) -> Verdict:
        """Each element checked against the cycle's rules (finite, ordered, no overflow)."""
        shape = self.shape if shape is None else shape
        verdict = Verdict(shape)
        if shape == ():
            values = self.values()  # Python floats: each check costs next to nothing
        else:
            values = {name: np.broadcast_to(getattr(self, name), shape) for name in FIELDS}
        with np.errstate(all="ignore"):  # overflow and bad elements are what is checked here
            check_cycle_inputs(verdict, values)
            dQ, dsigma = values["Q2"] - values["Q1"], values["sigma2"] - values["sigma1"]
            dP = values["P2"] - values["P1"]
            if shape == () and dP == 0:  # a float division by zero raises; P_order reports it
                dP = np.float64(0.0)
            check_changes(verdict, dQ, dsigma, dQ / dP, dsigma / dP, values)
        return verdict

    @property
    def dP(self) -> FloatArray:
        """Normal-load change P2 - P1 > 0 (3)."""
        return self.P2 - self.P1

    @property
    def dQ(self) -> FloatArray:
        """Shear-force change Q2 - Q1 (3)."""
        return self.Q2 - self.Q1

    @property
    def dsigma(self) -> FloatArray:
        """Bulk-tension change sigma2 - sigma1 (3)."""
        return self.sigma2 - self.sigma1

    @property
    def lam(self) -> FloatArray:
        """lambda = dQ/dP (18)."""
        return self.dQ / self.dP

    @property
    def eta(self) -> FloatArray:
        """eta = dsigma/dP (18)."""
        return self.dsigma / self.dP


def _broadcast_shape(arrays: list[FloatArray]) -> tuple[int, ...]:
    """The shape the six loads broadcast to, or an error naming two that do not."""
    shapes = [value.shape for value in arrays]
    if not any(shapes):
        return ()
    shape: tuple[int, ...] = ()
    for index, (name, value) in enumerate(zip(FIELDS, shapes, strict=True)):
        try:
            shape = np.broadcast_shapes(shape, value)
        except ValueError:
            other = (
                next(FIELDS[j] for j in range(index) if not _broadcastable(shapes[j], value))
                if any(not _broadcastable(shapes[j], value) for j in range(index))
                else "the others"
            )
            raise InputError(
                name,
                f"has shape {value}, which does not broadcast with {other}'s shape "
                f"{shapes[FIELDS.index(other)] if other in FIELDS else shape}",
            ) from None
    return shape


def _broadcastable(first: tuple[int, ...], second: tuple[int, ...]) -> bool:
    try:
        np.broadcast_shapes(first, second)
    except ValueError:
        return False
    return True
