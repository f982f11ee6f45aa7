"""A study: read -> evaluate -> write, mapped over the partitions of its cases, in one process
or on a Dask cluster, with an output that is complete or absent.

The same evaluation function (a sweep's chunk through the core, or a batch of solves) runs on
every partition wherever it runs: :func:`run_job` reads the partition (a slice of a CSV table
the driver read, or rows of a Parquet dataset the task reads itself), evaluates it, and either
returns the result columns or writes them as one part of the output.  :func:`run_study`
decides where the parts go:

- one process, one ``.csv``/``.parquet`` file: each partition's columns are written in order
  through :func:`asymslip.files.open_table` (the file appears when complete);
- a folder (a partitioned Parquet dataset), in one process or on a cluster: each task writes
  its part into the hidden staging folder of :mod:`.dataset`, renamed to the target at the end;
- a cluster and one file: the tasks write parts (in the file's format) into the staging
  folder, copied in order into the file at the end.

Examples
--------
A sweep of two cycles, one a task, in this process (the second slides grossly):

>>> import functools, pathlib, tempfile
>>> from asymslip import HertzLaw
>>> from asymslip.batch.study import Reading, run_study
>>> from asymslip.files import read_table
>>> from asymslip.sweep.chunk import schema, sweep_chunk
>>> with tempfile.TemporaryDirectory() as folder:
...     cases = pathlib.Path(folder) / "cases.csv"
...     _ = cases.write_text("P1,Q1,P2,Q2\\n100,0,105,1\\n100,0,105,50\\n")
...     table = read_table(cases, required=["P1", "Q1", "P2", "Q2"])
...     evaluate = functools.partial(
...         sweep_chunk, law=HertzLaw(1, 1), default_mu=0.1, edge="right", numbers=set()
...     )
...     columns = schema(table.header, "right", set())
...     out = pathlib.Path(folder) / "out.csv"
...     run = run_study(table, out, "csv", columns, evaluate, Reading(()), rows_per_task=1)
>>> run.rows, [line for line, _ in run.failed]
(2, [3])
"""

from __future__ import annotations

import sys
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any, TextIO

from ..files import CaseTable, Progress, TextColumn, open_table
from ..files.writer import Column, Kind
from .cluster import Cluster, run_tasks
from .dataset import (
    PART_SUFFIX,
    OutputKind,
    ParquetSource,
    Partition,
    clean_left_over_stagings,
    merge_parts,
    read_partition,
    staging,
)

Evaluate = Callable[[CaseTable], tuple[dict[str, Column], list[tuple[int, str]]]]


@dataclass(frozen=True)
class Reading:
    """How a task reads a Parquet partition: the columns parsed as numbers, those required."""

    numeric: tuple[str, ...]
    required: tuple[str, ...] = ()
    option: str = "cases"


@dataclass(frozen=True)
class Job:
    """One task: its rows, how to evaluate them, and where to write them (None: return)."""

    rows: CaseTable | Partition
    evaluate: Evaluate
    reading: Reading
    schema: tuple[tuple[str, Kind], ...]
    part: Path | None = None


@dataclass(frozen=True)
class JobResult:
    """Rows evaluated, the failed ones as (line, message), the columns if not written."""

    rows: int
    failed: list[tuple[int, str]]
    columns: dict[str, Column] | None = None


def run_job(job: Job) -> JobResult:
    """Read, evaluate and (for a part) write one partition; runs on a worker."""
    table = (
        job.rows
        if isinstance(job.rows, CaseTable)
        else read_partition(
            job.rows,
            numeric=job.reading.numeric,
            required=job.reading.required,
            option=job.reading.option,
        )
    )
    columns, failed = job.evaluate(table)
    rows = len(next(iter(columns.values()))) if columns else 0
    if job.part is None:
        return JobResult(rows, failed, columns)
    with open_table(job.part, job.schema, option="out") as writer:
        writer.write(columns)
    return JobResult(rows, failed)


@dataclass
class StudyRun:
    """What a study wrote: rows, the failed rows or cases (line, message), where, how long."""

    rows: int
    out: Path
    seconds: float
    failed: list[tuple[int, str]] = field(default_factory=list)
    parts: int = 0
    bytes: int = 0


def _own_text(table: CaseTable) -> CaseTable:
    """The slice with text columns of its own bytes: a slice's text shares the whole file's
    buffer, which would travel to the worker with every task."""
    text = {
        name: TextColumn(
            column.data[column.offsets[0] : column.offsets[-1]].copy(),
            column.offsets - column.offsets[0],
        )
        for name, column in table.text.items()
    }
    return replace(table, text=text)


def _pieces(
    source: CaseTable | ParquetSource, rows: int, shipped: bool
) -> list[CaseTable | Partition]:
    if isinstance(source, CaseTable):
        chunks = source.chunks(rows)
        return [_own_text(chunk) if shipped else chunk for chunk in chunks]
    return list(source.partitions(rows))


def run_study(
    source: CaseTable | ParquetSource,
    out: Path,
    kind: OutputKind,
    schema: Sequence[tuple[str, Kind]],
    evaluate: Evaluate,
    reading: Reading,
    *,
    rows_per_task: int,
    cluster: Cluster | None = None,
    command: str = "study",
    progress: bool | None = None,
    stream: TextIO | None = None,
    total: int = 0,
    client: Any = None,
) -> StudyRun:
    """Evaluate every partition of ``source`` and write the results to ``out``.

    Parameters
    ----------
    source
        A table the driver read (cut into slices of ``rows_per_task`` rows, sent to the
        tasks), or a Parquet dataset (cut into partitions the tasks read themselves).
    out, kind
        The target and what it is (:func:`asymslip.batch.dataset.output_kind`).
    schema
        The output columns.
    evaluate
        A table's rows -> (result columns, failed (line, message)); must pickle for a cluster.
    reading
        How a Parquet partition is read.
    rows_per_task
        Input rows a task takes.
    cluster
        None: this process.
    command
        Named in the manifest and the tasks' keys.
    progress, stream
        The progress bar: the project's (rows, on ``stream``) in one process, distributed's on
        a cluster; default only on a terminal.
    total
        Input rows, for the progress bar.
    client
        An open ``distributed.Client`` to run on instead of connecting to ``cluster`` (one
        cluster for several studies).
    """
    started = time.perf_counter()
    clean_left_over_stagings(out)
    here = cluster is None and client is None
    pieces = _pieces(source, rows_per_task, shipped=not here)
    frozen = tuple(schema)
    failed: list[tuple[int, str]] = []
    if here and kind != "folder":
        bar = Progress(total, stream or sys.stderr, progress, label=command)
        done = 0
        with open_table(out, frozen, option="out") as writer:
            for piece in pieces:
                result = run_job(Job(piece, evaluate, reading, frozen))
                assert result.columns is not None
                writer.write(result.columns)
                failed.extend(result.failed)
                done += len(piece) if isinstance(piece, CaseTable) else piece.rows
                bar.update(done)
        bar.close()
        return StudyRun(
            writer.rows, out, time.perf_counter() - started, failed, 1, writer.written.bytes
        )
    suffix = PART_SUFFIX if kind in ("folder", "parquet") else ".csv"
    with staging(out) as stage:
        parts = stage.parts(len(pieces), suffix)
        jobs = [
            Job(piece, evaluate, reading, frozen, part)
            for piece, part in zip(pieces, parts, strict=True)
        ]
        results = run_tasks(run_job, jobs, cluster, progress=progress, name=command, client=client)
        rows = sum(result.rows for result in results)
        for result in results:
            failed.extend(result.failed)
        if kind == "folder":
            manifest: dict[str, Any] = {
                "written_by": f"asymslip {command}",
                "rows": rows,
                "parts": [part.name for part in parts],
                "part_rows": [result.rows for result in results],
                "columns": [name for name, _ in frozen],
            }
            size = sum(part.stat().st_size for part in parts)
            stage.publish_folder(manifest)
        else:
            size = merge_parts(parts, out, kind, "out")
    return StudyRun(rows, out, time.perf_counter() - started, failed, len(parts), size)
