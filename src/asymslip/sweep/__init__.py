"""``asymslip sweep``: everything ``slip-zone`` reports, for every load cycle of a CSV file.

Read -> evaluate -> write, on top of the one evaluation model of :mod:`asymslip.slip_zones`.
One cycle per row (columns ``P1, Q1, P2, Q2``; optional ``sigma1, sigma2`` (default 0) and
``mu`` (overrides ``--mu``); other columns are carried through untouched).  Each row is checked
by the rules the API checks, and a row that breaks one is written with its reason in the
``error`` column (the message ``slip_zone`` would raise for it) instead of stopping the
others.  Nothing is dropped: every non-blank input line gives one output line, in order.

Output columns: the input columns as given, then the JSON keys of ``slip-zone`` flattened
(``validity.eq24 -> eq24``; ``warnings`` joined by :data:`WARNING_SEPARATOR`), the left edge's
prefixed ``left_``, then ``error``.  The result is written beside the target and renamed when
complete: an interrupted sweep leaves no truncated file.
"""

from __future__ import annotations

import sys
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import TextIO

import numpy as np

from ..errors import InputError
from ..files.atomic import atomic_write, refuse_same_file
from ..laws.base import ContactLaw
from .columns import (
    CYCLE_COLUMNS,
    WARNING_SEPARATOR,
    Edges,
    edge_columns,
    edges_of,
    output_columns,
)
from .evaluate import evaluate_chunk
from .progress import Progress
from .reading import parse_chunk, read_header
from .writing import _compressed_rows, _quoted, format_numbers

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

    @property
    def rows_per_second(self) -> float:
        return self.rows / self.seconds if self.seconds > 0 else float("inf")

    def report(self, shown: int = 10) -> str:
        """The stderr summary."""
        lines = [f"asymslip sweep: {self.rows} rows written to {self.out} in "
                 f"{self.seconds:.2f} s ({self.rows_per_second:,.0f} rows/s)"]  # fmt: skip
        if self.invalid:
            lines.append(f"{len(self.invalid)} invalid rows (reason in the error column):")
            lines.extend(f"  line {line}: {message}" for line, message in self.invalid[:shown])
            if len(self.invalid) > shown:
                lines.append(f"  ... and {len(self.invalid) - shown} more")
        return "\n".join(lines)


def _chunk_text(lines: list[bytes], header: list[str], law: ContactLaw, edge: Edges,
                default_mu: float | None, numbers: np.ndarray) -> tuple[bytes, list[str | None]]:
    chunk = parse_chunk(lines, numbers, header, default_mu)
    result = evaluate_chunk(law, {name: chunk.values[name] for name in CYCLE_COLUMNS},
                            chunk.values["mu"], edge, chunk.errors)  # fmt: skip
    rows = len(lines)
    invalid = np.array([error is not None for error in result.errors], dtype=bool)
    commas = len(header) - 1
    # The input columns exactly as read; a line with the wrong number of fields gets empty ones.
    segments = [[line if line.count(b",") == commas else b"," * commas for line in lines]]
    for side in edges_of(edge):
        prefix = "" if side == "right" else "left_"
        blocks = []
        for column in edge_columns():
            if column == "warnings":
                segments.append(_compressed_rows(blocks))
                texts = result.warnings[prefix + "warnings"]
                quoted = [_quoted(text) for text in texts.categories]
                segments.append([quoted[code] for code in texts.codes.tolist()])
                blocks = []
                continue
            values = result.numbers[prefix + column]
            blocks.append(format_numbers(values, invalid | np.isnan(values)))
        if blocks:
            segments.append(_compressed_rows(blocks))
    segments.append([_quoted(error or "") for error in result.errors])
    width = 2 * len(segments)
    pieces: list[bytes] = [b","] * (rows * width)
    for position, segment in enumerate(segments):
        pieces[2 * position :: width] = segment
    pieces[width - 1 :: width] = [b"\n"] * rows
    return b"".join(pieces), result.errors


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
    workers: int | None = None,
) -> SweepSummary:
    """Evaluate the slip zone of every cycle in ``cases`` and write one CSV row per cycle.

    Parameters
    ----------
    cases
        CSV with a header row: ``P1, Q1, P2, Q2`` required; ``sigma1, sigma2`` (default 0) and
        ``mu`` (default ``mu``) optional; any other columns are copied through.
    law
        The contact law.
    out
        The result CSV (see the module docstring for its columns); never the input file.
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
    workers
        Accepted for compatibility; chunks are evaluated in this process.

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
    refuse_same_file(out, "out", cases)
    if mu is not None:
        mu = float(mu)
    header, lines, numbers = read_header(cases)
    if mu is None and "mu" not in header:
        raise InputError("mu", "is required: give --mu or a mu column in the cases file")
    bar = Progress(len(lines), stream or sys.stderr, progress)
    invalid: list[tuple[int, str]] = []
    with atomic_write(out, "out") as handle:
        handle.write((",".join(output_columns(header, edge)) + "\n").encode())
        for begin in range(0, len(lines), chunk_rows):
            end = begin + chunk_rows
            text, errors = _chunk_text(lines[begin:end], header, law, edge, mu,
                                       numbers[begin:end])  # fmt: skip
            handle.write(text)
            invalid.extend((int(numbers[begin + row]), message)
                           for row, message in enumerate(errors) if message is not None)
            bar.update(min(end, len(lines)))
    bar.close()
    return SweepSummary(len(lines), out, time.perf_counter() - start, invalid)
