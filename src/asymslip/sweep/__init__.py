"""``asymslip sweep``: everything ``slip-zone`` reports, for every load cycle of a CSV file.

Read -> evaluate -> write, on top of the one evaluation model of :mod:`asymslip.slip_zones`.
One cycle per row (columns ``P1, Q1, P2, Q2``; optional ``sigma1, sigma2`` (default 0) and
``mu`` (overrides ``--mu``); other columns are carried through untouched).  Each row is checked
by the rules the API checks, and a row that breaks one is written with its reason in the
``error`` column (the message ``slip_zone`` would raise for it) instead of stopping the
others.  Nothing is dropped: every non-blank input line gives one output line, in order.

Output columns: the input columns as given, then the JSON keys of ``slip-zone`` flattened
(``validity.eq24 -> eq24``; ``warnings`` joined by :data:`WARNING_SEPARATOR`), the left edge's
prefixed ``left_``, then ``error``.  CSV numbers are the shortest text that reads back to the
same double, and the input columns are copied as written (an exact round trip);
``--out RESULTS.parquet`` writes Parquet (pyarrow, the ``parquet`` extra), where the input
columns the sweep reads as numbers (``P1, Q1, P2, Q2, sigma1, sigma2, mu``) are float64 -- the
doubles it computed with, null where a field is empty or not a number -- and the other input
columns text.  The
result is written beside the target and renamed when complete: an interrupted sweep leaves no
truncated file.  Reading and writing go through :mod:`asymslip.files` (pyarrow when it is
installed, NumPy otherwise, the same bytes either way).

Examples
--------
>>> import pathlib, tempfile
>>> from asymslip import HertzLaw
>>> from asymslip.sweep import sweep_file
>>> with tempfile.TemporaryDirectory() as folder:
...     cases, out = pathlib.Path(folder) / "cases.csv", pathlib.Path(folder) / "out.csv"
...     _ = cases.write_text("case,P1,Q1,P2,Q2\\nfig5,100,0,105,1\\nswapped,105,0,100,1\\n")
...     summary = sweep_file(cases, HertzLaw(R=1, E_star=1), out, mu=0.1, progress=False)
...     rows = out.read_text().splitlines()
>>> summary.rows, summary.invalid  # doctest: +ELLIPSIS
(2, [(3, "P2: must exceed P1: ...")])
>>> rows[1].split(",")[:7]
['"fig5"', '"100"', '"0"', '"105"', '"1"', '11.283791670955127', '11.562445770562217']
"""

from __future__ import annotations

import sys
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import TextIO

import numpy as np

from ..errors import InputError
from ..files import CaseTable, Categorical, Progress, WrittenTable, open_table, read_table
from ..files.collisions import Input, Output, refuse_overwriting_inputs
from ..files.writer import Column, Kind, table_format
from ..laws.base import ContactLaw
from .columns import (
    CYCLE_COLUMNS,
    DEFAULTS,
    PREFIX,
    REQUIRED_COLUMNS,
    WARNING_SEPARATOR,
    Edges,
    edge_columns,
    edges_of,
    output_columns,
)
from .evaluate import FloatArray, evaluate_chunk

__all__ = ["WARNING_SEPARATOR", "SweepSummary", "edge_columns", "output_columns", "sweep_file"]

#: Rows evaluated at once: large enough to amortise NumPy's per-call cost, small enough that
#: a chunk's text and arrays stay well under 100 MB.
CHUNK_ROWS = 100_000


@dataclass
class SweepSummary:
    """What a sweep did: rows written, the invalid ones (line, message), time taken."""

    rows: int
    out: Path
    seconds: float
    invalid: list[tuple[int, str]] = field(default_factory=list)
    written: WrittenTable | None = None
    comment_lines: int = 0

    @property
    def rows_per_second(self) -> float:
        return self.rows / self.seconds if self.seconds > 0 else float("inf")

    def report(self, shown: int = 10) -> str:
        """The stderr summary."""
        lines = [
            f"asymslip sweep: {self.rows:,} rows written to {self.out} in "
            f"{self.seconds:.2f} s ({self.rows_per_second:,.0f} rows/s)"
        ]
        if self.written is not None:
            lines.append(f"  {self.written}")
        if self.comment_lines:
            lines.append(f"  {self.comment_lines} comment lines of the input were skipped")
        if self.invalid:
            lines.append(f"{len(self.invalid)} invalid rows (reason in the error column):")
            lines.extend(f"  line {line}: {message}" for line, message in self.invalid[:shown])
            if len(self.invalid) > shown:
                lines.append(f"  ... and {len(self.invalid) - shown} more")
        return "\n".join(lines)


def _schema(header: list[str], edge: Edges, numbers: set[str]) -> list[tuple[str, Kind]]:
    """Input columns (``numbers`` as numbers, the rest as text), then each edge's numbers and
    warnings, then the error."""
    schema: list[tuple[str, Kind]] = [
        (name, "float" if name in numbers else "text") for name in header
    ]
    for side in edges_of(edge):
        schema.extend(
            (PREFIX[side] + name, "category" if name == "warnings" else "float")
            for name in edge_columns()
        )
    schema.append(("error", "category"))
    return schema


def _cycle_values(
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


def sweep_file(
    cases: str | Path,
    law: ContactLaw,
    out: str | Path,
    *,
    mu: float | None = None,
    edge: Edges = "both",
    chunk_rows: int = CHUNK_ROWS,
    progress: bool | None = None,
    stream: TextIO | None = None,
) -> SweepSummary:
    """Evaluate the slip zone of every cycle in ``cases`` and write one row per cycle.

    Parameters
    ----------
    cases
        CSV with a header row: ``P1, Q1, P2, Q2`` required; ``sigma1, sigma2`` (default 0) and
        ``mu`` (default ``mu``) optional; any other columns are copied through.
    law
        The contact law.
    out
        The results, ``.csv`` or ``.parquet`` (see the module docstring for the columns);
        never the input file.  Written beside the target and renamed when complete.
    mu
        Coefficient of friction for rows without their own ``mu``.
    edge
        ``"right"``, ``"left"`` or ``"both"`` (default).
    chunk_rows
        Rows evaluated at once.
    progress
        Show a progress bar; default: only when ``stream`` is a terminal.
    stream
        Where the progress bar goes (default ``sys.stderr``).

    Returns
    -------
    SweepSummary
        Rows written, the invalid ones with their line numbers and reasons, time taken.

    Raises
    ------
    InputError
        Only for the file as a whole: unreadable, no header, a required column missing, no
        friction coefficient at all, an output that is the input.  Bad rows are reported in
        the output instead.
    """
    start = time.perf_counter()
    cases, out = Path(cases), Path(out)
    if edge not in ("right", "left", "both"):
        raise InputError("edge", "must be 'right', 'left' or 'both'", edge)
    table_format(out, "out")
    source = Input(cases, "cases", "the cases")
    refuse_overwriting_inputs([source], [Output(out, "out")])
    table = read_table(
        cases, required=REQUIRED_COLUMNS, numeric=("sigma1", "sigma2", "mu"), option="cases"
    )
    clash = sorted(set(table.header) & set(output_columns([], "both")))
    if clash:
        raise InputError(
            "cases",
            f"{cases}: input column {', '.join(clash)} has the name of an output column; rename it",
        )
    if mu is None and "mu" not in table.header:
        raise InputError("mu", "is required: give --mu or a mu column in the cases file")
    default_mu = None if mu is None else float(mu)
    invalid: list[tuple[int, str]] = []
    bar = Progress(len(table), stream or sys.stderr, progress)
    # Parquet keeps the columns the sweep reads as numbers as numbers (float64, null where a
    # field is empty or not a number: its row's error says which); CSV copies every field's
    # text as written, for an exact round trip.
    numbers = set(table.values) if table_format(out) == "parquet" else set()
    schema = _schema(table.header, edge, numbers)
    with open_table(out, schema, option="out", inputs=[source]) as writer:
        for part in table.chunks(chunk_rows):
            values, friction, errors = _cycle_values(part, default_mu)
            result = evaluate_chunk(law, values, friction, edge, errors)
            columns: dict[str, Column] = {
                name: part.values[name] if name in numbers else part.text[name]
                for name in table.header
            }
            columns.update(result.numbers)
            columns.update(
                {
                    name: Categorical(encoded.codes, encoded.categories)
                    for name, encoded in result.warnings.items()
                }
            )
            columns["error"] = Categorical.from_strings(result.errors)  # None: no error
            writer.write(columns)
            invalid.extend(
                (int(part.line[row]), message)
                for row, message in enumerate(result.errors)
                if message is not None
            )
            bar.update(writer.rows)
    bar.close()
    return SweepSummary(
        len(table), out, time.perf_counter() - start, invalid, writer.written, len(table.comments)
    )
