"""One chunk of a sweep, read -> evaluate -> columns: what every way of running a sweep does to
its rows (:func:`asymslip.sweep.sweep_file` in one process, :mod:`asymslip.batch.sweep` on the
partitions of a dataset or a Dask cluster).

Examples
--------
>>> from asymslip.sweep.chunk import schema
>>> schema(["case", "P1", "Q1", "P2", "Q2"], "right", {"P1"})[:3]
[('case', 'text'), ('P1', 'float'), ('Q1', 'text')]
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import numpy as np

from ..errors import InputError
from ..files import CaseTable, Categorical
from ..files.writer import Column, Kind
from ..laws.base import ContactLaw
from .columns import (
    CYCLE_COLUMNS,
    DEFAULTS,
    PREFIX,
    Edges,
    edge_columns,
    edges_of,
    output_columns,
)
from .evaluate import FloatArray, evaluate_chunk


def schema(header: list[str], edge: Edges, numbers: set[str]) -> list[tuple[str, Kind]]:
    """Input columns (``numbers`` as numbers, the rest as text), then each edge's numbers and
    warnings, then the error."""
    columns: list[tuple[str, Kind]] = [
        (name, "float" if name in numbers else "text") for name in header
    ]
    for side in edges_of(edge):
        columns.extend(
            (PREFIX[side] + name, "category" if name == "warnings" else "float")
            for name in edge_columns()
        )
    columns.append(("error", "category"))
    return columns


def check_header(header: Sequence[str], cases: Path, mu: float | None) -> None:
    """Refuse an input column named like an output column, and a sweep with no friction
    coefficient anywhere."""
    clash = sorted(set(header) & set(output_columns([], "both")))
    if clash:
        raise InputError(
            "cases",
            f"{cases}: input column {', '.join(clash)} has the name of an output column; rename it",
        )
    if mu is None and "mu" not in header:
        raise InputError("mu", "is required: give --mu or a mu column in the cases file")


def cycle_values(
    part: CaseTable, default_mu: float | None
) -> tuple[dict[str, FloatArray], FloatArray, list[str | None]]:
    """The cycle columns and mu of a chunk, defaults filled in, and each row's parse error."""
    rows = len(part)
    errors: list[str | None] = [part.errors.get(row) for row in range(rows)]
    values = {}
    for name in CYCLE_COLUMNS:
        if name in part.values:
            column = part.values[name]
            if name in DEFAULTS:
                column = np.where(part.empty[name], DEFAULTS[name], column)
            values[name] = column
        else:
            values[name] = np.full(rows, DEFAULTS[name])
    fallback = np.nan if default_mu is None else default_mu
    if "mu" in part.values:
        mu = np.where(part.empty["mu"], fallback, part.values["mu"])
        if default_mu is None:
            for row in np.flatnonzero(part.empty["mu"]).tolist():
                errors[row] = errors[row] or "mu: missing (give --mu or a value in the mu column)"
    else:
        mu = np.full(rows, fallback)
    return values, mu, errors


def sweep_chunk(
    part: CaseTable,
    *,
    law: ContactLaw,
    default_mu: float | None,
    edge: Edges,
    numbers: set[str],
) -> tuple[dict[str, Column], list[tuple[int, str]]]:
    """The output columns of a chunk's rows and its invalid rows as (line, message).

    ``numbers``: the input columns written as numbers (Parquet) rather than as their text.
    """
    values, friction, errors = cycle_values(part, default_mu)
    result = evaluate_chunk(law, values, friction, edge, errors)
    columns: dict[str, Column] = {
        name: part.values[name] if name in numbers else part.text[name] for name in part.header
    }
    columns.update(result.numbers)
    columns.update(
        {
            name: Categorical(encoded.codes, encoded.categories)
            for name, encoded in result.warnings.items()
        }
    )
    columns["error"] = Categorical.from_strings(result.errors)  # None: no error
    invalid = [
        (int(part.line[row]), message)
        for row, message in enumerate(result.errors)
        if message is not None
    ]
    return columns, invalid
