"""Typed records of stress fields at points: one state, and a cycle's states and amplitude.

Conventions: :mod:`asymslip.stress`.

Examples
--------
>>> import numpy as np
>>> one = StressField(np.array([0.0]), np.array([1.0]), np.array([-2.0]), np.array([-1.0]),
...                   np.array([0.5]))
>>> (one.with_bulk(3.0) - one).sxx, one.out_of_plane(0.3)
(array([3.]), array([-0.9]))
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

FloatArray = NDArray[np.float64]
COMPONENTS = ("sxx", "syy", "sxy")


@dataclass(frozen=True)
class StressField:
    """In-plane stresses at points (x, depth), tension positive, flat arrays of one length."""

    x: FloatArray
    depth: FloatArray
    sxx: FloatArray
    syy: FloatArray
    sxy: FloatArray

    def __sub__(self, other: StressField) -> StressField:
        return StressField(
            self.x, self.depth, self.sxx - other.sxx, self.syy - other.syy, self.sxy - other.sxy
        )

    def with_bulk(self, sigma: float) -> StressField:
        """The field with a bulk tension sigma added to sxx (the lower body's)."""
        return StressField(self.x, self.depth, self.sxx + sigma, self.syy, self.sxy)

    def component(self, name: str) -> FloatArray:
        value: FloatArray = getattr(self, name)
        return value

    def out_of_plane(self, nu: float) -> FloatArray:
        """szz = nu (sxx + syy): plane strain."""
        result: FloatArray = nu * (self.sxx + self.syy)
        return result

    def to_points(self) -> list[dict[str, float]]:
        """One dictionary of sxx, syy, sxy per point."""
        return [
            {"sxx": float(a), "syy": float(b), "sxy": float(c)}
            for a, b, c in zip(self.sxx.tolist(), self.syy.tolist(), self.sxy.tolist(), strict=True)
        ]


@dataclass(frozen=True)
class CycleStress:
    """The stress at points over a steady cycle.

    ``states`` holds the field at each point of the load path (the paper's cycle: state 1,
    state 2), ``labels`` their names; ``amplitude`` is state 2 minus state 1 (the change over
    the loading half of the cycle, twice the fatigue amplitude) where the source gives it.
    ``accuracy`` (asymptotic source) is the stated bound on |error| of every component of the
    amplitude at each point, ``near_edge`` whether the point is close enough to the edge for
    the asymptote (no warning), ``warnings`` the cycle's and the points' doubts in words.
    """

    source: str
    edge: str | None
    x: FloatArray
    depth: FloatArray
    states: tuple[StressField, ...]
    labels: tuple[str, ...]
    amplitude: StressField | None
    accuracy: FloatArray | None = None
    near_edge: NDArray[np.bool_] | None = None
    warnings: tuple[str, ...] = field(default_factory=tuple)

    @property
    def count(self) -> int:
        return int(self.x.size)

    def to_dict(self) -> dict[str, object]:
        """JSON-ready: ``points``, each with x, depth, amplitude and the states it has."""
        points: list[dict[str, object]] = []
        amplitude = None if self.amplitude is None else self.amplitude.to_points()
        states = [state.to_points() for state in self.states]
        for index, (x, depth) in enumerate(zip(self.x.tolist(), self.depth.tolist(), strict=True)):
            point: dict[str, object] = {"x": x, "depth": depth}
            if amplitude is not None:
                point["amplitude"] = amplitude[index]
            for label, values in zip(self.labels, states, strict=True):
                point[f"state{label}"] = values[index]
            if self.accuracy is not None:
                point["accuracy"] = float(self.accuracy[index])
            if self.near_edge is not None:
                point["near_edge"] = bool(self.near_edge[index])
            points.append(point)
        return {
            "source": self.source,
            "edge": self.edge,
            "points": points,
            "warnings": list(self.warnings),
        }
