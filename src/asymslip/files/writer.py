"""Write a result table, chunk by chunk, as CSV or Parquet (chosen by the extension).

Columns have a fixed schema: ``"float"`` (float64; NaN means no value: an empty CSV field, a
Parquet null), ``"text"`` (:class:`TextColumn` or a sequence of strings) and ``"category"``
(:class:`Categorical`: codes and a few distinct strings, a Parquet dictionary column).

CSV: doubles as the shortest text that reads back to the same double; every text field in
double quotes (quotes doubled), a missing one (a category's code -1) an empty field, as
``pyarrow.csv`` writes strings with ``quoting_style="needed"``; ``\\n`` line ends; the header
unquoted unless a name needs it.  With pyarrow the rows are written by ``pyarrow.csv`` (whose
doubles are the shortest round-trip ones: tested), without it by the NumPy formatter of
:mod:`asymslip.files.numbers`; the two give the same bytes (tested).  Quoting every text field
keeps the fast writer whatever the text holds (pyarrow can only quote all strings or none);
CSV readers (pyarrow, pandas, Python's csv) read a quoted number as the number.

Everything goes through :func:`asymslip.files.atomic.atomic_write`: the file appears complete
when the ``with`` block ends without an error, and not at all otherwise.

Examples
--------
>>> import pathlib, tempfile
>>> import numpy as np
>>> from asymslip.files.writer import open_table
>>> with tempfile.TemporaryDirectory() as folder:
...     path = pathlib.Path(folder) / "out.csv"
...     with open_table(path, [("b", "float"), ("note", "text")]) as table:
...         table.write({"b": np.array([0.1, np.nan]), "note": ["fine", "no value"]})
...     print(path.read_text(), end="")
b,note
0.1,"fine"
,"no value"
"""

from __future__ import annotations

import time
from collections.abc import Iterator, Mapping, Sequence
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import IO, Any, Literal

import numpy as np
from numpy.typing import NDArray

from ..errors import InputError
from . import arrow
from .atomic import atomic_write
from .collisions import Input, Output, refuse_overwriting_inputs
from .numbers import WIDTH, format_doubles
from .text import Categorical, TextColumn, quote, quote_always

Kind = Literal["float", "text", "category"]
Format = Literal["csv", "parquet"]
Column = NDArray[np.float64] | TextColumn | Categorical | Sequence[str | None]
FORMATS: dict[str, Format] = {".csv": "csv", ".parquet": "parquet"}
#: Rows formatted at once by the NumPy CSV writer (bounded memory: ~45 bytes per number).
_NUMPY_ROWS = 16_384


@dataclass(frozen=True)
class WrittenTable:
    """What was written: say it on stderr (``str(written)``)."""

    path: Path
    format: Format
    rows: int
    columns: int
    bytes: int
    seconds: float
    engine: str

    def __str__(self) -> str:
        size = self.bytes / 1e6
        return (
            f"wrote {self.rows:,} rows x {self.columns} columns to {self.path} "
            f"({self.format}, {size:,.1f} MB, {self.seconds:.2f} s)"
        )


def table_format(path: str | Path, option: str = "out") -> Format:
    """``"csv"`` or ``"parquet"`` from the extension; anything else is refused."""
    suffix = Path(path).suffix.lower()
    if suffix not in FORMATS:
        raise InputError(
            option, f"{path}: the extension must be .csv or .parquet (got {suffix or 'none'!r})"
        )
    return FORMATS[suffix]


class TableWriter:
    """Write chunks of a table with a fixed schema; use :func:`open_table`."""

    def __init__(
        self,
        handle: IO[bytes],
        path: Path,
        schema: Sequence[tuple[str, Kind]],
        fmt: Format,
        engine: str,
    ) -> None:
        self.path, self.schema, self.format, self.engine = path, list(schema), fmt, engine
        self.rows = 0
        self._handle = handle
        self._started = time.perf_counter()
        self._written: WrittenTable | None = None
        self._parquet = None
        names = [name for name, _ in self.schema]
        if len(set(names)) != len(names):
            raise ValueError(f"column names repeat: {names}")
        for name, kind in self.schema:
            if kind not in ("float", "text", "category"):
                raise ValueError(f"column {name}: kind must be float, text or category")
        if fmt == "csv":
            handle.write((",".join(quote(name) for name in names) + "\n").encode("utf-8"))
        else:
            import pyarrow as pa
            import pyarrow.parquet as pq

            self._arrow_schema = pa.schema([(name, _arrow_type(kind)) for name, kind in schema])
            # Dictionary pages only for the category columns: trying them on a million distinct
            # doubles more than doubles the write time and saves nothing.
            categories = [name for name, kind in schema if kind == "category"]
            self._parquet = pq.ParquetWriter(
                pa.PythonFile(handle, mode="w"), self._arrow_schema, use_dictionary=categories
            )

    def write(self, chunk: Mapping[str, Column]) -> None:
        """Append rows: one entry per schema column, all of the same length."""
        columns = self._check(chunk)
        rows = len(next(iter(columns.values()))) if columns else 0
        if not rows:
            return
        if self.format == "parquet":
            import pyarrow as pa

            table = pa.table(
                [_arrow_array(columns[name], kind) for name, kind in self.schema],
                schema=self._arrow_schema,
            )
            assert self._parquet is not None
            self._parquet.write_table(table)
        elif self.engine == "pyarrow":
            self._write_csv_arrow(columns)
        else:
            for start in range(0, rows, _NUMPY_ROWS):
                part = {
                    name: _slice(column, start, start + _NUMPY_ROWS)
                    for name, column in columns.items()
                }
                self._handle.write(csv_rows(part, self.schema))
        self.rows += rows

    def _write_csv_arrow(self, columns: dict[str, Column]) -> None:
        import pyarrow as pa
        import pyarrow.csv as pcsv

        table = pa.table({name: _arrow_array(columns[name], kind) for name, kind in self.schema})
        sink = pa.BufferOutputStream()
        options = pcsv.WriteOptions(include_header=False, quoting_style="needed")
        pcsv.write_csv(table, sink, options)
        self._handle.write(sink.getvalue())

    def _check(self, chunk: Mapping[str, Column]) -> dict[str, Column]:
        names = [name for name, _ in self.schema]
        if set(chunk) != set(names):
            missing, extra = set(names) - set(chunk), set(chunk) - set(names)
            raise ValueError(
                f"chunk columns differ from the schema: missing {sorted(missing)}, "
                f"unknown {sorted(extra)}"
            )
        columns: dict[str, Column] = {}
        for name, kind in self.schema:
            column = chunk[name]
            if kind == "float":
                column = np.asarray(column, dtype=np.float64)
                if column.ndim != 1:
                    raise ValueError(f"column {name}: a float column is one-dimensional")
            elif kind == "text" and not isinstance(column, TextColumn):
                if isinstance(column, np.ndarray | Categorical):
                    raise ValueError(f"column {name}: a text column takes strings")
                column = TextColumn.from_strings(column)
            elif kind == "category" and not isinstance(column, Categorical):
                raise ValueError(f"column {name}: a category column takes a Categorical")
            columns[name] = column
        lengths = {len(column) for column in columns.values()}
        if len(lengths) > 1:
            raise ValueError(f"columns of one chunk differ in length: {sorted(lengths)}")
        return columns

    def _close(self) -> None:
        if self._parquet is not None:
            self._parquet.close()
        self._handle.flush()

    def _abandon(self) -> None:
        """Let go of the Parquet writer after an error (the file is being removed)."""
        if self._parquet is not None:
            try:
                self._parquet.close()
            except Exception:  # noqa: BLE001 - the original error is the one to report
                pass

    @property
    def written(self) -> WrittenTable:
        """What was written (complete once the ``with`` block has ended)."""
        if self._written is None:
            raise RuntimeError("the table is not written until its with block ends")
        return self._written


@contextmanager
def open_table(
    path: str | Path,
    schema: Sequence[tuple[str, Kind]],
    *,
    option: str = "out",
    inputs: Sequence[Input | None] = (),
    engine: str | None = None,
) -> Iterator[TableWriter]:
    """Open a result table for writing: a context manager yielding a :class:`TableWriter`.

    The rows go to a temporary file beside ``path``, renamed to ``path`` when the block ends
    without an error; on an error or an interrupt the temporary file is removed and ``path``
    is untouched.  Afterwards ``writer.written`` says what was written.

    Parameters
    ----------
    path
        ``.csv`` or ``.parquet``.
    schema
        ``(name, kind)`` per column, kind ``"float"``, ``"text"`` or ``"category"``.
    option
        The option named in errors (bad extension, unwritable folder, missing pyarrow).
    inputs
        Files being read: writing over one of them is refused
        (:func:`~asymslip.files.collisions.refuse_overwriting_inputs`).
    engine
        For CSV: ``"pyarrow"``, ``"numpy"`` or ``None`` (pyarrow when installed).  Parquet
        always needs pyarrow.

    Raises
    ------
    InputError
        An extension other than .csv/.parquet, an output that is one of ``inputs``, a folder
        that cannot be written, a full disk, Parquet without pyarrow (naming the extra).
    """
    path = Path(path)
    fmt = table_format(path, option)
    refuse_overwriting_inputs(inputs, [Output(path, option)])
    if fmt == "parquet":
        arrow.require(option, "Parquet output")
        engine = "pyarrow"
    elif engine is None:
        engine = "pyarrow" if arrow.available() else "numpy"
    elif engine == "pyarrow":
        arrow.require("engine", "engine='pyarrow'")
    elif engine != "numpy":
        raise InputError("engine", "must be 'pyarrow' or 'numpy'", engine)
    with atomic_write(path, option) as handle:
        writer = TableWriter(handle, path, schema, fmt, engine)
        try:
            yield writer
        except BaseException:
            writer._abandon()
            raise
        writer._close()
    writer._written = WrittenTable(
        path,
        fmt,
        writer.rows,
        len(writer.schema),
        path.stat().st_size,
        time.perf_counter() - writer._started,
        engine,
    )


# --- columns as Arrow arrays ---------------------------------------------------------------------
def _arrow_type(kind: Kind) -> Any:  # a pyarrow DataType (no type information)
    import pyarrow as pa

    return {
        "float": pa.float64(),
        "text": pa.large_string(),
        "category": pa.dictionary(pa.int32(), pa.string()),
    }[kind]


def _arrow_array(column: Column, kind: Kind) -> Any:  # a pyarrow Array
    import pyarrow as pa

    if kind == "float":
        values = np.asarray(column, dtype=np.float64)
        missing = np.isnan(values)
        return pa.array(values, mask=missing if missing.any() else None, type=pa.float64())
    if kind == "text":
        assert isinstance(column, TextColumn)
        offsets = column.offsets - column.offsets[0]
        data = np.ascontiguousarray(column.data[column.offsets[0] : column.offsets[-1]])
        return pa.LargeStringArray.from_buffers(
            len(column), pa.py_buffer(offsets), pa.py_buffer(data)
        )
    assert isinstance(column, Categorical)
    codes = column.codes
    missing = codes < 0
    indices = pa.array(
        np.where(missing, 0, codes).astype(np.int32), mask=missing if missing.any() else None
    )
    return pa.DictionaryArray.from_arrays(indices, pa.array(column.categories, pa.string()))


def _slice(column: Column, start: int, stop: int) -> Column:
    if isinstance(column, TextColumn | Categorical):
        return column.slice(start, min(stop, len(column)))
    return column[start:stop]


# --- the NumPy CSV formatter ---------------------------------------------------------------------
def csv_rows(columns: Mapping[str, Column], schema: Sequence[tuple[str, Kind]]) -> bytes:
    """CSV lines (no header) of one chunk, with NumPy alone.

    Runs of float columns are formatted together into one NUL-padded byte block (with the
    commas in it) whose padding is dropped in one pass; text columns are joined in between.
    """
    rows = len(next(iter(columns.values())))
    segments: list[list[bytes]] = []
    run: list[str] = []

    def flush() -> None:
        if run:
            segments.append(_float_block([np.asarray(columns[name]) for name in run], rows))
            run.clear()

    for name, kind in schema:
        if kind == "float":
            run.append(name)
            continue
        flush()
        column = columns[name]
        if isinstance(column, Categorical):
            names = [quote_always(item).encode("utf-8") for item in column.categories] + [b""]
            segments.append([names[code] for code in column.codes.tolist()])
        else:
            assert isinstance(column, TextColumn)
            segments.append(
                [b'"' + item.replace(b'"', b'""') + b'"' for item in column.to_bytes_list()]
            )
    flush()
    width = 2 * len(segments)
    pieces: list[bytes] = [b","] * (rows * width)
    for position, segment in enumerate(segments):
        pieces[2 * position :: width] = segment
    pieces[width - 1 :: width] = [b"\n"] * rows
    return b"".join(pieces)


def _float_block(columns: list[NDArray[np.float64]], rows: int) -> list[bytes]:
    """The formatted floats of each row, comma-separated, as one bytes object per row."""
    count = len(columns)
    block = np.zeros((rows, count, WIDTH + 1), np.uint8)
    values = np.stack(columns, axis=1).ravel()  # row-major: row 0's numbers first
    format_doubles(values, out=block.reshape(rows * count, WIDTH + 1)[:, :WIDTH])
    block[:, :-1, WIDTH] = ord(",")
    flat = block.reshape(rows, count * (WIDTH + 1))
    kept = flat != 0
    ends = np.cumsum(np.count_nonzero(kept, axis=1)).tolist()
    text = flat[kept].tobytes()
    return [text[a:b] for a, b in zip([0, *ends[:-1]], ends, strict=True)]


def iter_rows(path: str | Path) -> Iterator[list[str]]:
    """The rows of a CSV written here, as lists of strings (for tests and quick looks)."""
    import csv

    with open(path, newline="", encoding="utf-8") as handle:
        yield from csv.reader(handle)
