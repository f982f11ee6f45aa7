"""``asymslip solve-batch``: the reference solver on every case of a table, in one process or on
a Dask cluster; two result rows per case (right edge, left edge).

Examples
--------
>>> import pathlib, tempfile
>>> from asymslip.batch import BatchSettings, solve_batch
>>> with tempfile.TemporaryDirectory() as folder:
...     cases = pathlib.Path(folder) / "cases.csv"
...     rows = ["case,P1,Q1,P2,Q2,mu", "fig5,100,0,105,1,0.1", "slides,100,0,105,50,0.1"]
...     _ = cases.write_text("\\n".join(rows) + "\\n")
...     settings = BatchSettings("hertz", (("R", 1.0), ("E_star", 1.0)), elements=200)
...     summary = solve_batch(cases, pathlib.Path(folder) / "out.csv", settings, progress=False)
>>> summary.cases, summary.rows, summary.failed  # doctest: +ELLIPSIS
(2, 4, [(3, 'Q2: ...')])
"""

from __future__ import annotations

import functools
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, TextIO

from ..errors import InputError
from ..files import CaseTable, read_table
from ..files.writer import Kind
from ..solver import solve
from .cases import NUMERIC_COLUMNS, BatchSettings, check_header
from .cluster import Cluster
from .dataset import (
    ParquetSource,
    is_parquet_input,
    open_source,
    output_kind,
    refuse_overwriting_cases,
)
from .solving import Solve, result_schema, solve_table
from .study import Reading, run_study

#: Cases a task solves by default: a task costs milliseconds on a cluster, a solve about 0.3 s
#: to seconds, and ten cases keep 2 x 64 workers busy from 1,280 cases on.
CASES_PER_TASK = 10


@dataclass
class BatchSummary:
    """What a batch did: cases, rows written, the failed cases (line, message), time taken."""

    cases: int
    rows: int
    out: Path
    seconds: float
    failed: list[tuple[int, str]] = field(default_factory=list)
    parts: int = 1
    bytes: int = 0
    where: str = "one process"
    #: What a failed case's number counts: ``line`` of a CSV file, ``row`` of a Parquet dataset.
    unit: str = "line"

    def report(self, shown: int = 10) -> str:
        """The stderr summary."""
        lines = [
            f"asymslip solve-batch: {self.cases:,} cases ({self.rows:,} rows) written to "
            f"{self.out} in {self.seconds:.2f} s on {self.where} "
            f"({self.bytes / 1e6:,.1f} MB, {self.parts} part{'s' if self.parts != 1 else ''})"
        ]
        if self.failed:
            lines.append(f"{len(self.failed)} cases failed (reason in the error column):")
            lines.extend(
                f"  {self.unit} {line}: {message}" for line, message in self.failed[:shown]
            )
            if len(self.failed) > shown:
                lines.append(f"  ... and {len(self.failed) - shown} more")
        return "\n".join(lines)


def solve_batch(
    cases: str | Path,
    out: str | Path,
    settings: BatchSettings,
    *,
    cluster: Cluster | None = None,
    cases_per_task: int = CASES_PER_TASK,
    progress: bool | None = None,
    stream: TextIO | None = None,
    client: Any = None,
    solver: Solve = solve,
) -> BatchSummary:
    """Solve every case of ``cases`` and write two rows per case to ``out``.

    Parameters
    ----------
    cases
        A CSV file, a Parquet file or a folder of Parquet files: one case per row (columns in
        :mod:`asymslip.batch.cases`).
    out
        A ``.parquet`` or ``.csv`` file, or a folder (ending in ``/``) for a partitioned
        Parquet dataset (columns in :mod:`asymslip.batch.solving`).  Complete or absent.
    settings
        The law and the defaults of every row.
    cluster
        None: this process; else a :class:`~asymslip.batch.cluster.Cluster`.
    cases_per_task
        Cases one task solves (one part of a folder output).
    progress, stream
        The progress bar (default: on a terminal).
    solver
        The solver of one case, :func:`asymslip.solver.solve` (a test may wrap it).

    Raises
    ------
    InputError
        For the table or the output as a whole (unreadable, no cycle or path columns, no
        friction coefficient, a column with an output column's name, an output that is an
        input or a folder not written by this tool).  Bad cases are reported in their rows.
    """
    kind = output_kind(out)  # before Path() drops a trailing separator
    cases, out = Path(cases), Path(out)
    if (
        isinstance(cases_per_task, bool)
        or not isinstance(cases_per_task, int)
        or cases_per_task < 1
    ):
        raise InputError("cases_per_task", "must be a whole number >= 1", cases_per_task)
    refuse_overwriting_cases(cases, out, kind)
    table_or_source: CaseTable | ParquetSource
    if is_parquet_input(cases):
        source = open_source(cases)
        header, total = list(source.header), source.total
        table_or_source = source
    else:
        table = read_table(cases, numeric=NUMERIC_COLUMNS, option="cases")
        header, total = table.header, len(table)
        table_or_source = table
    check_header(header, settings)
    outputs = [name for name, _ in result_schema()]
    clash = sorted(set(header) & set(outputs))
    if clash:
        raise InputError(
            "cases",
            f"{cases}: input column {', '.join(clash)} has the name of an output column; rename it",
        )
    # Parquet keeps the columns read as numbers as numbers (null where empty); CSV copies
    # every field's text as written.
    numbers = {name for name in header if name in NUMERIC_COLUMNS} if kind != "csv" else set()
    schema: list[tuple[str, Kind]] = [
        (name, "float" if name in numbers else "text") for name in header
    ]
    schema += result_schema()
    evaluate = functools.partial(solve_table, settings=settings, numbers=numbers, solver=solver)
    run = run_study(
        table_or_source,
        out,
        kind,
        schema,
        evaluate,
        Reading(NUMERIC_COLUMNS),
        rows_per_task=cases_per_task,
        cluster=cluster,
        command="solve-batch",
        progress=progress,
        stream=stream,
        total=total,
        client=client,
    )
    where = "one process" if client is None else "the given Dask client's cluster"
    if cluster is not None:
        where = (
            f"a local cluster of {cluster.workers} workers"
            if cluster.workers is not None
            else f"the cluster at {cluster.scheduler}"
        )
    return BatchSummary(
        total,
        run.rows,
        out,
        run.seconds,
        sorted(run.failed),
        run.parts,
        run.bytes,
        where,
        "row" if is_parquet_input(cases) else "line",
    )
