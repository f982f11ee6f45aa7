"""Load paths: the paper's proportional cycle, or any closed polygon of (P, Q, sigma, M) points.

A path is one period: its points are visited in order, the last joined back to the first, and
the period is repeated until the steady state.  Between points the loads vary linearly (each
segment is split into the same number of load steps).

Initial loading (before the first period): the normal load and moment are applied first, with
Q = sigma = 0, up to the first point's P and M -- in elastically similar bodies this produces
no shear traction at all, so it needs no steps -- and then Q and sigma rise linearly, at that
P and M, to the first point's values (one segment of steps).  For the paper's cycle the first
point is state 1.

Units: P, Q per unit length [force/length], sigma [force/length^2], M per unit length [force];
M is the moment of the pressure about the profile's origin, M = int x p(x) dx.

Examples
--------
>>> from asymslip import LoadCycle
>>> from asymslip.solver.path import LoadPath
>>> LoadPath.from_cycle(LoadCycle(100, 0, 105, 1)).points.tolist()  # (P, Q, sigma, M) per point
[[100.0, 0.0, 0.0, 0.0], [105.0, 1.0, 0.0, 0.0]]
>>> path = LoadPath([[100, -5], [120, 0], [100, 5]])  # a triangle in (P, Q); sigma = M = 0
>>> path.labels, path.points[:, 3].tolist()
(('1', '2', '3'), [0.0, 0.0, 0.0])
"""

from __future__ import annotations

import csv
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import ArrayLike

from ..cycle import LoadCycle
from ..errors import InputError, as_float_array
from .toeplitz import FloatArray

COLUMNS = ("P", "Q", "sigma", "M")


@dataclass(frozen=True)
class LoadPath:
    """One period of a closed, piecewise-linear load path.

    Parameters
    ----------
    points
        Array (n, 4) of rows (P, Q, sigma, M), n >= 2; P > 0.  Rows of 2 or 3 columns are
        padded with sigma = 0 and M = 0.
    labels
        Names of the points used in results (default "1", "2", ...).
    """

    points: FloatArray
    labels: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        points = as_float_array("path", self.points)
        if points.ndim != 2 or not 2 <= points.shape[1] <= 4:
            raise InputError("path", "must be rows of (P, Q[, sigma[, M]])", points.shape)
        if points.shape[1] < 4:
            points = np.hstack([points, np.zeros((points.shape[0], 4 - points.shape[1]))])
        if points.shape[0] < 2:
            raise InputError(
                "path", "needs at least 2 points: a load cycle goes somewhere", points.shape[0]
            )
        if np.array_equal(points[0], points[-1]) and points.shape[0] > 2:
            points = points[:-1]  # a closing point repeating the first
        bad = np.flatnonzero(~(points[:, 0] > 0))
        if bad.size:
            raise InputError(
                "path",
                f"P must be > 0 at every point (point {self._name(bad[0])})",
                float(points[bad[0], 0]),
            )
        if np.all(points == points[0]):
            raise InputError("path", "all points are the same: nothing varies along the path")
        object.__setattr__(self, "points", points)
        labels = tuple(self.labels) or tuple(str(i + 1) for i in range(points.shape[0]))
        if len(labels) != points.shape[0]:
            raise InputError("labels", "must name every point", len(labels))
        object.__setattr__(self, "labels", labels)

    def _name(self, index: int) -> str:
        return str(index + 1)

    @classmethod
    def from_cycle(cls, cycle: LoadCycle) -> LoadPath:
        """The paper's cycle: state 1, state 2, back to state 1 (M = 0)."""
        if np.ndim(cycle.P1) or np.ndim(cycle.P2):
            raise InputError("cycle", "the solver takes one cycle, not arrays of cycles")
        points = [[cycle.P1, cycle.Q1, cycle.sigma1, 0.0], [cycle.P2, cycle.Q2, cycle.sigma2, 0.0]]
        return cls(np.asarray(points, dtype=np.float64), ("1", "2"))

    @classmethod
    def from_csv(cls, path: str | Path) -> LoadPath:
        """Read points from a CSV file with the header ``P,Q,sigma,M`` (sigma and M optional)."""
        try:
            with open(path, newline="", encoding="utf-8") as handle:
                reader = csv.DictReader(handle)
                header = reader.fieldnames or []
                rows = list(reader)
        except OSError as error:
            raise InputError("path", f"cannot read {path}: {error.strerror}") from None
        names = [name.strip() for name in header]
        if "P" not in names or "Q" not in names:
            raise InputError(
                "path",
                f"{path} must have a header with columns P and Q (and optionally sigma and M)",
                ",".join(names),
            )
        unknown = [name for name in names if name not in COLUMNS]
        if unknown:
            raise InputError(
                "path",
                f"{path}: unknown column(s) {', '.join(unknown)}; the columns are P, Q, sigma, M",
            )
        points = []
        for line, row in enumerate(rows, start=2):
            row = {
                key.strip(): (value or "").strip() for key, value in row.items() if key is not None
            }
            values = []
            for column in COLUMNS:
                text = row.get(column, "")
                if not text and column in ("sigma", "M"):
                    values.append(0.0)
                    continue
                try:
                    values.append(float(text))
                except ValueError:
                    raise InputError(
                        "path", f"{path} line {line}: {column} must be a number", text
                    ) from None
            points.append(values)
        if not points:
            raise InputError("path", f"{path} has no points")
        return cls(np.asarray(points, dtype=np.float64))

    @property
    def count(self) -> int:
        return int(self.points.shape[0])

    def check_partial_slip(self, mu: float) -> None:
        """Refuse a path that reaches gross sliding, |Q| >= mu P, at some point.

        Along a segment P and Q vary linearly, so |Q| - mu P is largest at a point.
        """
        P, Q = self.points[:, 0], self.points[:, 1]
        bad = np.flatnonzero(np.abs(Q) >= mu * P)
        if bad.size:
            i = int(bad[0])
            raise InputError(
                "path",
                f"point {self.labels[i]} (P = {P[i]:.6g}, Q = {Q[i]:.6g}) has |Q| >= mu P = "
                f"{mu * P[i]:.6g}: the contact slides as a whole there, and the model has no "
                "partial-slip steady state",
            )

    def segment_loads(self, steps: int) -> list[FloatArray]:
        """Loads at the end of each step of one period, segment by segment (steps, 4) each.

        Step j of a segment from A to B is ((steps - j)/steps) A + (j/steps) B: the same two
        products, summed, as step steps - j of a segment from B to A, so a segment run back
        along another gives loads equal to the last bit (the normal solutions are reused).
        """
        done = np.arange(1, steps + 1)
        to_end = (done / steps)[:, None]
        from_start = ((steps - done) / steps)[:, None]
        segments = []
        for i in range(self.count):
            start, end = self.points[i], self.points[(i + 1) % self.count]
            loads = from_start * start + to_end * end
            loads[-1] = end  # exactly the vertex
            segments.append(loads)
        return segments

    def initial_loads(self, steps: int) -> FloatArray:
        """The initial loading: (P0, 0, 0, M0), then Q and sigma up to the first point."""
        first = self.points[0]
        start = np.array([first[0], 0.0, 0.0, first[3]])
        if first[1] == 0 and first[2] == 0:
            return start[None, :]
        fractions = np.arange(0, steps + 1) / steps
        loads: FloatArray = start + fractions[:, None] * (first - start)
        loads[-1] = first
        return loads


def as_path(loading: LoadCycle | LoadPath | ArrayLike) -> LoadPath:
    """A :class:`LoadPath` from a cycle, a path or an array of points."""
    if isinstance(loading, LoadPath):
        return loading
    if isinstance(loading, LoadCycle):
        return LoadPath.from_cycle(loading)
    return LoadPath(np.asarray(loading, dtype=np.float64))
