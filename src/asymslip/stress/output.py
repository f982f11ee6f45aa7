"""Write a stress field as a table fatigue libraries read, and draw it near an edge.

The table (CSV or Parquet, by the extension; :mod:`asymslip.files.writer`) has one row per
point and state, in the column names of pyLife's stress tensors (``S11, S22, S33, S12, S13,
S23``, the Voigt order its ``voigt`` accessor and FatPy's functions take) with 1 = x along
the surface, 2 = the depth, 3 = out of plane (plane strain: S33 = nu (S11 + S22), written when
nu is given, else empty; S13 = S23 = 0):

``point``, ``x``, ``depth``
    the point (its index in the request, from the contact centre, into the lower body);
``state``
    ``1``, ``2`` (the solver's states, by path point) or ``amplitude`` (state 2 minus state 1);
``accuracy``, ``near_edge``
    the asymptote's stated bound on every component's error and its flag (empty otherwise).

Conventions: :mod:`asymslip.stress`.

Examples
--------
>>> import pathlib, tempfile
>>> from asymslip import HertzLaw, LoadCycle
>>> from asymslip.stress.asymptote import edge_amplitude
>>> field = edge_amplitude(HertzLaw(1, 1), LoadCycle(100, 0, 105, 1), 0.1, [11.5], [0.0])
>>> with tempfile.TemporaryDirectory() as folder:
...     path = write_table(field, pathlib.Path(folder) / "field.csv", nu=0.3)
...     print(path.read_text().splitlines()[0])
point,x,depth,state,S11,S22,S33,S12,S13,S23,accuracy,near_edge
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from ..errors import InputError
from ..files import Categorical
from ..files.atomic import atomic_write
from ..files.writer import Kind, open_table
from .field import COMPONENTS, CycleStress, StressField

COLUMNS = ("point", "x", "depth", "state", "S11", "S22", "S33", "S12", "S13", "S23")
SCHEMA: list[tuple[str, Kind]] = [
    ("point", "float"),
    ("x", "float"),
    ("depth", "float"),
    ("state", "category"),
    ("S11", "float"),
    ("S22", "float"),
    ("S33", "float"),
    ("S12", "float"),
    ("S13", "float"),
    ("S23", "float"),
    ("accuracy", "float"),
    ("near_edge", "float"),
]


def _rows(field: CycleStress, nu: float | None) -> list[tuple[str, StressField]]:
    rows = [(label, state) for label, state in zip(field.labels, field.states, strict=True)]
    if field.amplitude is not None:
        rows.append(("amplitude", field.amplitude))
    return rows


def write_table(field: CycleStress, path: str | Path, *, nu: float | None = None) -> Path:
    """Write ``field`` to ``path`` (.csv or .parquet), one row per point and state."""
    rows = _rows(field, nu)
    labels = [label for label, _ in rows]
    count = field.count
    with open_table(path, SCHEMA) as table:
        for code, (label, values) in enumerate(rows):
            nan = np.full(count, np.nan)
            amplitude = label == "amplitude"
            table.write(
                {
                    "point": np.arange(count, dtype=float),
                    "x": field.x,
                    "depth": field.depth,
                    "state": Categorical(np.full(count, code, dtype=np.int32), labels),
                    "S11": values.sxx,
                    "S22": values.syy,
                    "S33": values.out_of_plane(nu) if nu is not None else nan,
                    "S12": values.sxy,
                    "S13": np.zeros(count),
                    "S23": np.zeros(count),
                    "accuracy": field.accuracy if amplitude and field.accuracy is not None else nan,
                    "near_edge": field.near_edge.astype(float)
                    if amplitude and field.near_edge is not None
                    else nan,
                }
            )
    return Path(path)


def _figure_class() -> Any:
    try:
        from matplotlib.figure import Figure
    except ImportError:
        raise InputError(
            "out",
            "drawing the field needs matplotlib: install the 'plot' extra, e.g. "
            "pip install 'asymslip[plot]' (or give --out FILE.csv for the table only)",
        ) from None
    return Figure


def draw(field: CycleStress, path: str | Path, *, title: str = "") -> Path:
    """Contours of the amplitude (or the last state) over the grid of the points.

    The points must be a grid of at least 2 x 2 (every x with every depth, as the command's
    ``--x`` and ``--depth`` make); depth increases downwards, as in the body.
    """
    shown = field.amplitude if field.amplitude is not None else field.states[-1]
    xs, depths = np.unique(field.x), np.unique(field.depth)
    if xs.size < 2 or depths.size < 2 or xs.size * depths.size != field.count:
        raise InputError(
            "out",
            "drawing needs a grid of at least two x and two depths (every --x with every "
            "--depth); write a table instead (--out FILE.csv)",
        )
    order = np.lexsort((field.x, field.depth))
    figure = _figure_class()(figsize=(12.0, 3.8))
    axes = figure.subplots(1, 3, sharey=True)
    name = "amplitude (state 2 - state 1)" if field.amplitude is not None else "last state"
    for axis, component in zip(axes, COMPONENTS, strict=True):
        values = shown.component(component)[order].reshape(depths.size, xs.size)
        image = axis.contourf(xs, depths, values, levels=24, cmap="RdBu_r")
        figure.colorbar(image, ax=axis, shrink=0.85)
        axis.set_title(f"{component}, {name}")
        axis.set_xlabel("x (from the contact centre)")
        axis.invert_yaxis() if axis is axes[0] else None
    axes[0].set_ylabel("depth")
    if title:
        figure.suptitle(title)
    figure.tight_layout()
    target = Path(path)
    with atomic_write(target, "out") as handle:
        figure.savefig(handle, format="png", dpi=120)
    return target
