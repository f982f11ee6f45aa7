"""The structured, graded mesh of the plane-strain cylinder-on-block model.

Both bodies are meshed with four-node plane-strain quadrilaterals (CPE4) on one tensor grid of
columns x and rows of depth: uniform columns of width ``h`` over the fine zone |x| <= ``fine``
(the contact and its edges at every load of the cycle), growing geometrically by ``growth``
per element beyond it out to |x| = ``extent``; rows of height ``h`` at the surface growing by
``growth`` with depth down to ``depth``.  The block occupies -depth <= y <= 0; the cylinder's
columns stand on its circular profile y = R - sqrt(R^2 - x^2) and rise ``depth`` above it.
Both surfaces carry the same columns, so every node of the block's surface faces a node of
the cylinder's (the contact is node to surface all the same).

The model's frame: x along the surface from the contact centre, y upwards (the block is the
lower body, below y = 0); depth into the block is -y.

Runtime needs NumPy only.

Examples
--------
>>> grid = Grid.build(h=0.1, fine=1.0, extent=3.0, depth=3.0, growth=1.2)
>>> bool(grid.x[0] == -grid.x[-1]), round(float(grid.x[grid.x.size // 2]), 12)
(True, 0.05)
>>> float(grid.depths[1]), bool(grid.depths[-1] >= 3.0)
(0.1, True)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

FloatArray = NDArray[np.float64]
IntArray = NDArray[np.int64]


def graded_offsets(h: float, start: float, end: float, growth: float) -> list[float]:
    """Positions beyond ``start`` with spacing h * growth^k (k = 1, 2, ...), the last >= end."""
    positions: list[float] = []
    position, step = start, h
    while position < end - 1e-12 * end:
        step *= growth
        position += step
        positions.append(position)
    return positions


@dataclass(frozen=True)
class Grid:
    """Column positions x (symmetric about 0) and row depths (0 at the surface, increasing)."""

    x: FloatArray
    depths: FloatArray
    h: float

    @classmethod
    def build(cls, h: float, fine: float, extent: float, depth: float, growth: float) -> Grid:
        """The graded grid: uniform spacing ``h`` over |x| <= fine, growing beyond it."""
        # Nodes at odd multiples of h/2: none at the centre, and the Hertz edge a(P2) = n h
        # of the model falls between two nodes rather than on one.
        count = math.ceil(fine / h)
        uniform = (np.arange(-count, count) + 0.5) * h
        outer = graded_offsets(h, (count - 0.5) * h, extent, growth)
        x = np.concatenate([-np.array(outer[::-1]), uniform, np.array(outer)])
        depths = np.array([0.0, *graded_offsets(h / growth, 0.0, depth, growth)])
        return cls(x=x.astype(np.float64), depths=depths.astype(np.float64), h=float(h))


@dataclass(frozen=True)
class Body:
    """One body's nodes and elements.

    ``ids[row, column]`` is the node number at that depth row and column (row 0 is the
    contact surface); ``coordinates[k]`` the (x, y) of node ``node_numbers[k]``; ``elements``
    the CPE4 connectivity (counter-clockwise), one row per element, numbered from
    ``first_element``.
    """

    ids: IntArray
    coordinates: FloatArray
    elements: IntArray
    first_element: int

    @property
    def element_numbers(self) -> IntArray:
        return np.arange(self.elements.shape[0], dtype=np.int64) + self.first_element

    def element_number(self, row: int, column: int) -> int:
        """The element between depth rows row, row + 1 and columns column, column + 1."""
        columns = int(self.ids.shape[1]) - 1
        return int(self.first_element + row * columns + column)


def block(grid: Grid) -> Body:
    """The lower body: nodes 1, 2, ... row by row from the surface down."""
    rows, columns = grid.depths.size, grid.x.size
    ids = np.arange(1, rows * columns + 1, dtype=np.int64).reshape(rows, columns)
    X, D = np.meshgrid(grid.x, grid.depths)
    coordinates = np.column_stack([X.ravel(), -D.ravel()])
    # Counter-clockwise with y up: the deeper row (row + 1) first.
    elements = np.column_stack(
        [
            ids[1:, :-1].ravel(),
            ids[1:, 1:].ravel(),
            ids[:-1, 1:].ravel(),
            ids[:-1, :-1].ravel(),
        ]
    )
    return Body(ids, coordinates, elements, first_element=1)


def cylinder(grid: Grid, R: float, first_node: int, first_element: int) -> Body:
    """The upper body: columns standing on the circle of radius R touching y = 0 at x = 0."""
    rows, columns = grid.depths.size, grid.x.size
    ids = np.arange(first_node, first_node + rows * columns, dtype=np.int64).reshape(rows, columns)
    # R - sqrt(R^2 - x^2) written without cancellation: x^2 / (R + sqrt(R^2 - x^2)).
    profile = grid.x**2 / (R + np.sqrt(R * R - grid.x**2))
    X, D = np.meshgrid(grid.x, grid.depths)
    coordinates = np.column_stack([X.ravel(), (D + profile[None, :]).ravel()])
    elements = np.column_stack(
        [
            ids[:-1, :-1].ravel(),
            ids[:-1, 1:].ravel(),
            ids[1:, 1:].ravel(),
            ids[1:, :-1].ravel(),
        ]
    )
    return Body(ids, coordinates, elements, first_element=first_element)
