"""Write a nucleation result: a table of the findings and a picture of where each criterion
peaks near both edges.

``nucleation.csv``: one row per finding -- ``edge, criterion, method, value, x, depth, angle,
resolution`` (angle in degrees, empty where none).  ``nucleation.png``: each critical-plane
criterion over the window of each edge (depth downwards), its peak marked with a cross and,
with a critical distance, the point (L/2) and line (0..2L) below the hot spot.

Examples
--------
>>> import tempfile
>>> from asymslip import HertzLaw, LoadCycle
>>> from asymslip.nucleation import Criterion, Material, nucleation
>>> from asymslip.solver import solve
>>> result = solve(HertzLaw(1, 1), LoadCycle(100, 0, 105, 1), mu=0.1, elements=200)
>>> found = nucleation(result, Material(E=1.82, nu=0.3), [Criterion.RUIZ])
>>> with tempfile.TemporaryDirectory() as folder:
...     (path,) = write_outputs(found, folder)
...     print(path.name, path.read_text().splitlines()[0])
nucleation.csv edge,criterion,method,value,x,depth,angle,resolution
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from ..errors import InputError
from ..files import Categorical
from ..files.atomic import atomic_write
from ..files.writer import Kind, open_table
from .assessment import NucleationResult

SCHEMA: list[tuple[str, Kind]] = [
    ("edge", "category"),
    ("criterion", "category"),
    ("method", "category"),
    ("value", "float"),
    ("x", "float"),
    ("depth", "float"),
    ("angle", "float"),
    ("resolution", "float"),
]


def write_table(found: NucleationResult, path: Path) -> Path:
    findings = found.findings
    with open_table(path, SCHEMA) as table:
        table.write(
            {
                "edge": Categorical.from_strings(f.edge for f in findings),
                "criterion": Categorical.from_strings(f.criterion for f in findings),
                "method": Categorical.from_strings(f.method for f in findings),
                "value": np.array([f.value for f in findings]),
                "x": np.array([f.x for f in findings]),
                "depth": np.array([f.depth for f in findings]),
                "angle": np.array([np.nan if f.angle is None else f.angle for f in findings]),
                "resolution": np.array([f.resolution for f in findings]),
            }
        )
    return path


def _figure_class() -> Any:
    try:
        from matplotlib.figure import Figure
    except ImportError:
        raise InputError(
            "out",
            "drawing nucleation.png needs matplotlib: install the 'plot' extra, e.g. "
            "pip install 'asymslip[plot]'",
        ) from None
    return Figure


def draw(found: NucleationResult, path: Path, title: str = "") -> Path:
    """One panel per critical-plane criterion and edge."""
    criteria = list(dict.fromkeys(m.criterion for m in found.maps))
    edges = list(dict.fromkeys(m.edge for m in found.maps))
    if not criteria:
        raise InputError("criteria", "the picture shows critical-plane criteria: ask for one")
    figure = _figure_class()(figsize=(5.2 * len(edges), 3.6 * len(criteria)))
    axes = np.atleast_2d(figure.subplots(len(criteria), len(edges), squeeze=False))
    for row, criterion in enumerate(criteria):
        for column, edge in enumerate(edges):
            axis = axes[row, column]
            edge_map = next(m for m in found.maps if (m.criterion, m.edge) == (criterion, edge))
            image = axis.contourf(edge_map.x, edge_map.depth, edge_map.values, levels=24)
            figure.colorbar(image, ax=axis, shrink=0.85)
            peak = found.find(edge, criterion, "peak")
            axis.plot([peak.x], [peak.depth], "wx", markersize=10, markeredgewidth=2)
            if found.material.L is not None:
                point = found.find(edge, criterion, "point")
                axis.plot([point.x, point.x], [0, 2 * found.material.L], "w-", linewidth=1)
                axis.plot([point.x], [point.depth], "wo", markersize=4)
            axis.set_ylim(float(edge_map.depth.max()), 0.0)
            axis.set_title(f"{criterion}, {edge} edge: peak {peak.value:.4g}")
            axis.set_xlabel("x (from the contact centre)")
            axis.set_ylabel("depth")
    if title:
        figure.suptitle(title)
    figure.tight_layout()
    with atomic_write(path, "out") as handle:
        figure.savefig(handle, format="png", dpi=120)
    return path


def write_outputs(found: NucleationResult, folder: str | Path, title: str = "") -> list[Path]:
    """nucleation.csv, and nucleation.png when a critical-plane criterion was asked for."""
    target = Path(folder)
    if target.exists() and not target.is_dir():
        raise InputError("out", f"{target} exists and is not a folder")
    target.mkdir(parents=True, exist_ok=True)
    written = [write_table(found, target / "nucleation.csv")]
    if found.maps:
        written.append(draw(found, target / "nucleation.png", title))
    return written
