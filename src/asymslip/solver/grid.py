"""The uniform grid of the interface and the influence operators built on it."""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from asymslip_gen.solver_influence import gap_opening_influence, relative_slip_influence

from .toeplitz import FloatArray, ToeplitzOperator


@dataclass(frozen=True)
class Grid:
    """N elements of equal width h covering [start, start + N h]; collocation at the centres.

    Parameters
    ----------
    start
        Left end of the computational domain [length].
    width
        Element width h > 0 [length].
    count
        Number of elements N.
    """

    start: float
    width: float
    count: int

    @classmethod
    def spanning(cls, left: float, right: float, count: int) -> Grid:
        return cls(float(left), float(right - left) / count, int(count))

    @property
    def length(self) -> float:
        return self.width * self.count

    @property
    def end(self) -> float:
        return self.start + self.length

    @cached_property
    def centres(self) -> FloatArray:
        return self.start + (np.arange(self.count, dtype=np.float64) + 0.5) * self.width

    def boundary(self, index: int, side: int) -> float:
        """Position of the end of element ``index`` on ``side`` (+1 right, -1 left)."""
        return self.start + (index + (1 if side > 0 else 0)) * self.width


class InfluenceOperators:
    """The two Toeplitz matrices of the grid, from the generated kernels.

    ``gap`` is W(i - j), the opening of the gap per unit pressure (positive definite);
    ``slip`` is S(i - j), the relative tangential displacement u_x2 - u_x1 per unit shear
    traction on body 1, the indenter (so minus the slip delta: conventions); S = -W, and the
    tangential problem minimises with -S.  The
    reference length of the logarithm is the grid's length, which keeps both definite.
    """

    def __init__(self, grid: Grid, E_star: float) -> None:
        self.grid = grid
        self.E_star = E_star
        h, ell = grid.width, grid.length
        # The kernels are typed to return a scalar for scalar input; k is an array here.
        self.gap = ToeplitzOperator(
            lambda k: np.asarray(gap_opening_influence(k, h, ell, E_star), dtype=np.float64),
            grid.count,
        )

        # The tangential problem's Hessian is -S, positive definite.  For similar bodies the
        # derivation finds S = -W, which the generated kernels give bit for bit (a sign is
        # exact): then one operator serves both problems -- one kernel column, one spectrum,
        # one set of preconditioner spectra and FFT buffers in memory.
        def stiffness(k: FloatArray) -> FloatArray:
            return -np.asarray(relative_slip_influence(k, h, ell, E_star), dtype=np.float64)

        if np.array_equal(
            stiffness(np.arange(self.gap.column.size, dtype=np.float64)), self.gap.column
        ):
            self.slip_stiffness = self.gap
        else:
            self.slip_stiffness = ToeplitzOperator(stiffness, grid.count)

    def relative_slip(self, shear: FloatArray) -> FloatArray:
        """S q: the relative tangential displacement of the shear tractions q."""
        return -self.slip_stiffness.apply(shear)
