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

from ..errors import InputError
from ..files import Progress, WrittenTable, open_table, read_table
from ..files.collisions import Input, Output, refuse_overwriting_inputs
from ..files.writer import table_format
from ..laws.base import ContactLaw
from .chunk import check_header, schema, sweep_chunk
from .columns import REQUIRED_COLUMNS, WARNING_SEPARATOR, Edges, edge_columns, output_columns

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
    #: What an invalid row's number counts: ``line`` of a CSV file, ``row`` of a dataset.
    unit: str = "line"

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
            lines.extend(
                f"  {self.unit} {line}: {message}" for line, message in self.invalid[:shown]
            )
            if len(self.invalid) > shown:
                lines.append(f"  ... and {len(self.invalid) - shown} more")
        return "\n".join(lines)


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
    check_header(table.header, cases, mu)
    default_mu = None if mu is None else float(mu)
    invalid: list[tuple[int, str]] = []
    bar = Progress(len(table), stream or sys.stderr, progress)
    # Parquet keeps the columns the sweep reads as numbers as numbers (float64, null where a
    # field is empty or not a number: its row's error says which); CSV copies every field's
    # text as written, for an exact round trip.
    numbers = set(table.values) if table_format(out) == "parquet" else set()
    with open_table(
        out, schema(table.header, edge, numbers), option="out", inputs=[source]
    ) as writer:
        for part in table.chunks(chunk_rows):
            columns, bad = sweep_chunk(
                part, law=law, default_mu=default_mu, edge=edge, numbers=numbers
            )
            writer.write(columns)
            invalid.extend(bad)
            bar.update(writer.rows)
    bar.close()
    return SweepSummary(
        len(table), out, time.perf_counter() - start, invalid, writer.written, len(table.comments)
    )
