"""Read a table of cases (CSV): every column's text, the numeric columns as doubles, and for
each row its 1-based file line and, if it is bad, why.

The file is scanned once with NumPy (line breaks, quotes, blank and comment lines, the header),
then parsed by ``pyarrow.csv`` when pyarrow is installed, else by NumPy (``np.loadtxt`` per
column, with a per-field fallback that names the bad field).  Both give the same table (tested).

The format
----------
- UTF-8, optionally with a byte-order mark; ``\\n`` or ``\\r\\n`` line ends.
- The first line that is neither blank nor a comment is the header.  A comment line starts with
  ``#`` (after optional spaces).  Blank and comment lines are skipped anywhere, and counted in
  the line numbers, as an editor shows them.
- Fields are separated by commas; a field in double quotes may hold commas, quotes (doubled)
  and line breaks (its row's line number is that of its first line).
- A number is ``[+-]digits[.digits][e[+-]digits]`` (also ``.5``, ``5.``), ``inf``,
  ``infinity`` or ``nan`` in any case, with optional spaces or tabs around it; an empty field
  is "no value".

Examples
--------
>>> import pathlib, tempfile
>>> from asymslip.files.reader import read_table
>>> with tempfile.TemporaryDirectory() as folder:
...     path = pathlib.Path(folder) / "cases.csv"
...     _ = path.write_text("# loads in N\\nP1,Q1,note\\n100,0,first\\n\\n105,abc,second\\n")
...     table = read_table(path, required=["P1", "Q1"])
>>> table.header, table.line.tolist(), table.values["P1"].tolist()
(['P1', 'Q1', 'note'], [3, 5], [100.0, 105.0])
>>> table.errors
{1: "Q1: 'abc' is not a number"}
"""

from __future__ import annotations

import codecs
import csv
import io
import os
import re
from collections.abc import Iterator, Sequence
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Literal

import numpy as np
from numpy.typing import NDArray

from ..errors import InputError
from . import arrow
from .text import TextColumn

FloatArray = NDArray[np.float64]
Engine = Literal["pyarrow", "numpy"]
#: What a parser gives: each column's text, the wanted columns' numbers, their empty and bad
#: fields, and each record's field count (None where every record had the header's).
Parsed = tuple[
    dict[str, TextColumn],
    dict[str, FloatArray],
    dict[str, NDArray[np.bool_]],
    dict[str, NDArray[np.bool_]],
    NDArray[np.int64] | None,
]

#: What a number looks like (after stripping WHITESPACE); both engines accept exactly this.
NUMBER = r"[+-]?(?:(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?|[iI][nN][fF](?:[iI][nN][iI][tT][yY])?|[nN][aA][nN])"  # noqa: E501
WHITESPACE = " \t\r\n\v\f"
_NUMBER = re.compile(NUMBER)
_NAN_TEXT = re.compile(r"[+-]?nan", re.IGNORECASE)
_SHOWN = 120  # characters of a bad line quoted in its error


@dataclass
class CaseTable:
    """The rows of a cases file.

    Attributes
    ----------
    path
        The file read.
    header
        Column names in file order.
    line
        1-based file line (as an editor counts them) of each row.
    text
        Every column's text per row, unquoted, as written (a row with the wrong number of
        fields has empty text in every column).
    values
        Each numeric column asked for, as float64: NaN where empty or bad.
    empty
        Each numeric column: True where the cell is empty (or only spaces).
    errors
        Row index -> why the row is bad (``P1: 'abc' is not a number``, ``P1: missing value``,
        ``line has 4 fields, the header has 8: '...'``); rows not listed are good.
    comments
        File lines skipped as comments.
    engine
        ``"pyarrow"`` or ``"numpy"``: which parser read the rows.
    """

    path: Path
    header: list[str]
    line: NDArray[np.int64]
    text: dict[str, TextColumn]
    values: dict[str, FloatArray]
    empty: dict[str, NDArray[np.bool_]]
    errors: dict[int, str] = field(default_factory=dict)
    comments: list[int] = field(default_factory=list)
    engine: Engine = "numpy"

    def __len__(self) -> int:
        return len(self.line)

    @property
    def bad(self) -> NDArray[np.bool_]:
        """True for each row listed in :attr:`errors`."""
        mask = np.zeros(len(self), bool)
        mask[list(self.errors)] = True
        return mask

    def slice(self, start: int, stop: int) -> CaseTable:
        """Rows ``start:stop`` (no copy of the arrays; error rows renumbered from 0)."""
        stop = min(stop, len(self))
        return CaseTable(
            self.path,
            self.header,
            self.line[start:stop],
            {name: column.slice(start, stop) for name, column in self.text.items()},
            {name: column[start:stop] for name, column in self.values.items()},
            {name: column[start:stop] for name, column in self.empty.items()},
            {row - start: message for row, message in self.errors.items() if start <= row < stop},
            self.comments,
            self.engine,
        )

    def chunks(self, rows: int) -> Iterator[CaseTable]:
        """Consecutive slices of at most ``rows`` rows."""
        for start in range(0, len(self), rows):
            yield self.slice(start, start + rows)


@dataclass
class _Layout:
    """Where the records of the file are: the result of the NumPy scan."""

    data: bytes
    buffer: NDArray[np.uint8]
    quoted: bool
    starts: NDArray[np.int64]  # byte offset of each data record
    ends: NDArray[np.int64]  # byte offset of its line break (excluding a \r before it)
    line: NDArray[np.int64]  # 1-based line of each data record
    header: list[str]
    header_line: int
    comments: list[int]
    #: A file with no quotes, blank or comment lines after its header: the body is one slice
    #: and row i is on line header_line + 1 + i; starts/ends/line are then not computed.
    body: tuple[int, int] | None = None


def read_table(
    path: str | Path,
    *,
    required: Sequence[str] = (),
    numeric: Sequence[str] = (),
    option: str = "cases",
    engine: Engine | None = None,
) -> CaseTable:
    """Read a CSV table of cases.

    Parameters
    ----------
    path
        The CSV file.
    required
        Columns the header must have; an empty cell in one is a bad row (``missing value``).
    numeric
        Columns parsed as numbers where present (the ``required`` ones are parsed too).  A
        field that is not a number makes its row bad; the first such field in this order is
        named.
    option
        The option named in file-level errors (the command line's ``cases``).
    engine
        ``"pyarrow"``, ``"numpy"`` or ``None`` (pyarrow when installed).

    Returns
    -------
    CaseTable

    Raises
    ------
    InputError
        For the file as a whole, naming ``option``, the file and the line: unreadable, not
        UTF-8 text, a NUL byte, no header, no row below the header, an unnamed, repeated or
        missing required column, a quote never closed.  Bad rows are not raised: they are
        listed in ``errors``.
    """
    path = Path(path)
    if engine is None:
        engine = "pyarrow" if arrow.available() else "numpy"
    elif engine == "pyarrow":
        arrow.require("engine", "engine='pyarrow'")
    elif engine != "numpy":
        raise InputError("engine", "must be 'pyarrow' or 'numpy'", engine)
    wanted = list(dict.fromkeys([*required, *numeric]))
    data = _read(path, option)
    layout = _simple_layout(data, path, option, required) if engine == "pyarrow" else None
    if layout is None:
        layout = _scan(data, path, option, required)
    if (not len(layout.starts)) if layout.body is None else layout.body[0] >= layout.body[1]:
        raise _fail(
            option,
            path,
            None,
            "has a header but no rows: there is nothing to read "
            "(one case per row below the header)",
        )
    wanted = [name for name in wanted if name in layout.header]
    if engine == "pyarrow":
        parsed = _parse_arrow(layout, wanted)
        if parsed is None:  # the simple reading met a bad row: scan the file, read again
            layout = _scan(data, path, option, required)
            parsed = _parse_arrow(layout, wanted)
        assert parsed is not None
    else:
        parsed = _parse_numpy(layout, wanted)
    text, values, empty, bad, counts = parsed
    errors = _row_errors(layout, counts, text, empty, bad, wanted, set(required))
    return CaseTable(
        path, layout.header, layout.line, text, values, empty, errors, layout.comments, engine
    )


# --- the scan ---------------------------------------------------------------------------------
def _fail(option: str, path: Path, line: int | None, rule: str) -> InputError:
    where = f"{path}: line {line}: " if line is not None else f"{path}: "
    return InputError(option, where + rule)


def _read(path: Path, option: str) -> bytes:
    try:
        return path.read_bytes()
    except OSError as error:
        raise InputError(option, f"cannot read {path}: {error.strerror}") from None


def _line_of(data: bytes, offset: int) -> int:
    return data.count(b"\n", 0, offset) + 1


def _check_text(data: bytes, path: Path, option: str) -> None:
    """Refuse a NUL byte or bytes that are not UTF-8, naming the line."""
    skip = len(codecs.BOM_UTF8) if data.startswith(codecs.BOM_UTF8) else 0
    nul = data.find(b"\0")
    if nul >= 0:
        raise _fail(
            option, path, _line_of(data, nul), "holds a NUL byte: this is not a CSV text file"
        )
    try:
        codecs.decode(data[skip:], "utf-8")
    except UnicodeDecodeError as error:
        raise _fail(option, path, _line_of(data, skip + error.start), "is not UTF-8 text") from None


def _parse_header(
    text: str, line: int, path: Path, option: str, required: Sequence[str]
) -> list[str]:
    header = [name.strip() for name in next(csv.reader([text]))]
    for position, name in enumerate(header, start=1):
        if not name:
            raise _fail(option, path, line, f"column {position} of the header has no name")
    repeated = sorted({name for name in header if header.count(name) > 1})
    if repeated:
        raise _fail(option, path, line, f"column {', '.join(repeated)} appears twice in the header")
    missing = [name for name in required if name not in header]
    if missing:
        raise _fail(
            option,
            path,
            line,
            f"the header has no column {', '.join(missing)} (found {', '.join(header)})",
        )
    return header


def _simple_layout(data: bytes, path: Path, option: str, required: Sequence[str]) -> _Layout | None:
    """The layout of a plain file (a header on line 1, then one record per line: no quotes,
    no blank or comment line before the trailing blank ones), found with a few ``find`` calls
    instead of a scan; ``None`` for any other file."""
    skip = len(codecs.BOM_UTF8) if data.startswith(codecs.BOM_UTF8) else 0
    end = len(data)
    while end > skip and data[end - 1] in b" \t\r\n":
        end -= 1
    if data.find(b'"', skip, end) >= 0 or data.find(b"\0", skip, end) >= 0:
        return None
    if end == skip or data[skip] in b" \t\r\n#":
        return None
    buffer = np.frombuffer(data, np.uint8)
    after = buffer[np.flatnonzero(buffer[skip:end] == 10) + skip + 1]
    if np.isin(after, np.frombuffer(b"\n\r# \t", np.uint8)).any():
        return None  # a blank, comment or indented line: scan the file
    newline = data.find(b"\n", skip, end)
    header_end = end if newline < 0 else newline
    try:
        text = data[skip:header_end].decode("utf-8").rstrip("\r")
    except UnicodeDecodeError:
        return None
    header = _parse_header(text, 1, path, option, required)
    body = (header_end + 1, end) if newline >= 0 else (end, end)
    empty = np.zeros(0, np.int64)
    return _Layout(data, buffer, False, empty, empty, empty, header, 1, [], body)


def _scan(data: bytes, path: Path, option: str, required: Sequence[str]) -> _Layout:
    """Every record's bounds and line, blank and comment lines, the header: one NumPy scan."""
    _check_text(data, path, option)
    skip = len(codecs.BOM_UTF8) if data.startswith(codecs.BOM_UTF8) else 0
    buffer = np.frombuffer(data, np.uint8)
    newlines = np.flatnonzero(buffer == 10)

    def line_of(offset: int) -> int:
        return int(np.searchsorted(newlines, offset, side="right")) + 1

    quoted = data.find(b'"', skip) >= 0
    breaks = newlines
    if quoted:
        quotes = np.flatnonzero(buffer == 34)
        if len(quotes) % 2:
            raise _fail(option, path, line_of(int(quotes[-1])), "a quoted field is never closed")
        breaks = newlines[np.searchsorted(quotes, newlines) % 2 == 0]
    starts = np.concatenate(([skip], breaks + 1)).astype(np.int64)
    ends = np.concatenate((breaks, [len(data)])).astype(np.int64)
    if starts[-1] >= len(data):  # the file ends with a line break: no last record
        starts, ends = starts[:-1], ends[:-1]
    # A \r before the line break belongs to the break.
    if len(ends):
        cr = np.zeros(len(ends), bool)
        inside = ends > starts
        cr[inside] = buffer[ends[inside] - 1] == 13
        ends = ends - cr
    line = (
        np.arange(len(starts), dtype=np.int64) + 1
        if not quoted
        else np.searchsorted(newlines, starts).astype(np.int64) + 1
    )
    # Blank and comment lines: only records that are empty or start with a space, a tab or #
    # can be either; look at those few in Python.
    first = np.full(len(starts), 0, np.uint8)
    nonempty = ends > starts
    first[nonempty] = buffer[starts[nonempty]]
    maybe = np.flatnonzero(~nonempty | (first == 32) | (first == 9) | (first == 35))
    skipped: list[int] = []
    comments: list[int] = []
    for record in maybe.tolist():
        content = data[starts[record] : ends[record]].strip(b" \t\r\n\v\f")
        if not content:
            skipped.append(record)
        elif content.startswith(b"#"):
            skipped.append(record)
            comments.append(int(line[record]))
    keep = np.ones(len(starts), bool)
    keep[skipped] = False
    records = np.flatnonzero(keep)
    names = ", ".join(required) or "its columns"
    if not len(records):
        raise _fail(option, path, None, f"has no header: it needs a header row naming {names}")
    head = int(records[0])
    header_line = int(line[head])
    text = data[starts[head] : ends[head]].decode("utf-8")
    header = _parse_header(text, header_line, path, option, required)
    records = records[1:]
    return _Layout(
        data,
        buffer,
        quoted,
        starts[records],
        ends[records],
        line[records],
        header,
        header_line,
        comments,
    )


def _field_counts(layout: _Layout) -> NDArray[np.int64]:
    """Fields in each record (commas outside quotes + 1), vectorised."""
    commas = np.flatnonzero(layout.buffer == 44)
    if layout.quoted:
        quotes = np.flatnonzero(layout.buffer == 34)
        commas = commas[np.searchsorted(quotes, commas) % 2 == 0]
    record = np.searchsorted(layout.starts, commas, side="right") - 1
    inside = (record >= 0) & (commas < layout.ends[np.maximum(record, 0)])
    return np.bincount(record[inside], minlength=len(layout.starts)) + 1


def _record_bytes(layout: _Layout, records: NDArray[np.intp]) -> memoryview | bytes:
    """The given records, one per line, as one buffer: a slice of the file when they follow
    each other (only line breaks between them), else joined."""
    if not len(records):
        return b""
    starts, ends = layout.starts[records], layout.ends[records]
    line_break = 1 + (layout.buffer[ends[:-1]] == 13)  # "\n" or "\r\n"
    if len(records) == len(layout.starts) and (starts[1:] - ends[:-1] == line_break).all():
        return memoryview(layout.data)[starts[0] : ends[-1]]
    data = layout.data
    return b"\n".join(data[a:b] for a, b in zip(starts.tolist(), ends.tolist(), strict=True))


# --- pyarrow ------------------------------------------------------------------------------------
def _text_from_arrow(column: Any) -> TextColumn:  # a pyarrow (Chunked)Array
    import pyarrow as pa

    array = column.combine_chunks() if isinstance(column, pa.ChunkedArray) else column
    _, offsets, data = array.buffers()
    kind = np.int64 if pa.types.is_large_string(array.type) else np.int32
    offsets = np.frombuffer(offsets, kind)[array.offset : array.offset + len(array) + 1]
    data = np.frombuffer(data, np.uint8) if data is not None else np.zeros(0, np.uint8)
    return TextColumn(data, offsets.astype(np.int64))


def _parse_arrow(layout: _Layout, wanted: list[str]) -> Parsed | None:
    """Parse with ``pyarrow.csv`` (every column as text), then the numbers with Arrow's cast;
    ``None`` when the simple layout turns out to hold a bad row (the caller scans the file)."""
    import pyarrow as pa
    import pyarrow.csv as pcsv

    header = layout.header
    read = pcsv.ReadOptions(column_names=header, use_threads=True)
    parse = pcsv.ParseOptions(newlines_in_values=layout.quoted, ignore_empty_lines=False)
    convert = pcsv.ConvertOptions(
        column_types={name: pa.string() for name in header},
        strings_can_be_null=False,
        quoted_strings_can_be_null=False,
    )
    counts = None
    if layout.body is not None:
        begin, end = layout.body
        try:
            table = pcsv.read_csv(
                pa.py_buffer(memoryview(layout.data)[begin:end]), read, parse, convert
            )
        except pa.ArrowInvalid:  # wrong field count or bad UTF-8: the careful way
            return None
        rows = table.num_rows
        good = np.arange(rows)
        layout.line = np.arange(rows, dtype=np.int64) + layout.header_line + 1
    else:
        rows = len(layout.starts)
        good = np.arange(rows)
        table = None
        try:
            table = pcsv.read_csv(pa.py_buffer(_record_bytes(layout, good)), read, parse, convert)
        except pa.ArrowInvalid:  # a row with the wrong number of fields: find them, drop them
            pass
        if table is None or table.num_rows != rows:
            counts = _field_counts(layout)
            good = np.flatnonzero(counts == len(header))
            # No well-formed row at all: pyarrow refuses an empty buffer ("Empty CSV file"), so
            # the table of no rows is built here; every row then carries its field-count error.
            table = (
                pcsv.read_csv(pa.py_buffer(_record_bytes(layout, good)), read, parse, convert)
                if len(good)
                else pa.table({name: pa.array([], pa.string()) for name in header})
            )
        if table.num_rows != len(good):  # the scan and pyarrow disagree on the records
            raise RuntimeError(
                f"pyarrow read {table.num_rows} rows where "
                f"the scan found {len(good)}; use engine='numpy'"
            )
    text: dict[str, TextColumn] = {}
    for name in header:
        column = _text_from_arrow(table[name])
        text[name] = column if len(good) == rows else _spread_text(column, good, rows)
    # Arrow's cast runs in C++ without the GIL: one thread per column uses every core.
    with ThreadPoolExecutor(max(1, min(len(wanted), os.cpu_count() or 1))) as pool:
        converted = list(pool.map(lambda name: _arrow_numbers(table[name]), wanted))
    values: dict[str, FloatArray] = {}
    empty: dict[str, NDArray[np.bool_]] = {}
    bad: dict[str, NDArray[np.bool_]] = {}
    for name, (number, blank, wrong) in zip(wanted, converted, strict=True):
        values[name], empty[name], bad[name] = (
            _spread(number, good, rows, np.nan),
            _spread(blank, good, rows, False),
            _spread(wrong, good, rows, False),
        )
    return text, values, empty, bad, counts


def _arrow_numbers(column: Any) -> tuple[FloatArray, NDArray[np.bool_], NDArray[np.bool_]]:
    """(values, empty, not a number) of one Arrow text column."""
    import pyarrow as pa
    import pyarrow.compute as pc

    blank = pc.equal(column, "")
    try:
        source = pc.if_else(blank, "nan", column) if pc.any(blank).as_py() else column
        parsed = pc.cast(source, pa.float64())
        wrong = np.zeros(len(column), bool)
    except pa.ArrowInvalid:  # spaces around numbers, or a bad field: the careful way
        column = pc.utf8_trim(column, WHITESPACE)
        blank = pc.equal(column, "")
        fits = pc.match_substring_regex(column, f"^(?:{NUMBER})$")
        parsed = pc.cast(pc.if_else(fits, column, "nan"), pa.float64())
        wrong = ~np.asarray(fits.to_numpy(zero_copy_only=False), bool)
    number = np.asarray(parsed.to_numpy(zero_copy_only=False), np.float64)
    if not number.flags.writeable:
        number = number.copy()
    blank = np.asarray(blank.to_numpy(zero_copy_only=False), bool)
    wrong &= ~blank
    # Arrow also reads "nan(123)": only nan itself is a number here.
    for row in np.flatnonzero(np.isnan(number) & ~blank & ~wrong).tolist():
        if not _NAN_TEXT.fullmatch(column[row].as_py().strip(WHITESPACE)):
            wrong[row] = True
    number[blank | wrong] = np.nan
    return number, blank, wrong


def _spread(array: NDArray[Any], good: NDArray[np.intp], rows: int, fill: object) -> NDArray[Any]:
    if len(good) == rows:
        return array
    full = np.full(rows, fill, dtype=array.dtype)
    full[good] = array
    return full


def _spread_text(column: TextColumn, good: NDArray[np.intp], rows: int) -> TextColumn:
    """Rows ``good`` of a column of ``rows`` rows; the others empty."""
    lengths = np.zeros(rows, np.int64)
    lengths[good] = np.diff(column.offsets)
    offsets = np.empty(rows + 1, np.int64)
    offsets[0] = column.offsets[0]
    np.cumsum(lengths, out=offsets[1:])
    offsets[1:] += column.offsets[0]
    return TextColumn(column.data, offsets)


# --- NumPy --------------------------------------------------------------------------------------
def _parse_numpy(layout: _Layout, wanted: list[str]) -> Parsed:
    header = layout.header
    rows = len(layout.starts)
    counts = _field_counts(layout)
    good = np.flatnonzero(counts == len(header))
    if layout.quoted:
        text = _split_quoted(layout, good)
    else:
        text = _split_plain(layout, good)
    if len(good) != rows:
        text = {name: _spread_text(column, good, rows) for name, column in text.items()}
    values: dict[str, FloatArray] = {}
    empty: dict[str, NDArray[np.bool_]] = {}
    bad: dict[str, NDArray[np.bool_]] = {}
    for name in wanted:
        number, blank, wrong = _numbers(text[name])
        outside = np.ones(rows, bool)
        outside[good] = False
        blank &= ~outside
        number[outside] = np.nan
        values[name], empty[name], bad[name] = number, blank, wrong
    return text, values, empty, bad, counts


def _split_plain(layout: _Layout, good: NDArray[np.intp]) -> dict[str, TextColumn]:
    """Field bounds from the comma positions of well-formed records (no quotes in the file)."""
    width = len(layout.header)
    starts, ends = layout.starts[good], layout.ends[good]
    commas = np.flatnonzero(layout.buffer == 44)
    record = np.searchsorted(layout.starts, commas, side="right") - 1
    inside = (record >= 0) & (commas < layout.ends[np.maximum(record, 0)])
    commas, record = commas[inside], record[inside]
    keep = np.zeros(len(layout.starts), bool)
    keep[good] = True
    pairs = commas[keep[record]].reshape(len(good), width - 1)
    field_starts = np.column_stack([starts, pairs + 1])
    field_ends = np.column_stack([pairs, ends])
    columns = {}
    for position, name in enumerate(layout.header):
        lengths = field_ends[:, position] - field_starts[:, position]
        data, offsets = _gather(layout.buffer, field_starts[:, position], lengths)
        columns[name] = TextColumn(data, offsets)
    return columns


def _gather(
    buffer: NDArray[np.uint8], starts: NDArray[np.int64], lengths: NDArray[np.int64]
) -> tuple[NDArray[np.uint8], NDArray[np.int64]]:
    offsets = np.zeros(len(starts) + 1, np.int64)
    np.cumsum(lengths, out=offsets[1:])
    total = int(offsets[-1])
    if not total:
        return np.zeros(0, np.uint8), offsets
    index = np.repeat(starts - offsets[:-1], lengths) + np.arange(total, dtype=np.int64)
    return buffer[index], offsets


def _split_quoted(layout: _Layout, good: NDArray[np.intp]) -> dict[str, TextColumn]:
    """Quoted fields (commas, quotes, line breaks inside): Python's csv module, record by
    record."""
    data = layout.data
    fields = [
        next(csv.reader([data[a:b].decode("utf-8")]))
        for a, b in zip(layout.starts[good].tolist(), layout.ends[good].tolist(), strict=True)
    ]
    return {
        name: TextColumn.from_strings(row[position] for row in fields)
        for position, name in enumerate(layout.header)
    }


def _numbers(column: TextColumn) -> tuple[FloatArray, NDArray[np.bool_], NDArray[np.bool_]]:
    """(values, empty, not a number) of a text column: np.loadtxt, or field by field."""
    rows = len(column)
    lengths = np.diff(column.offsets)
    number = np.full(rows, np.nan)
    blank = lengths == 0
    wrong = np.zeros(rows, bool)
    present = np.flatnonzero(~blank)
    if not len(present):
        return number, blank, wrong
    data, offsets = (
        (column.data, column.offsets)
        if len(present) == rows
        else (lambda taken: (taken.data, taken.offsets))(column.take(present))
    )
    lines = np.insert(data[offsets[0] : offsets[-1]], (offsets[1:-1] - offsets[0]), 10)
    try:
        parsed = np.loadtxt(
            io.BytesIO(lines.tobytes() + b"\n"),
            dtype=np.float64,
            comments=None,
            delimiter="\x1f",
            ndmin=1,
        )
        if len(parsed) != len(present):
            raise ValueError("lines lost")
        number[present] = parsed
    except ValueError:
        texts = column.take(present).to_list()
        for row, item in zip(present.tolist(), texts, strict=True):
            item = item.strip(WHITESPACE)
            if not item:
                blank[row] = True
            elif _NUMBER.fullmatch(item):
                number[row] = float(item)
            else:
                wrong[row] = True
    return number, blank, wrong


# --- the errors of each row -----------------------------------------------------------------------
def _row_errors(
    layout: _Layout,
    counts: NDArray[np.int64] | None,
    text: dict[str, TextColumn],
    empty: dict[str, NDArray[np.bool_]],
    bad: dict[str, NDArray[np.bool_]],
    wanted: list[str],
    required: set[str],
) -> dict[int, str]:
    """Why each bad row is bad: its field count, else its first bad field in ``wanted`` order."""
    errors: dict[int, str] = {}
    width = len(layout.header)
    if counts is not None:
        for row in np.flatnonzero(counts != width).tolist():
            shown = layout.data[layout.starts[row] : layout.ends[row]].decode("utf-8")
            if len(shown) > _SHOWN:
                shown = shown[:_SHOWN] + "..."
            errors[row] = f"line has {counts[row]} fields, the header has {width}: {shown!r}"
    flagged = np.zeros(len(layout.line), bool)
    for name in wanted:
        flagged |= bad[name]
        if name in required:
            flagged |= empty[name]
    for row in np.flatnonzero(flagged).tolist():
        if row in errors:
            continue
        for name in wanted:
            if bad[name][row]:
                errors[row] = f"{name}: {text[name][row].strip(WHITESPACE)!r} is not a number"
                break
            if name in required and empty[name][row]:
                errors[row] = f"{name}: missing value"
                break
    return dict(sorted(errors.items()))
