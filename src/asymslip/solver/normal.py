"""The normal contact problem on the grid: pressure, contact set, approach and tilt.

With the gap opening W p of the pressures (``InfluenceOperators.gap``) the gap at element i is
g_i = h(x_i) - delta - theta x_i + (W p)_i, with the rigid approach delta and the rigid tilt
theta of the indenter.  The discrete contact problem is

    p >= 0,  g >= 0,  p g = 0,  sum_i p_i h_el = P,  sum_i x_i p_i h_el = M,

the optimality conditions of minimising 1/2 p.W.p + h.p with the two equalities (multipliers
-delta/h_el and -theta/h_el).  Being uncoupled from the shear (similar bodies), it depends on
the current (P, M) only, so each load step's solution is reused in every period.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from .grid import Grid, InfluenceOperators
from .qp import BoolArray, BoxQP, Workspace, solve_box_qp
from .toeplitz import FloatArray, Runs


class ContactOutsideGrid(Exception):
    """The contact reached the end of the grid: the caller widens the domain."""


@dataclass(frozen=True)
class NormalState:
    """The solution of the normal problem at one load (P, M)."""

    P: float
    M: float
    pressure: FloatArray
    contact: BoolArray
    approach: float
    tilt: float
    iterations: int
    gap: FloatArray  # h - delta - theta x + W p: 0 in contact, > 0 outside

    @property
    def first(self) -> int:
        return int(np.argmax(self.contact))

    @property
    def last(self) -> int:
        return int(self.contact.size - 1 - np.argmax(self.contact[::-1]))


class NormalSolver:
    """Solves the normal problem on one grid for any (P, M)."""

    def __init__(self, grid: Grid, operators: InfluenceOperators, heights: FloatArray) -> None:
        self.grid = grid
        self.operators = operators
        self.heights = heights
        x = grid.centres
        self._rows = np.vstack([np.full(grid.count, grid.width), x * grid.width])
        self._lower = np.zeros(grid.count)
        self._upper = np.full(grid.count, np.inf)
        self._domain = np.ones(grid.count, dtype=bool)
        self._workspace = Workspace()

    def initial_contact(self) -> BoolArray:
        """A first guess: the grid without its ends (the domain is chosen to fit the contact)."""
        margin = max(1, int(0.04 * self.grid.count))
        guess = np.zeros(self.grid.count, dtype=bool)
        guess[margin:-margin] = True
        return guess

    def problem(self, P: float, M: float) -> BoxQP:
        """The programme whose minimiser is the pressure at load P and moment M."""
        return BoxQP(
            operator=self.operators.gap,
            domain=self._domain,
            lower=self._lower,
            upper=self._upper,
            linear=-self.heights,
            rows=self._rows,
            targets=np.array([P, M], dtype=np.float64),
        )

    def solve(
        self,
        P: float,
        M: float,
        start: BoolArray | None = None,
        guess: FloatArray | None = None,
        settle: bool = True,
    ) -> NormalState:
        """Pressure at load P and moment M, warm-started from a guess of the contact set.

        ``guess`` is a guess of the pressures; ``settle`` moves the guessed contact's ends
        first (:func:`~asymslip.solver.qp.settle_ends`: for a guess that is not already an
        extrapolation to this load).

        Raises
        ------
        ContactOutsideGrid
            When the contact reaches an end of the grid.
        InputError
            (``profile``) when the contact is not one interval.
        """
        if start is None:
            start = self.initial_contact()
        qp = self.problem(P, M)
        solution = solve_box_qp(
            qp,
            ~start,
            np.zeros(self.grid.count, dtype=bool),
            workspace=self._workspace,
            guess=guess,
            settle=settle,
        )
        contact = ~solution.at_lower
        pressure = np.where(contact, np.maximum(solution.y, 0.0), 0.0)
        if contact[0] or contact[-1]:
            raise ContactOutsideGrid
        runs = Runs.of(contact)
        if len(runs.starts) != 1:
            pieces = ", ".join(
                f"[{self.grid.boundary(a, -1):.6g}, {self.grid.boundary(b - 1, 1):.6g}]"
                for a, b in zip(runs.starts, runs.stops, strict=True)
            )
            raise InputError(
                "profile",
                f"gives a contact in {len(runs.starts)} pieces at P = {P:.6g}, M = {M:.6g} "
                f"({pieces}); the solver supports profiles whose contact is one interval "
                "(convex profiles, or any that touch in one piece)",
            )
        width = self.grid.width
        approach = -float(solution.multipliers[0]) * width
        tilt = -float(solution.multipliers[1]) * width
        gap = np.where(contact, 0.0, np.maximum(solution.gradient, 0.0))
        return NormalState(
            float(P), float(M), pressure, contact, approach, tilt, solution.iterations, gap
        )


def predict_contact(before: NormalState, now: NormalState, ahead: float) -> BoolArray:
    """Guess the contact at the next load from the last two, ``ahead`` times as far on.

    Near the ends of an incomplete contact the pressure vanishes like a square root of the
    distance from the edge (4) and the gap grows like its 3/2 power, so p^2 and g^(2/3) are
    close to linear in the edge's position, and so in the load over a short step:
    extrapolated, p^2 <= 0 marks the elements expected to leave the contact and g^(2/3) <= 0
    those expected to enter it.  The guess is the one interval that spans the result (the
    solver refuses a contact in pieces).  It only affects the work, never the solution.
    """
    squared_now, squared_before = now.pressure**2, before.pressure**2
    leaving = (
        now.contact & before.contact & (squared_now + ahead * (squared_now - squared_before) <= 0)
    )
    opening_now, opening_before = np.cbrt(now.gap) ** 2, np.cbrt(before.gap) ** 2
    outside = ~now.contact & ~before.contact
    entering = outside & (opening_now + ahead * (opening_now - opening_before) <= 0)
    guess = (now.contact & ~leaving) | entering
    inside = np.flatnonzero(guess)
    if not inside.size:
        return now.contact
    first, last = max(int(inside[0]), 1), min(int(inside[-1]), guess.size - 2)
    interval = np.zeros(guess.size, dtype=bool)
    interval[first : last + 1] = True
    return interval
