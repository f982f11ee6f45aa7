"""FE XY reports: a surface path's contact pressure against position, as Abaqus writes it.

An Abaqus/CAE XY report (Report > XY, or ``session.writeXYReport`` from a script) of path
data -- CPRESS along a path of surface nodes, X the true distance along the path or a
coordinate -- is what :func:`parse_xy_report` reads.  The layout, as Abaqus writes it:

* a blank line, the column titles -- ``X`` over the first column, then each XY data object's
  name -- a blank line, then one row per point, and blank lines at the end.  A short name
  fits one header line (``X  CPRESS_n1  CPRESS_n4``); a long one is wrapped over two or
  more lines, a piece of every column on each line and ``X`` on the last
  (``_RF:RF2 PI: PRESS`` over ``-1 N: 1_1``);
* numbers in columns, in Abaqus's *engineering* format by default (``0.``, ``-0.``,
  ``62.5E-03``, ``-3.54027E+03``, ``1.E-03``: six significant digits, exponents a multiple
  of three) or in *scientific* format (``2.5105396E-02``);
* a row may be repeated exactly (a path point met twice, a history's step boundary).

  Those three were seen in report files written by Abaqus/CAE and published in public
  repositories: github.com/nalet/bme.Finite-Element-Analysis-I, ``assignment4/appendix/*.rpt``
  and ``assignment5/*.rpt`` (engineering format, titles wrapped over two lines), and
  github.com/lcharleux/argiope, ``doc/abq/abqpostproc/workdir/history.rpt`` (scientific
  format, one-line titles, a repeated row).  The options below are Abaqus's documented
  ``session.xyReportOptions`` (``layout``, ``minMax``, ``interpolation``), not seen in a
  published file:
* one table for all the XY data (``SINGLE_TABLE``), their points merged on one X column --
  where an XY data object has no point at a row's X the cell says ``NoValue`` (public
  readers of Abaqus reports test for that word) -- or one table per XY data object
  (``SEPARATE_TABLES``); a report appended to the file (``append``) adds another table with
  its own header;
* optionally, after the rows, lines of column minima and maxima.

The report carries no units: x and the pressures are in the model's units (the load balance
of :func:`asymslip.calibration.calibrate` refuses loads that do not fit them).  A *field*
output report (Report > Field Output: values per node label, sorted by label) is not a path
and is refused, as is a probe values report.

Rules: every line whose tokens are all numbers or ``NoValue``, the first a number, is a row;
any other non-blank line (a header, a min/max/total line, a banner) ends the table above it,
and the rows after it form a new table.  Each column after the first is one load's trace:
its rows with a number (``NoValue`` cells left out).  A row repeated exactly is read once,
with a note.  The loads are given (one per column, in file order) or read from headers that
contain ``P=<number>`` once per column.

Runtime needs NumPy only.

Examples
--------
>>> text = "\\n  X  XYData-1  XYData-2\\n\\n  0.  0.  0.\\n  1.  2.  NoValue\\n"
>>> table = parse_xy_report("path.rpt", text, loads=[10.0, 20.0])
>>> table.P.tolist(), table.x.tolist(), table.p.tolist(), table.rows.tolist()
([10.0, 10.0, 20.0], [0.0, 1.0, 0.0], [0.0, 2.0, 0.0], [4, 5, 4])
>>> print(table.notes[0])  # doctest: +NORMALIZE_WHITESPACE
read 2 pressure columns (2 loads) from 1 table of an XY report; 1 NoValue cell (no point of
that column at that X) left out
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from ..errors import InputError

FloatArray = NDArray[np.float64]

#: The word Abaqus prints in a single table where an XY data object has no point at that X.
NO_VALUE = "NoValue"
#: Reports that are not a path's XY data: their rows are values per node or element label.
NOT_A_PATH = ("Field Output Report", "Probe Values Report")
_LOAD_IN_HEADER = re.compile(r"P\s*=\s*([-+0-9.eE]+)")
#: Column titles on a header line are separated by two or more spaces (one is part of a name).
_COLUMN_GAP = re.compile(r"\s{2,}")


@dataclass(frozen=True)
class XYReport:
    """The rows of an XY report as long-format columns: one entry per point per load.

    ``rows`` gives each entry's file line (1-based); ``notes`` what the reader did.
    """

    P: FloatArray
    x: FloatArray
    p: FloatArray
    rows: NDArray[np.intp]
    notes: tuple[str, ...] = field(default=())


@dataclass
class _Table:
    """One table: its header (the text lines above its rows) and its rows (NaN for NoValue)."""

    header: tuple[str, ...]
    header_line: int
    lines: list[int] = field(default_factory=list)
    values: list[list[float]] = field(default_factory=list)
    repeated: int = 0

    @property
    def width(self) -> int:
        return len(self.values[0])

    def titles(self) -> list[str] | None:
        """Each column's title, its pieces on the header lines joined (None if they do not fit).

        Abaqus wraps a long XY data name over two or more header lines, a piece of each column
        on each line, the pieces separated by two or more spaces (a name holds single spaces:
        ``_RF:RF2 PI: PRESS`` over ``-1 N: 1_1``); ``X`` is on the last line only.  The pieces
        of each line are matched to the columns from the right.
        """
        columns: list[list[str]] = [[] for _ in range(self.width)]
        for line in self.header:
            pieces = _COLUMN_GAP.split(line.strip())
            if len(pieces) > self.width:
                return None
            for column, piece in zip(columns[self.width - len(pieces) :], pieces, strict=True):
                column.append(piece)
        return ["".join(column) for column in columns]


def _cells(line: str) -> list[float] | None:
    """The row's numbers (NaN for NoValue), or None if the line is not a row."""
    tokens = line.split()
    values = []
    for token in tokens:
        if token == NO_VALUE:
            values.append(math.nan)
            continue
        try:
            values.append(float(token))
        except ValueError:
            return None
    if not values or math.isnan(values[0]):
        return None  # a row starts with its X
    return values


def parse_xy_report(source: str, text: str, loads: Sequence[float] | None = None) -> XYReport:
    """Read the tables of an XY report into long-format columns (see the module notes).

    Parameters
    ----------
    source
        The file's name, for the messages.
    text
        Its text.
    loads
        One load per pressure column, in file order; None to read them from the headers.

    Raises
    ------
    InputError
        Naming the file line: a field or probe report, a row of another width than its
        table's, a row with no pressure, a column with no number, loads missing or of the
        wrong count.
    """
    tables: list[_Table] = []
    header: list[str] = []
    header_line = 0
    after_text = False  # the line above was a header line: a wrapped title continues
    for number, line in enumerate(text.splitlines(), start=1):
        stripped = line.strip()
        if not stripped:
            after_text = False
            continue
        if stripped.startswith(NOT_A_PATH):
            raise InputError(
                "traces",
                f"{source}: line {number}: an Abaqus {stripped.split(',')[0].lower()}: its "
                "rows are values per node or element label, not points along a path; write the "
                "path's XY data instead (Report > XY of CPRESS along a path of surface nodes)",
            )
        cells = _cells(stripped)
        if cells is None:
            if stripped.startswith("*"):  # a banner of asterisks is not a header
                after_text = False
            elif after_text:
                header.append(line)
            else:
                header, header_line, after_text = [line], number, True
            if tables and tables[-1].values:
                tables.append(_Table((), 0))  # text after rows ends their table
            continue
        after_text = False
        if not tables:
            tables.append(_Table((), 0))
        table = tables[-1]
        if not table.values:
            table.header, table.header_line = tuple(header), header_line
            if len(cells) < 2:
                raise InputError(
                    "traces",
                    f"{source}: line {number}: a row needs the position and at least one pressure",
                )
        elif len(cells) != table.width:
            raise InputError(
                "traces",
                f"{source}: line {number}: {len(cells)} numbers, the rows above have {table.width}",
            )
        elif _same(cells, table.values[-1]):
            table.repeated += 1  # the same point again: read once
            continue
        table.lines.append(number)
        table.values.append(cells)
    tables = [table for table in tables if table.values]
    if not tables:
        raise InputError("traces", f"{source}: no rows of numbers (position, pressure, ...) found")
    loads = _loads(source, tables, loads)
    P, x, p, rows = [], [], [], []
    missing = 0
    columns = [(table, j) for table in tables for j in range(1, table.width)]
    for (table, j), load in zip(columns, loads, strict=True):
        values = np.array(table.values, dtype=np.float64)
        present = ~np.isnan(values[:, j])
        missing += int(np.sum(~present))
        if not present.any():
            raise InputError(
                "traces",
                f"{source}: line {table.header_line or table.lines[0]}: pressure column {j} "
                f"has no number ({NO_VALUE} in every row)",
            )
        P.append(np.full(int(present.sum()), float(load)))
        x.append(values[present, 0])
        p.append(values[present, j])
        rows.append(np.array(table.lines, dtype=np.intp)[present])
    return XYReport(
        np.concatenate(P),
        np.concatenate(x),
        np.concatenate(p),
        np.concatenate(rows),
        _notes(tables, len(columns), len(set(loads)), missing),
    )


def _same(a: list[float], b: list[float]) -> bool:
    return all(u == v or (math.isnan(u) and math.isnan(v)) for u, v in zip(a, b, strict=True))


def _loads(source: str, tables: list[_Table], loads: Sequence[float] | None) -> list[float]:
    """One load per pressure column: as given, or one 'P=<number>' per column in the headers."""
    count = sum(table.width - 1 for table in tables)
    if loads is None:
        found: list[float] = []
        for table in tables:
            named = _named_loads(table)
            if len(named) != table.width - 1:
                raise InputError(
                    "traces",
                    f"{source}: line {table.lines[0]}: the pressure columns do not say their "
                    "load (no 'P=<number>' per column in the header): give the loads, one per "
                    "pressure column",
                )
            try:
                found += [float(value) for value in named]
            except ValueError:
                raise InputError(
                    "traces",
                    f"{source}: line {table.header_line}: the loads in the header "
                    f"({', '.join(named)}) are not numbers",
                ) from None
        loads = found
    loads = [float(load) for load in loads]
    if len(loads) != count:
        raise InputError(
            "traces",
            f"{source}: {count} pressure columns but {len(loads)} loads given: give one "
            "load per pressure column",
        )
    return loads


def _named_loads(table: _Table) -> list[str]:
    """The 'P=<number>' of each pressure column's title; else those of the whole header."""
    titles = table.titles()
    if titles is not None:
        per_column = [_LOAD_IN_HEADER.findall(title) for title in titles[1:]]
        if all(len(found) == 1 for found in per_column):
            return [found[0] for found in per_column]
    return _LOAD_IN_HEADER.findall(" ".join(line.strip() for line in table.header))


def _notes(tables: list[_Table], columns: int, loads: int, missing: int) -> tuple[str, ...]:
    plural = "s" if len(tables) > 1 else ""
    text = (
        f"read {columns} pressure column{'s' if columns > 1 else ''} ({loads} loads) from "
        f"{len(tables)} table{plural} of an XY report"
    )
    if missing:
        text += (
            f"; {missing} {NO_VALUE} cell{'s' if missing > 1 else ''} (no point of that "
            "column at that X) left out"
        )
    repeated = sum(table.repeated for table in tables)
    if repeated:
        text += f"; {repeated} row{'s' if repeated > 1 else ''} repeated exactly, read once"
    return (text,)
