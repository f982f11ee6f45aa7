"""The columns of a sweep's result: the input as given, every slip-zone quantity, the error.

Examples
--------
>>> from asymslip.sweep.columns import edge_columns, output_columns
>>> edge_columns()[:4]
['a1', 'a2', 'lam', 'eta']
>>> output_columns(["case", "P1", "Q1", "P2", "Q2"], "left")[:7]
['case', 'P1', 'Q1', 'P2', 'Q2', 'left_a1', 'left_a2']
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Literal

from ..edge import Edge
from ..edge_flags import MEASURE_KEYS, NUMBER_KEYS

Edges = Literal["right", "left", "both"]

#: Input columns the sweep reads; the first four are required.
CYCLE_COLUMNS = ("P1", "Q1", "P2", "Q2", "sigma1", "sigma2")
REQUIRED_COLUMNS = ("P1", "Q1", "P2", "Q2")
#: Values of the optional columns where a row leaves them empty (mu: the --mu default).
DEFAULTS = {"sigma1": 0.0, "sigma2": 0.0}
#: Joins a row's warnings.  Not ";": one of the warning texts contains a semicolon.
WARNING_SEPARATOR = " | "
PREFIX = {"right": "", "left": "left_"}


def edge_columns() -> list[str]:
    """One edge's columns: the JSON keys of ``slip-zone`` flattened (validity.eq24 -> eq24)."""
    return [*NUMBER_KEYS, *MEASURE_KEYS, "warnings"]


def edges_of(edge: Edges) -> list[Edge]:
    return {"right": [Edge.RIGHT], "left": [Edge.LEFT], "both": [Edge.RIGHT, Edge.LEFT]}[edge]


def output_columns(input_columns: Sequence[str], edge: Edges) -> list[str]:
    names = list(input_columns)
    for side in edges_of(edge):
        names.extend(PREFIX[side] + name for name in edge_columns())
    return [*names, "error"]
