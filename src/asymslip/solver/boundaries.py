"""Where a boundary lies inside its element: contact edges and stick boundaries.

On the grid a boundary is first known as the end between the last element inside (in contact,
or stuck) and the first outside.  Every boundary the solver reports is one across which a
non-negative *reserve* r vanishes like a square root: the pressure p at a contact edge of an
incomplete contact (p ~ L_I sqrt(a - x), (4)), and the friction reserve mu p - |q| at a
stick/slip boundary (the traction reaches mu p as a square root: the slip zone's dislocation
density grows like sqrt(x - b), (15)).  So r^2 is close to linear in x next to the boundary,
and the boundary is placed where the straight line fitted (least squares) to r^2 at the
``FIT_POINTS`` elements inside it, excluding the last, reaches zero.  The last element is
left out because it straddles the boundary (its value is not on the square root).

The error bound is the larger of one element width and twice the spread of the same fit over
three other windows (the last element included; one point fewer; two more).  On Hertz
contacts the fitted boundary is within 0.03-0.08 elements of the exact one (measured, N =
500-8000), and the grid end within one element, so one element is a safe bound; the
refinement mode (``refine``) then measures the actual convergence.  If the fit is impossible
(too few elements inside, a reserve that does not shrink towards the boundary) or lands more
than one element from the grid end, the grid end is reported with an error of one element plus
the discrepancy.  So is it where the reserve at the fitted elements is below
``NOISE_FRACTION`` of its largest value: the active-set iteration decides at 1e-9 of the
tractions, so such a reserve is zero to the solver's accuracy -- e.g. elements held at the
friction limit by a locked-in traction, which stick without slipping -- and a line through
it would place the boundary by rounding (measured: a state's stick boundary moved by a whole
element between two runs whose tractions agreed to 1e-9).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .grid import Grid
from .toeplitz import FloatArray

#: Elements inside the boundary used by the primary fit.
FIT_POINTS = 4
#: A reserve below this fraction of its largest value is zero to the solver's accuracy.
NOISE_FRACTION = 1e-8


@dataclass(frozen=True)
class Boundary:
    """A boundary's position x (in the grid's frame), its error bound and how it was found."""

    x: float
    error: float
    grid_x: float  # the element end between the last element inside and the first outside
    method: str  # "fit" (sub-element, from the square-root reserve) or "grid"


def _fit_root(x: FloatArray, reserve: FloatArray) -> float | None:
    """Zero of the least-squares line through (x, reserve^2); None when meaningless."""
    if x.size < 2 or not np.all(reserve > 0):
        return None
    slope, intercept = np.polyfit(x, reserve**2, 1)
    if slope == 0 or not np.isfinite(slope):
        return None
    return float(-intercept / slope)


def locate(grid: Grid, reserve: FloatArray, last_inside: int, side: int) -> Boundary:
    """The boundary beyond element ``last_inside`` on ``side`` (+1: to its right, -1: left).

    Parameters
    ----------
    grid
        The grid.
    reserve
        The non-negative quantity that vanishes like a square root at the boundary (defined
        on the whole grid; only elements inside are used).
    last_inside
        Index of the last element inside the boundary.
    side
        +1 if the boundary is the right end of the inside region, -1 if its left end.
    """
    h = grid.width
    grid_x = grid.boundary(last_inside, side)
    x = grid.centres
    inward = -side
    floor = NOISE_FRACTION * float(np.max(np.abs(reserve), initial=0.0))

    def window(skip: int, count: int) -> float | None:
        indices = last_inside + inward * np.arange(skip, skip + count)
        if indices.min() < 0 or indices.max() >= grid.count:
            return None
        values = reserve[indices]
        if not np.all(values > floor):
            return None
        # The reserve must grow away from the boundary for the square-root picture to hold.
        if not np.all(np.diff(values) > 0):
            return None
        return _fit_root(x[indices], values)

    primary = window(1, FIT_POINTS)
    if primary is None or abs(primary - grid_x) > h:
        discrepancy = 0.0 if primary is None else abs(primary - grid_x)
        return Boundary(grid_x, h + discrepancy, grid_x, "grid")
    alternatives = [window(0, FIT_POINTS), window(1, FIT_POINTS - 1), window(1, FIT_POINTS + 2)]
    spread = max((abs(a - primary) for a in alternatives if a is not None), default=h)
    return Boundary(primary, max(h, 2 * spread), grid_x, "fit")
