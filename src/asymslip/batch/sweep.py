"""The sweep over partitions: a Parquet dataset in, a folder of parts out, or a Dask cluster.

The same chunk evaluation as :func:`asymslip.sweep.sweep_file`
(:func:`asymslip.sweep.chunk.sweep_chunk`) mapped by :func:`asymslip.batch.study.run_study`
over the partitions of the cases: rows of a CSV file the driver read, or of a Parquet file or
folder that each task reads itself (so 10^8 rows are never in one process).  The columns are
the sweep's; the input columns the sweep reads as numbers are float64 in Parquet (null where
empty), the others text.  In one process with a CSV file in and a file out, use ``sweep_file``
(the command line does): this module gives the same rows.

Examples
--------
>>> import pathlib, tempfile
>>> import pyarrow.parquet as pq
>>> from asymslip import HertzLaw
>>> from asymslip.batch.sweep import sweep_study
>>> with tempfile.TemporaryDirectory() as folder:
...     cases = pathlib.Path(folder) / "cases.csv"
...     _ = cases.write_text("P1,Q1,P2,Q2\\n100,0,105,1\\n100,0,110,2\\n100,0,120,4\\n")
...     out = folder + "/results/"
...     summary = sweep_study(cases, HertzLaw(1, 1), out, mu=0.1, rows_per_task=2)
...     parts = sorted(p.name for p in pathlib.Path(out).iterdir())
...     exact = pq.read_table(out).column("b_exact").to_pylist()
>>> parts
['_asymslip.json', 'part-000000.parquet', 'part-000001.parquet']

``b_exact`` is a(P_K): sqrt(4 P_K / pi) by (29) with P_K = (P1 + P2)/2 - (Q2 - Q1)/(2 mu) by
(33), i.e. P_K = 97.5, 95 and 90:

>>> [round(value, 4) for value in exact]
[11.1419, 10.9981, 10.7047]
"""

from __future__ import annotations

import functools
from pathlib import Path
from typing import Any, TextIO

from ..errors import InputError
from ..files import CaseTable, read_table
from ..laws.base import ContactLaw
from ..sweep import SweepSummary
from ..sweep.chunk import check_header, schema, sweep_chunk
from ..sweep.columns import CYCLE_COLUMNS, REQUIRED_COLUMNS, Edges
from .cluster import Cluster
from .dataset import (
    ParquetSource,
    is_parquet_input,
    open_source,
    output_kind,
    refuse_overwriting_cases,
)
from .study import Reading, run_study

#: Rows a task evaluates by default (the sweep's chunk).
ROWS_PER_TASK = 100_000
#: The input columns read as numbers.
NUMERIC = ("sigma1", "sigma2", "mu")


def sweep_study(
    cases: str | Path,
    law: ContactLaw,
    out: str | Path,
    *,
    mu: float | None = None,
    edge: Edges = "both",
    rows_per_task: int = ROWS_PER_TASK,
    cluster: Cluster | None = None,
    progress: bool | None = None,
    stream: TextIO | None = None,
    client: Any = None,
) -> SweepSummary:
    """Evaluate the slip zone of every cycle in ``cases``; one output row per case.

    Parameters
    ----------
    cases
        A CSV file (as :func:`asymslip.sweep.sweep_file` reads), a Parquet file or a folder of
        Parquet files, with the columns ``P1, Q1, P2, Q2`` and optionally ``sigma1, sigma2,
        mu``; other columns are copied.
    law
        The contact law (it travels to the workers: it must pickle).
    out
        A ``.csv`` or ``.parquet`` file, or a folder (ending in ``/``) for a partitioned
        Parquet dataset of one part per task.  Complete or absent.
    mu, edge
        As for ``sweep_file``.
    rows_per_task
        Input rows one task evaluates (and one part of a folder output holds).
    cluster
        None: this process; else the :class:`~asymslip.batch.cluster.Cluster` to run on.
    progress, stream
        The progress bar (default: on a terminal).

    Returns
    -------
    SweepSummary
        ``written`` is None; ``invalid`` holds (line of a CSV file or row of a dataset,
        message).
    """
    kind = output_kind(out)  # before Path() drops a trailing separator
    cases, out = Path(cases), Path(out)
    if edge not in ("right", "left", "both"):
        raise InputError("edge", "must be 'right', 'left' or 'both'", edge)
    if isinstance(rows_per_task, bool) or not isinstance(rows_per_task, int) or rows_per_task < 1:
        raise InputError("rows_per_task", "must be a whole number >= 1", rows_per_task)
    refuse_overwriting_cases(cases, out, kind)
    source: CaseTable | ParquetSource
    if is_parquet_input(cases):
        source = open_source(cases)
        header, total, comments = list(source.header), source.total, 0
        missing = [name for name in REQUIRED_COLUMNS if name not in header]
        if missing:
            raise InputError(
                "cases",
                f"{cases}: the dataset has no column {', '.join(missing)} "
                f"(found {', '.join(header)})",
            )
    else:
        source = read_table(cases, required=REQUIRED_COLUMNS, numeric=NUMERIC, option="cases")
        header, total, comments = source.header, len(source), len(source.comments)
    check_header(header, cases, mu)
    read_as_numbers = {name for name in (*CYCLE_COLUMNS, "mu") if name in header}
    numbers = read_as_numbers if kind != "csv" else set()
    evaluate = functools.partial(
        sweep_chunk,
        law=law,
        default_mu=None if mu is None else float(mu),
        edge=edge,
        numbers=numbers,
    )
    run = run_study(
        source,
        out,
        kind,
        schema(header, edge, numbers),
        evaluate,
        Reading(NUMERIC, REQUIRED_COLUMNS),
        rows_per_task=rows_per_task,
        cluster=cluster,
        command="sweep",
        progress=progress,
        stream=stream,
        total=total,
        client=client,
    )
    unit = "row" if isinstance(source, ParquetSource) else "line"
    return SweepSummary(total, out, run.seconds, sorted(run.failed), None, comments, unit)
