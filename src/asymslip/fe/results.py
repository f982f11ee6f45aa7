"""The steady stick boundaries and contact edges of a CalculiX run of the cylinder-on-block model.

Read from the run's .frd (:func:`asymslip.calibration.frd.read_frd`): the contact block of the
last increment of each step, at the block's surface nodes (the slave nodes), in the model's x.

* **Contact edges** at each state: between the last node with a positive pressure and the first
  without (CalculiX's small tension at open nodes near the master shows as a slightly negative
  pressure there); reported as the midpoint, known to half a spacing.
* **Slip on loading** 1 -> 2 of the last cycle: the change of the relative tangential
  displacement (CSLIP1) at each node, less its elastic part (the stick penalty's compliance
  times the change of shear, CSHEAR1: that compliance is measured at the nodes of the inner
  half of the contact, which stick), is the node's slip.  A node slips when its slip exceeds
  ten times the largest that any node of that inner half shows (and a thousandth of the largest
  slip), so the threshold follows the run's own convergence.
* **The stick boundary** of each edge: the midpoint between the innermost slipping node of the
  slip zone next to the edge and its sticking neighbour, known to half a spacing; b is its
  distance from the contact centre (x = 0), as ``slip-zone`` reports both edges.  The same is
  read from the unloading 2 -> 1 that follows and the one before: a steady cycle gives the
  same node each time.

Runtime needs NumPy only.

Examples
--------
Five nodes, the outer two slipping between two states (their slip grows beyond the stick
penalty's elastic part, which is 1e-6 per unit of shear here):

>>> import numpy as np
>>> x = np.array([-0.2, -0.1, 0.0, 0.1, 0.2, 0.3, 0.4])
>>> shear = np.array([1.0, 1.0, 1.0, 1.0, 1.0, 2.0, 2.0])
>>> zero = np.zeros(7)
>>> start = SurfaceState(x, zero, zero, zero, zero)
>>> end = SurfaceState(x, zero, shear, 1e-6 * shear + [0, 0, 0, 0, 0, 1e-4, 3e-4], zero)
>>> b, half_spacing = _stick_boundary(start, end, a1=0.45, side="right")
>>> round(b, 12), round(half_spacing, 12)
(0.25, 0.05)
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from ..calibration.frd import FrdFile, ResultBlock, read_frd
from ..errors import InputError
from .deck import steps
from .model import CylinderOnBlock

FloatArray = NDArray[np.float64]
#: A node slips when its slip exceeds this many times the largest slip of the inner half.
SLIP_OVER_STICK = 10.0
#: ... and this fraction of the largest slip of the run.
SLIP_FRACTION = 1e-3


@dataclass(frozen=True)
class SurfaceState:
    """The slave nodes at the end of one step, sorted by x (expanded node pairs averaged)."""

    x: FloatArray
    pressure: FloatArray
    shear: FloatArray
    slip: FloatArray
    opening: FloatArray


@dataclass(frozen=True)
class FeEdge:
    """One edge of the FE model: stick boundary and contact edges, distances from x = 0."""

    side: str
    b: float
    b_unloading: float
    b_unloading_before: float
    a1: float
    a2: float
    resolution: float  # half the node spacing: the error of b, a1 and a2

    def to_dict(self) -> dict[str, object]:
        return {
            "b": self.b,
            "b_unloading": self.b_unloading,
            "b_unloading_before": self.b_unloading_before,
            "a1": self.a1,
            "a2": self.a2,
            "resolution": self.resolution,
        }


@dataclass(frozen=True)
class FeResult:
    """Both edges of a run, and the element size of its fine zone."""

    right: FeEdge
    left: FeEdge
    element_size: float
    source: str

    def to_dict(self) -> dict[str, object]:
        return {
            "source": self.source,
            "element_size": self.element_size,
            "right": self.right.to_dict(),
            "left": self.left.to_dict(),
        }


def surface_state(frd: FrdFile, block: ResultBlock) -> SurfaceState:
    """The contact block at the model's nodes (a planar model's expanded pairs averaged)."""
    nodes = frd.model_node(block.nodes)
    unique, inverse = np.unique(nodes, return_inverse=True)
    counts = np.bincount(inverse).astype(np.float64)

    def mean(component: str) -> FloatArray:
        return np.bincount(inverse, weights=block.column(component)) / counts

    x = frd.positions(unique)[:, 0]
    order = np.argsort(x)
    return SurfaceState(
        x=x[order],
        pressure=mean("CPRESS")[order],
        shear=mean("CSHEAR1")[order],
        slip=mean("CSLIP1")[order],
        opening=mean("COPEN")[order],
    )


def _last_contact_of_each_step(frd: FrdFile) -> dict[int, ResultBlock]:
    last: dict[int, ResultBlock] = {}
    for block in frd.named("CONTACT"):
        if block.step not in last or block.increment >= last[block.step].increment:
            last[block.step] = block
    return last


def _edge(x: FloatArray, inside: NDArray[np.bool_], side: str) -> tuple[float, float]:
    """(distance of the edge from 0, half spacing) between the last node in and the next."""
    order = np.arange(x.size) if side == "right" else np.arange(x.size)[::-1]
    sign = 1.0 if side == "right" else -1.0
    last = None
    for k in order:
        if sign * x[k] >= 0 and inside[k]:
            last = k
    if last is None:
        raise InputError("frd", f"no node of the {side} half is in contact")
    beyond = last + (1 if side == "right" else -1)
    if not 0 <= beyond < x.size:
        raise InputError("frd", f"the {side} edge reaches the last slave node with results")
    return float(sign * 0.5 * (x[last] + x[beyond])), float(0.5 * abs(x[beyond] - x[last]))


def _stick_boundary(
    start: SurfaceState, end: SurfaceState, a1: float, side: str
) -> tuple[float, float]:
    """b of one edge from the slip between two states (the same nodes, sorted by x)."""
    # Contact elements come and go with the clearance: compare the nodes both states list.
    x, first, second = np.intersect1d(start.x, end.x, return_indices=True)
    change = end.slip[second] - start.slip[first]
    shear = end.shear[second] - start.shear[first]
    inner = np.abs(x) <= 0.5 * a1
    compliance = float(np.sum(change[inner] * shear[inner]) / np.sum(shear[inner] ** 2))
    slip = np.abs(change - compliance * shear)
    threshold = max(
        SLIP_OVER_STICK * float(np.max(slip[inner])), SLIP_FRACTION * float(np.max(slip))
    )
    sign = 1.0 if side == "right" else -1.0
    distance = sign * x
    # From the state-1 edge inwards: the slip zone is the run of slipping nodes next to it.
    candidates = np.flatnonzero((distance >= 0) & (distance <= a1))
    candidates = candidates[np.argsort(-distance[candidates])]
    slipping = slip[candidates] > threshold
    if not slipping[0]:
        return a1, 0.0  # no slip zone inside a1
    first_stick = int(np.argmin(slipping)) if not slipping.all() else slipping.size
    if first_stick == slipping.size:
        raise InputError("frd", f"the whole {side} half slips: no stick zone")
    outer, inner_node = candidates[first_stick - 1], candidates[first_stick]
    return (
        float(0.5 * (distance[outer] + distance[inner_node])),
        float(0.5 * abs(distance[outer] - distance[inner_node])),
    )


def read_result(path: str | Path, model: CylinderOnBlock) -> FeResult:
    """The steady stick boundaries and contact edges of a finished run of ``model``."""
    frd = read_frd(path)
    blocks = _last_contact_of_each_step(frd)
    listed = steps(model)
    numbers = {
        kind: [n for n, step in enumerate(listed, 1) if step.kind == kind]
        for kind in ("state 1", "state 2")
    }
    missing = [n for n in numbers["state 1"] + numbers["state 2"] if n not in blocks]
    if missing:
        raise InputError(
            "frd", f"{path}: no contact results for step {missing[0]} (did the run finish?)"
        )
    states = {n: surface_state(frd, blocks[n]) for n in numbers["state 1"] + numbers["state 2"]}
    # The last loading (1 -> 2) and unloading (2 -> 1), and the unloading before them: the
    # first loading from the initial state 1 is not yet steady, every later half-cycle is.
    load_from, last_2, last_1 = (
        numbers["state 1"][-2],
        numbers["state 2"][-1],
        numbers["state 1"][-1],
    )
    before_2, before_1 = numbers["state 2"][-2], numbers["state 1"][-2]
    edges = {}
    for side in ("right", "left"):
        a1, half1 = _edge(states[last_1].x, states[last_1].pressure > 0, side)
        a2, half2 = _edge(states[last_2].x, states[last_2].pressure > 0, side)
        b, half = _stick_boundary(states[load_from], states[last_2], a1, side)
        b_unloading, _ = _stick_boundary(states[last_2], states[last_1], a1, side)
        b_before, _ = _stick_boundary(states[before_2], states[before_1], a1, side)
        edges[side] = FeEdge(
            side=side,
            b=b,
            b_unloading=b_unloading,
            b_unloading_before=b_before,
            a1=a1,
            a2=a2,
            resolution=max(half, half1, half2),
        )
    return FeResult(edges["right"], edges["left"], model.element_size, str(path))
