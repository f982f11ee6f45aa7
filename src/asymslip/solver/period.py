"""What the solver keeps of the steps it has run: the last period, compactly.

A period of the path is ``segments x steps`` load steps.  The results (:mod:`.steady`) need,
of each step of the steady period: its normal state (shared with the cache of normal
solutions, :class:`NormalCache`), its shear tractions (the stick boundaries' friction reserves
and the states at the path's points), and its slip -- which is non-zero only in the slip zones
and on the elements entering or leaving the contact, a small part of the contact, so it is kept
sparse (:class:`SlipRecord`).  :class:`PeriodWindow` holds one record per step of the period,
each replaced by the same step of the next period: memory is one period of shear tractions,
O(N x steps), and nothing else grows with the number of periods.

The window is read in the period's order, from point 1, whatever step was run last: once the
state at some point of the path repeats after a period, the period that ends there is the
steady one, and it is the same period read from point 1 (:func:`asymslip.solver.run.solve`).

Examples
--------
>>> import numpy as np
>>> from asymslip.solver.period import SlipRecord
>>> record = SlipRecord(np.array([3, 7]), np.array([1, -1], dtype=np.int8),
...                     np.array([2e-3, -1e-9]), np.array([4e-5, 0.0]))
>>> record.sign_at(7), record.sign_at(5), record.signs(9).tolist()
(-1, 0, [0, 0, 0, 1, 0, 0, 0, -1, 0])
>>> record.significant(1e-6).index.tolist()  # the tiny slip of element 7 is dropped
[3]
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .normal import NormalSolver, NormalState, predict_contact
from .tangential import TangentialState
from .toeplitz import FloatArray

Int8Array = NDArray[np.int8]


@dataclass(frozen=True)
class SlipRecord:
    """One step's slip on the elements that moved: index, sign, increment and energy.

    ``sign`` is the slip state at the step's end (+1/-1 slipping, 0 not: an element that
    left the contact while slipping moved without slipping at the end); ``increment`` the
    relative slip over the step; ``energy`` the frictional energy of the step per unit area.
    """

    index: NDArray[np.intp]
    sign: Int8Array
    increment: FloatArray
    energy: FloatArray

    @classmethod
    def of(cls, state: TangentialState, energy: FloatArray) -> SlipRecord:
        """The non-zero slip of a step's state (and its energy, zero wherever there is none)."""
        index = np.flatnonzero((state.slip_sign != 0) | (state.slip_increment != 0))
        return cls(index, state.slip_sign[index], state.slip_increment[index], energy[index])

    def largest(self) -> float:
        """The largest |increment| of the step (0 if nothing moved)."""
        return float(np.max(np.abs(self.increment), initial=0.0))

    def significant(self, threshold: float) -> SlipRecord:
        """Only the elements whose |increment| exceeds ``threshold``."""
        keep = np.abs(self.increment) > threshold
        return SlipRecord(
            self.index[keep], self.sign[keep], self.increment[keep], self.energy[keep]
        )

    def signs(self, count: int) -> Int8Array:
        """The slip signs on all ``count`` elements (0 where nothing is recorded)."""
        signs = np.zeros(count, dtype=np.int8)
        signs[self.index] = self.sign
        return signs

    def sign_at(self, element: int) -> int:
        """The slip sign of one element (0 when not recorded)."""
        position = int(np.searchsorted(self.index, element))
        if position < self.index.size and self.index[position] == element:
            return int(self.sign[position])
        return 0


@dataclass(frozen=True)
class StepRecord:
    """One load step of the period: its normal state, shear tractions and slip."""

    normal: NormalState
    shear: FloatArray
    slip: SlipRecord


class PeriodWindow:
    """One record per step of a period, slot (segment, step), each kept until replaced."""

    def __init__(self, segments: int, steps: int) -> None:
        self.segments = segments
        self.steps = steps
        self._slots: list[StepRecord | None] = [None] * (segments * steps)

    def get(self, segment: int, step: int) -> StepRecord | None:
        return self._slots[segment * self.steps + step]

    def put(self, segment: int, step: int, record: StepRecord) -> StepRecord | None:
        """Store a step's record; returns the one it replaces (the previous period's)."""
        slot = segment * self.steps + step
        replaced, self._slots[slot] = self._slots[slot], record
        return replaced

    def records(self) -> list[StepRecord]:
        """The period's records from point 1 on (all slots must be filled)."""
        if any(record is None for record in self._slots):
            raise RuntimeError("the period window is read before a whole period was run")
        return [record for record in self._slots if record is not None]

    def largest_pressure(self) -> float:
        """The largest pressure of the period's steps."""
        return max(float(np.max(record.normal.pressure)) for record in self.records())


class NormalCache:
    """Normal solutions by load (P, M): the normal problem depends on nothing else.

    The paper's cycle visits each load twice per period (up, then down the same line), and
    every period the same loads: each is solved once.  A load is found by its exact bits,
    which the path's segments produce identically going up and coming down
    (:meth:`asymslip.solver.path.LoadPath.segment_loads`).  Each new load is warm-started from
    the contact of the last one solved, moved on as over the last two solutions
    (:func:`~asymslip.solver.normal.predict_contact`) when they were steps of the same segment
    (``steady_motion``).
    """

    def __init__(self, solver: NormalSolver) -> None:
        self.solver = solver
        self._states: dict[bytes, NormalState] = {}
        self._recent: list[NormalState] = []

    def __len__(self) -> int:
        return len(self._states)

    def solve(self, P: float, M: float, steady_motion: bool = False) -> NormalState:
        """The normal state at (P, M), solved if it is new."""
        load = np.array([P, M], dtype=np.float64)
        key = load.tobytes()
        state = self._states.get(key)
        if state is None:
            guess, pressure, extrapolated = None, None, False
            if steady_motion and len(self._recent) == 2:
                before, now = self._recent
                last = np.hypot(now.P - before.P, now.M - before.M)
                ahead = float(np.hypot(P - now.P, M - now.M) / last) if last else 0.0
                guess = predict_contact(before, now, ahead)
                pressure = now.pressure + ahead * (now.pressure - before.pressure)
                extrapolated = True
            elif self._recent:
                guess = self._recent[-1].contact
            state = self.solver.solve(P, M, guess, pressure, settle=not extrapolated)
            self._states[key] = state
            self._recent = [*self._recent[-1:], state]
        return state
