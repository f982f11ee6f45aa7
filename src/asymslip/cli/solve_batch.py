"""``asymslip solve-batch``: the reference solver on every case of a table, here or on Dask."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from ..errors import InputError, positive
from .laws import add_law_options
from .parser import number, whole_number


def register(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    from ..batch.solve_batch import CASES_PER_TASK
    from ..solver import DEFAULT_ELEMENTS, DEFAULT_STEPS

    batch = commands.add_parser(
        "solve-batch",
        help="the reference solver on every case of a table (one process or a Dask cluster)",
        description="One case per row: the paper's cycle (columns P1, Q1, P2, Q2; optional "
        "sigma1, sigma2) or a load path (column path: points 'P Q [sigma [M]]' separated by "
        "';'), with optional mu, law parameters (R, E_star, c, A, n) and elements, steps "
        "overriding the options; other columns are copied.  Two result rows per case (right "
        "and left edge): what solve --json reports, with every asymptotic estimate for the "
        "paper's cycle.  A case that fails gets its reason in the error column and the others "
        "go on (exit status 1).  In this process by default; --workers N starts a local Dask "
        "cluster, --scheduler ADDRESS uses a running one (the dask extra).",
    )
    batch.add_argument(
        "cases",
        type=Path,
        metavar="CASES.csv|.parquet|FOLDER",
        help="the cases: CSV, Parquet, or a folder of Parquet files",
    )
    add_law_options(batch)
    batch.add_argument("--mu", type=number, help="coefficient of friction for rows without mu")
    batch.add_argument(
        "--elements",
        type=whole_number,
        default=DEFAULT_ELEMENTS,
        help=f"elements of each solve, for rows without elements (default {DEFAULT_ELEMENTS})",
    )
    batch.add_argument(
        "--steps",
        type=whole_number,
        default=DEFAULT_STEPS,
        help=f"load steps per segment, for rows without steps (default {DEFAULT_STEPS})",
    )
    batch.add_argument(
        "--out",
        required=True,
        metavar="RESULTS.parquet|.csv|FOLDER/",
        help="the results: a Parquet or CSV file, or a folder (ending in /) for a "
        "partitioned Parquet dataset; complete or absent",
    )
    add_cluster_options(batch)
    batch.add_argument(
        "--cases-per-task",
        dest="cases_per_task",
        type=whole_number,
        default=CASES_PER_TASK,
        help=f"cases one task solves: one part of a folder output (default {CASES_PER_TASK})",
    )
    batch.set_defaults(run=run)


def add_cluster_options(parser: argparse.ArgumentParser) -> None:
    """``--workers``, ``--scheduler`` and ``--retries``, in one group (solve-batch, sweep)."""
    group = parser.add_argument_group("Dask (the dask extra; default: this process)")
    group.add_argument(
        "--workers", type=whole_number, help="start a local Dask cluster of N worker processes"
    )
    group.add_argument(
        "--scheduler",
        metavar="ADDRESS",
        help="use the running Dask scheduler at ADDRESS (tcp://host:8786); its workers must "
        "see the input and output paths",
    )
    group.add_argument(
        "--retries",
        type=whole_number,
        default=2,
        help="re-runs of a task that raised (a task whose worker died is re-run by the "
        "scheduler); default 2",
    )


def run(args: argparse.Namespace) -> int:
    from ..batch import BatchSettings, cluster_from_options, solve_batch
    from ..batch.cases import LAW_PARAMETERS
    from ..batch.cluster import StudyError

    if args.mu is not None:
        positive("mu", args.mu)
    from ..solver import MIN_ELEMENTS

    if args.elements < MIN_ELEMENTS:
        raise InputError("elements", f"must be at least {MIN_ELEMENTS}", args.elements)
    if args.steps < 1:
        raise InputError("steps", "must be at least 1", args.steps)
    if args.cases_per_task < 1:
        raise InputError("cases_per_task", "must be >= 1", args.cases_per_task)
    if args.law not in LAW_PARAMETERS:
        raise InputError(
            "law",
            f"solve-batch solves a law's profile: choose one of {', '.join(LAW_PARAMETERS)}",
            args.law,
        )
    parameters = tuple(
        (name, float(getattr(args, name)))
        for name in LAW_PARAMETERS[args.law]
        if getattr(args, name) is not None
    )
    settings = BatchSettings(args.law, parameters, args.mu, args.elements, args.steps)
    cluster = cluster_from_options(args.workers, args.scheduler, args.retries)
    try:
        summary = solve_batch(
            args.cases, args.out, settings, cluster=cluster, cases_per_task=args.cases_per_task
        )
    except StudyError as error:  # not the input's fault: one line, and the failure status
        print(f"asymslip solve-batch: error: {error}", file=sys.stderr)
        return 1
    print(summary.report(), file=sys.stderr)
    return 1 if summary.failed else 0
