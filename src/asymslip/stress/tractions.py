"""Surface loads: piecewise-linear pressure and shear traction between nodes.

A :class:`SurfaceLoad` is what the half-plane evaluator sums: a pressure p and a shear traction
q, exerted by the indenter on the lower body (conventions: :mod:`asymslip.stress`), linear
between strictly increasing nodes and zero at the first and the last node (a contact's
tractions vanish beyond it).

Examples
--------
>>> load = SurfaceLoad.from_nodes([-1.0, 0.0, 1.0], [0.0, 2.0, 0.0], [0.0, 0.5, 0.0])
>>> [jumps.tolist() for jumps in load.slope_jumps()]  # W'' = sum c_j delta(t - t_j)
[[2.0, -4.0, 2.0], [0.5, -1.0, 0.5]]
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from ..errors import InputError, as_float_array
from .field import FloatArray


@dataclass(frozen=True)
class SurfaceLoad:
    """p and q at strictly increasing nodes, linear in between, zero at both end nodes.

    Build with :meth:`from_nodes`, which checks this.
    """

    nodes: FloatArray
    pressure: FloatArray
    shear: FloatArray

    @classmethod
    def from_nodes(cls, nodes: ArrayLike, pressure: ArrayLike, shear: ArrayLike) -> SurfaceLoad:
        """Check and build: at least three nodes, increasing, finite, zero at both ends."""
        t = as_float_array("nodes", nodes).ravel()
        p = as_float_array("pressure", pressure).ravel()
        q = as_float_array("shear", shear).ravel()
        if t.size < 3:
            raise InputError("nodes", "need at least three nodes (a load between two zeros)")
        if p.shape != t.shape or q.shape != t.shape:
            raise InputError("pressure", "pressure, shear and nodes must have the same length")
        if not np.all(np.diff(t) > 0):
            raise InputError("nodes", "must be strictly increasing")
        for name, values in (("pressure", p), ("shear", q)):
            if values[0] != 0 or values[-1] != 0:
                raise InputError(
                    name,
                    "must be 0 at the first and the last node (the load vanishes beyond "
                    "them; add a node where it does)",
                )
        return cls(t, p, q)

    def slope_jumps(self) -> tuple[FloatArray, FloatArray]:
        """c_j of the pressure and of the shear: W'' = sum_j c_j delta(t - t_j) (HP-4)."""
        widths = np.diff(self.nodes)
        jumps = []
        for values in (self.pressure, self.shear):
            slopes = np.diff(values) / widths
            c = np.empty_like(self.nodes)
            c[0] = slopes[0]
            c[1:-1] = np.diff(slopes)
            c[-1] = -slopes[-1]
            jumps.append(c)
        return jumps[0], jumps[1]


def from_element_values(
    centres: FloatArray, width: float, pressure: FloatArray, shear: FloatArray
) -> SurfaceLoad:
    """A load through the element centres of a uniform grid, with zero nodes half an element
    beyond the first and last element carrying a load."""
    loaded = np.flatnonzero((pressure != 0) | (shear != 0))
    if loaded.size == 0:
        raise InputError("pressure", "the load is zero everywhere")
    first, last = int(loaded[0]), int(loaded[-1])
    t = np.concatenate(
        [[centres[first] - width / 2], centres[first : last + 1], [centres[last] + width / 2]]
    )
    p = np.concatenate([[0.0], pressure[first : last + 1], [0.0]])
    q = np.concatenate([[0.0], shear[first : last + 1], [0.0]])
    return SurfaceLoad.from_nodes(t, p, q)
