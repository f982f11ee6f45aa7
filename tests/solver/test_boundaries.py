"""Where a boundary lies inside its element: the square-root fit and what it refuses."""

from __future__ import annotations

import numpy as np

from asymslip.solver.boundaries import NOISE_FRACTION, locate
from asymslip.solver.grid import Grid

GRID = Grid.spanning(0.0, 1.0, 200)


def test_a_square_root_reserve_places_the_boundary_inside_its_element():
    # r = sqrt(b - x) inside, vanishing at b = 0.5013 (a quarter-element into element 100): the
    # line through r^2 is exact, so the fit finds b to rounding.
    b = 0.5 + 0.26 * GRID.width
    reserve = np.sqrt(np.maximum(b - GRID.centres, 0.0))
    found = locate(GRID, reserve, 99, +1)
    assert found.method == "fit"
    assert abs(found.x - b) < 1e-12


def test_a_reserve_at_rounding_level_is_not_fitted():
    # Elements held at the friction limit stick with a reserve of rounding size (here 1e-11 of
    # the largest, growing inwards like a square root): fitted, it would place the boundary
    # anywhere in the element; it stays at the grid end, with one element of error.
    b = 0.5 + 0.26 * GRID.width
    reserve = np.sqrt(np.maximum(b - GRID.centres, 0.0))
    held = GRID.centres > 0.45
    reserve[held] *= 1e-11 * reserve.max() / reserve[held].max()
    assert reserve[held].max() < NOISE_FRACTION * reserve.max()
    found = locate(GRID, reserve, 99, +1)
    assert found.method == "grid"
    assert found.x == GRID.boundary(99, 1) and found.error == GRID.width
