"""Contact nodes' positions along the surface, from their coordinates.

The traces' x is the position along the contact surface.  For nodes given by coordinates (an
FE result), the surface's direction is the principal direction of the nodes (the line that
fits them best); x is each node's projection on it, oriented so that x grows with the first
coordinate (with the second where the line is vertical).  When the nodes stray from that line
by more than :data:`CURVED` of their span, the surface is curved and x is the arc length along
the nodes, in the order of their projections, from the node nearest the line's foot of the
origin.  The normal is the in-plane perpendicular (the direction of the normal load).

Runtime needs NumPy only.

Examples
--------
>>> import numpy as np
>>> along = surface_positions(np.array([[0.0, 2.0], [1.0, 2.0], [-1.0, 2.0]]))
>>> along.x.tolist(), along.normal.tolist(), along.curved
([0.0, 1.0, -1.0], [0.0, 1.0], False)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..errors import InputError

FloatArray = NDArray[np.float64]
#: Largest distance of a node from the fitted line, over the nodes' span, for a flat surface.
CURVED = 1e-6


@dataclass(frozen=True)
class Positions:
    """x along the surface of each node (input order), the unit tangent and normal."""

    x: FloatArray
    tangent: FloatArray
    normal: FloatArray
    curved: bool


def surface_positions(coordinates: FloatArray) -> Positions:
    """Positions along the surface of nodes with in-plane coordinates (n, 2) or (n, 3)."""
    points = np.asarray(coordinates, dtype=np.float64)
    if points.shape[1] == 3:
        if np.ptp(points[:, 2]) > 0:
            raise InputError(
                "traces",
                "the contact nodes do not lie in one plane z = constant: a 2-D (plane or "
                "axisymmetric) model's contact surface is needed",
            )
        points = points[:, :2]
    if points.shape[0] < 2:
        raise InputError("traces", "fewer than two contact nodes")
    centre = points.mean(axis=0)
    _, _, vt = np.linalg.svd(points - centre)
    tangent = vt[0]
    if tangent[0] < 0 or (tangent[0] == 0 and tangent[1] < 0):
        tangent = -tangent
    normal = np.array([-tangent[1], tangent[0]]) + 0.0  # + 0.0: no negative zero
    along = points @ tangent
    across = (points - centre) @ normal
    span = float(np.ptp(along))
    if span == 0:
        raise InputError("traces", "every contact node is at the same place")
    curved = bool(np.max(np.abs(across)) > CURVED * span)
    if not curved:
        return Positions(along, tangent, normal, False)
    order = np.argsort(along)
    steps = np.hypot(*np.diff(points[order], axis=0).T)
    arc = np.concatenate([[0.0], np.cumsum(steps)])
    # Arc length measured from the node nearest the projection of the origin.
    start = int(np.argmin(np.abs(along[order])))
    x = np.empty_like(arc)
    x[order] = arc - arc[start] + along[order][start]
    return Positions(x, tangent, normal, True)
