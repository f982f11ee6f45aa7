"""Partitioned Parquet datasets: cases read a partition at a time, results written a part at a
time into a hidden folder that becomes the output only when every part is there.

Input
-----
A Parquet file, or a folder of them (every ``*.parquet`` file in it, in name order; names
starting with ``.`` or ``_`` are skipped), with the same columns in every file.  It is cut into
:class:`Partition` s of at most a given number of rows (a file's rows ``start:stop``; only the
row groups that hold them are read), so a dataset of 10^8 rows is never in one process's
memory.  Each partition is read as a :class:`~asymslip.files.CaseTable`, the table the CSV
reader gives: every column's text, the numeric columns as doubles (a null is an empty field),
and each row's number in the dataset (1-based) as its ``line``.  A numeric column must hold
numbers (integers, floats or decimals), not text.

Output
------
A study writes one part per partition (``part-000000.parquet``, ...) into a hidden folder
beside the target (``.NAME.asymslip-PID-HOST-RANDOM.parts``; one that a killed study left is
removed by the next study of the same target, as the file layer does); each part is itself written
atomically, so a task that is re-run after its worker died replaces a part whole.  At the end
the folder gets a manifest (``_asymslip.json``: the command, rows and parts) and is renamed to
the target -- or, for a single ``.csv`` or ``.parquet`` target, its parts are copied in order
into that one file, written atomically.  On any failure the hidden folder is removed: the
output is complete or absent.  An existing target folder is replaced only when it is a dataset
this tool wrote (it has the manifest); any other folder is refused.

Examples
--------
>>> import pathlib, tempfile
>>> import pyarrow as pa, pyarrow.parquet as pq
>>> from asymslip.batch.dataset import open_source, output_kind, read_partition
>>> output_kind("results/"), output_kind("results.parquet"), output_kind("results.csv")
('folder', 'parquet', 'csv')
>>> with tempfile.TemporaryDirectory() as folder:
...     cases = pathlib.Path(folder) / "cases.parquet"
...     pq.write_table(pa.table({"P1": [100.0, None, 90.0], "note": ["a", "b", None]}), cases)
...     source = open_source(cases)
...     parts = source.partitions(2)
...     table = read_partition(parts[0], numeric=["P1"], required=["P1"])
>>> [(part.start, part.stop) for part in parts], table.line.tolist()
([(0, 2), (2, 3)], [1, 2])
>>> table.values["P1"].tolist()[0], table.errors, table.text["note"].to_list()
(100.0, {1: 'P1: missing value'}, ['a', 'b'])
"""

from __future__ import annotations

import json
import os
import re
import shutil
import uuid
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Literal

import numpy as np

from ..errors import InputError
from ..files import CaseTable, TextColumn
from ..files.atomic import atomic_write
from ..files.collisions import Input, Output, refuse_overwriting_inputs
from ..files.partials import LOGGER, MARKER, host_tag, partial_prefix, process_is_running
from ..files.writer import FORMATS

OutputKind = Literal["csv", "parquet", "folder"]
#: The manifest of a dataset folder this tool wrote.
MANIFEST = "_asymslip.json"
PART_SUFFIX = ".parquet"
#: The end of a staging folder's name.
STAGING_SUFFIX = ".parts"


# --- the input --------------------------------------------------------------------------------
@dataclass(frozen=True)
class Partition:
    """Rows ``start:stop`` of one Parquet file; ``first_row`` is ``start``'s index in the
    whole dataset (0-based)."""

    path: Path
    start: int
    stop: int
    first_row: int

    @property
    def rows(self) -> int:
        return self.stop - self.start


@dataclass(frozen=True)
class ParquetSource:
    """A Parquet file or folder of files: the files, their row counts and the columns."""

    path: Path
    files: tuple[Path, ...]
    rows: tuple[int, ...]
    header: tuple[str, ...]
    types: dict[str, str]

    @property
    def total(self) -> int:
        return sum(self.rows)

    def partitions(self, rows: int) -> list[Partition]:
        """Consecutive partitions of at most ``rows`` rows, never across files."""
        parts: list[Partition] = []
        first = 0
        for path, count in zip(self.files, self.rows, strict=True):
            for start in range(0, count, rows):
                stop = min(start + rows, count)
                parts.append(Partition(path, start, stop, first + start))
            first += count
        return parts


def is_parquet_input(path: Path) -> bool:
    """A folder, or a file named ``.parquet``: read as a Parquet dataset (else CSV)."""
    return path.is_dir() or path.suffix.lower() == ".parquet"


def open_source(path: str | Path, option: str = "cases") -> ParquetSource:
    """The files, rows and columns of a Parquet file or folder (reading only the footers).

    Raises
    ------
    InputError
        Naming ``option``: no such file, an empty folder, a file that is not Parquet, files of
        different columns, a dataset with no rows.
    """
    from ..files import arrow

    path = Path(path)
    if path.is_dir():
        files = sorted(
            entry
            for entry in path.iterdir()
            if entry.suffix.lower() == ".parquet"
            and entry.is_file()
            and not entry.name.startswith((".", "_"))
        )
        if not files:
            raise InputError(option, f"cannot read {path}: the folder holds no .parquet file")
    elif path.is_file():
        files = [path]
    else:
        raise InputError(option, f"cannot read {path}: no such file or folder")
    arrow.require(option, "Parquet input")
    import pyarrow.parquet as pq

    rows: list[int] = []
    header: tuple[str, ...] | None = None
    types: dict[str, str] = {}
    for file in files:
        try:
            metadata = pq.ParquetFile(file).metadata
            schema = pq.read_schema(file)
        except (OSError, ValueError) as error:  # pyarrow's ArrowInvalid is a ValueError
            raise InputError(option, f"{file}: not a readable Parquet file ({error})") from None
        names = tuple(schema.names)
        if header is None:
            header = names
            types = {field.name: str(field.type) for field in schema}
        elif names != header:
            raise InputError(
                option,
                f"{file}: its columns ({', '.join(names)}) differ from those of {files[0].name} "
                f"({', '.join(header)}); every file of a dataset has the same columns",
            )
        rows.append(int(metadata.num_rows))
    assert header is not None
    if not sum(rows):
        raise InputError(option, f"{path}: the dataset has no rows: there is nothing to read")
    return ParquetSource(path, tuple(files), tuple(rows), header, types)


def _text(column: Any) -> TextColumn:
    """An Arrow column as UTF-8 text without a Python string per row (null: empty)."""
    import pyarrow as pa
    import pyarrow.compute as pc

    values = pc.fill_null(pc.cast(column, pa.large_string()), "")
    values = values.combine_chunks() if isinstance(values, pa.ChunkedArray) else values
    _, offsets, data = values.buffers()
    start = values.offset
    offset_array = np.frombuffer(offsets, np.int64)[start : start + len(values) + 1]
    data_array = np.frombuffer(data, np.uint8) if data is not None else np.zeros(0, np.uint8)
    return TextColumn(data_array, offset_array.copy())


def read_partition(
    partition: Partition,
    *,
    numeric: Sequence[str],
    required: Sequence[str] = (),
    option: str = "cases",
) -> CaseTable:
    """One partition as a :class:`~asymslip.files.CaseTable` (see the module docstring).

    A required column's null is the row's error (``P1: missing value``), as in a CSV.
    """
    import pyarrow as pa
    import pyarrow.compute as pc
    import pyarrow.parquet as pq

    source = pq.ParquetFile(partition.path)
    metadata = source.metadata
    groups, first = [], 0
    for group in range(metadata.num_row_groups):
        count = metadata.row_group(group).num_rows
        if first < partition.stop and first + count > partition.start:
            groups.append((group, first))
        first += count
    table = source.read_row_groups([group for group, _ in groups])
    offset = partition.start - (groups[0][1] if groups else 0)
    table = table.slice(offset, partition.rows)
    header = list(table.column_names)
    text = {name: _text(table.column(name)) for name in header}
    values: dict[str, np.ndarray] = {}
    empty: dict[str, np.ndarray] = {}
    for name in dict.fromkeys([*required, *numeric]):
        if name not in header:
            continue
        column = table.column(name)
        kind = column.type
        if not (pa.types.is_integer(kind) or pa.types.is_floating(kind)) and not (
            pa.types.is_decimal(kind) or pa.types.is_null(kind)
        ):
            raise InputError(
                option,
                f"{partition.path}: column {name} holds {kind}, not numbers; store it as "
                "numbers (integers or floats)",
            )
        missing = np.asarray(pc.is_null(column).to_numpy(zero_copy_only=False), dtype=bool)
        doubles = pc.cast(column, pa.float64()).to_numpy(zero_copy_only=False)
        values[name] = np.where(missing, np.nan, np.asarray(doubles, dtype=np.float64))
        empty[name] = missing
    errors: dict[int, str] = {}
    for name in required:
        if name in empty:
            for row in np.flatnonzero(empty[name]).tolist():
                errors.setdefault(row, f"{name}: missing value")
    line = np.arange(partition.rows, dtype=np.int64) + partition.first_row + 1
    return CaseTable(
        partition.path,
        header,
        line,
        text,
        values,
        empty,
        dict(sorted(errors.items())),
        [],
        "pyarrow",
    )


# --- the output -------------------------------------------------------------------------------
def output_kind(path: str | Path, option: str = "out") -> OutputKind:
    """``csv`` or ``parquet`` for a file of that extension, ``folder`` for a path ending in a
    separator (a partitioned Parquet dataset); an existing folder named without the separator
    is refused, so that a folder is never written by accident."""
    text = str(path)
    target = Path(path)
    if text.endswith(("/", os.sep)):
        return "folder"
    if target.is_dir():
        raise InputError(
            option,
            f"{path} is a folder: end it with / to write a partitioned Parquet dataset there, "
            "or name a .csv or .parquet file",
        )
    suffix = target.suffix.lower()
    if suffix not in FORMATS:
        raise InputError(
            option,
            f"{path}: name a .csv or .parquet file, or a folder for a partitioned Parquet "
            f"dataset (end it with /) (got extension {suffix or 'none'!r})",
        )
    return FORMATS[suffix]


def is_dataset_folder(path: Path) -> bool:
    """Whether ``path`` is a folder this tool wrote (it holds the manifest)."""
    return path.is_dir() and (path / MANIFEST).is_file()


def refuse_unsafe_target(
    target: Path, kind: OutputKind, inputs: Sequence[Path], option: str
) -> None:
    """Refuse a folder target that is not ours to replace, or that holds one of the inputs."""
    if kind != "folder":
        return
    if target.exists() and not target.is_dir():
        raise InputError(option, f"{target} is a file, not a folder")
    resolved = target.resolve()
    for source in inputs:
        place = Path(source).resolve()
        if place == resolved or resolved in place.parents:
            raise InputError(
                option,
                f"{target} holds an input ({source}): replacing the folder would destroy the "
                "data being read; choose another folder",
            )
    if target.is_dir() and any(target.iterdir()) and not is_dataset_folder(target):
        raise InputError(
            option,
            f"{target} is a folder this tool did not write (no {MANIFEST}): it would be "
            "replaced whole; choose a new or empty folder",
        )


def refuse_overwriting_cases(cases: Path, out: Path, kind: OutputKind, option: str = "out") -> None:
    """The project's one check (:func:`asymslip.files.collisions.refuse_overwriting_inputs`)
    for a study: the cases (a file, or a folder and every file in it) against the output (a
    file, or a folder and every file it holds now, all of which it replaces), after
    :func:`refuse_unsafe_target`."""
    refuse_unsafe_target(out, kind, [cases], option)
    inputs = [Input(cases, "cases", "the cases")]
    if cases.is_dir():
        inputs += [
            Input(entry, "cases", "a file of the cases") for entry in sorted(cases.iterdir())
        ]
    names: tuple[str, ...] = ()
    if kind == "folder" and out.is_dir():
        names = tuple(sorted(entry.name for entry in out.iterdir())) or (MANIFEST,)
    refuse_overwriting_inputs(inputs, [Output(out, option, names)])


def clean_left_over_stagings(target: Path) -> list[Path]:
    """Remove the staging folders a killed study of ``target`` left beside it -- only those
    provably left over (named as :class:`Staging` names them, on this machine, by a process that
    no longer runs, this user's); say each one found on the ``asymslip.files`` logger."""
    parent = target.parent if str(target.parent) else Path(".")
    pattern = re.compile(
        rf"\.{re.escape(target.name)}\.{MARKER}-(\d+)-([0-9a-f]{{8}})-[0-9a-f]+{STAGING_SUFFIX}"
    )
    removed = []
    try:
        entries = sorted(os.scandir(parent), key=lambda entry: entry.name)
    except OSError:
        return []
    for entry in entries:
        match = pattern.fullmatch(entry.name)
        if match is None or not entry.is_dir(follow_symlinks=False):
            continue
        pid, host = int(match.group(1)), match.group(2)
        mine = not hasattr(os, "getuid") or entry.stat(follow_symlinks=False).st_uid == os.getuid()
        if host == host_tag() and pid != os.getpid() and process_is_running(pid) is False and mine:
            shutil.rmtree(entry.path, ignore_errors=True)
            LOGGER.warning("removed %s, the parts a killed study left behind", entry.path)
            removed.append(Path(entry.path))
        else:
            LOGGER.warning("kept %s: it may be the parts of a study still running", entry.path)
    return removed


class Staging:
    """The hidden folder beside a target where a study's parts are written, named as the
    file layer names its partial files (:mod:`asymslip.files.partials`) but ending in
    ``.parts``: ``.NAME.asymslip-PID-HOST-RANDOM.parts``."""

    def __init__(self, target: Path, option: str) -> None:
        self.target = target
        self.option = option
        parent = target.parent if str(target.parent) else Path(".")
        self.folder = parent / (partial_prefix(target) + uuid.uuid4().hex[:8] + STAGING_SUFFIX)
        try:
            self.folder.mkdir()
        except OSError as error:
            raise InputError(option, f"cannot write {target}: {error.strerror}") from None

    def part(self, index: int, suffix: str = PART_SUFFIX) -> Path:
        return self.folder / f"part-{index:06d}{suffix}"

    def parts(self, count: int, suffix: str = PART_SUFFIX) -> list[Path]:
        return [self.part(index, suffix) for index in range(count)]

    def publish_folder(self, manifest: dict[str, Any]) -> None:
        """Write the manifest and rename the folder to the target (replacing an old dataset)."""
        for stray in self.folder.iterdir():  # partial files of a worker that died writing
            if stray.name.startswith("."):
                stray.unlink(missing_ok=True)
        (self.folder / MANIFEST).write_text(json.dumps(manifest, indent=1) + "\n")
        target = self.target
        old = None
        if target.is_dir():
            if any(target.iterdir()):
                old = target.parent / f".{target.name}.asymslip-old-{uuid.uuid4().hex[:8]}"
                os.rename(target, old)
            else:
                target.rmdir()
        os.rename(self.folder, target)
        if old is not None:
            shutil.rmtree(old, ignore_errors=True)

    def discard(self) -> None:
        shutil.rmtree(self.folder, ignore_errors=True)


@contextmanager
def staging(target: Path, option: str = "out") -> Iterator[Staging]:
    """A :class:`Staging` folder, removed if the block fails (publish it inside the block)."""
    stage = Staging(target, option)
    try:
        yield stage
    finally:
        stage.discard()  # after a publish the folder has been renamed away: nothing to remove


def merge_parts(parts: Sequence[Path], target: Path, kind: OutputKind, option: str) -> int:
    """Copy the parts, in order, into the one file ``target`` (written atomically); its size.

    CSV parts each start with the same header line, kept once; Parquet parts' row groups are
    copied as they are (one schema).
    """
    if kind == "csv":
        with atomic_write(target, option) as handle:
            for index, part in enumerate(parts):
                with open(part, "rb") as source:
                    header = source.readline()
                    if index == 0:
                        handle.write(header)
                    shutil.copyfileobj(source, handle, 1 << 20)
        return target.stat().st_size
    import pyarrow as pa
    import pyarrow.parquet as pq

    first = pq.ParquetFile(parts[0])
    schema = first.schema_arrow
    categories = [field.name for field in schema if pa.types.is_dictionary(field.type)]
    with atomic_write(target, option) as handle:
        writer = pq.ParquetWriter(
            pa.PythonFile(handle, mode="w"), schema, use_dictionary=categories
        )
        try:
            for part in parts:
                source = pq.ParquetFile(part)
                for group in range(source.metadata.num_row_groups):
                    writer.write_table(source.read_row_group(group))
        finally:
            writer.close()
    return target.stat().st_size
