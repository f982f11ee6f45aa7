"""``asymslip sweep``: the slip zone of every load cycle in a CSV file."""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

from ..errors import InputError, positive
from ..files.collisions import Input, Output, refuse_overwriting_inputs
from .laws import add_law_options, build_law, law_inputs
from .parser import number, whole_number
from .solve_batch import add_cluster_options


def register(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    sweep = commands.add_parser(
        "sweep",
        help="slip zone of every load cycle in a CSV file",
        description="One cycle per row (columns P1, Q1, P2, Q2; optional sigma1, sigma2, mu; "
        "other columns are copied).  Writes every slip-zone quantity per row; a row that "
        "breaks a rule gets its reason in the error column and the others go on.  Exit "
        "status 1 when some rows were invalid.",
    )
    sweep.add_argument(
        "cases",
        type=Path,
        metavar="CASES.csv|.parquet|FOLDER",
        help="the load cycles: CSV, Parquet, or a folder of Parquet files",
    )
    add_law_options(sweep)
    sweep.add_argument("--mu", type=number, help="coefficient of friction for rows without mu")
    sweep.add_argument(
        "--edge",
        choices=["right", "left", "both"],
        default="both",
        help="which edge (default both; left-edge columns are prefixed left_)",
    )
    sweep.add_argument(
        "--out",
        required=True,
        metavar="RESULTS.csv|.parquet|FOLDER/",
        help="the results: CSV, or Parquet for a .parquet name (needs the "
        "parquet extra), or a folder (ending in /) for a partitioned Parquet dataset; "
        "written beside the target and renamed when complete",
    )
    sweep.add_argument(
        "--chunk-rows",
        dest="chunk_rows",
        type=whole_number,
        default=100_000,
        help="rows evaluated at once: one task, one part of a folder output (default 100000)",
    )
    add_cluster_options(sweep)
    sweep.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from ..batch import cluster_from_options
    from ..batch.cluster import StudyError
    from ..batch.dataset import is_parquet_input
    from ..batch.sweep import sweep_study
    from ..sweep import sweep_file

    refuse_overwriting_inputs(
        [Input(args.cases, "cases", "the cases"), *law_inputs(args)],
        [Output(Path(args.out), "out")],
    )
    if args.chunk_rows < 1:
        raise InputError("chunk_rows", "must be >= 1", args.chunk_rows)
    if args.mu is not None:
        positive("mu", args.mu)  # a bad default is one error, not one per row
    law = build_law(args)
    cluster = cluster_from_options(args.workers, args.scheduler, args.retries)
    folder = args.out.endswith(("/", os.sep))  # a partitioned Parquet dataset
    if cluster is None and not is_parquet_input(args.cases) and not folder:
        summary = sweep_file(
            args.cases, law, args.out, mu=args.mu, edge=args.edge, chunk_rows=args.chunk_rows
        )
    else:  # partitions of a dataset, or a cluster: the same chunks mapped by asymslip.batch
        try:
            summary = sweep_study(
                args.cases,
                law,
                args.out,
                mu=args.mu,
                edge=args.edge,
                rows_per_task=args.chunk_rows,
                cluster=cluster,
            )
        except StudyError as error:  # not the input's fault: one line, the failure status
            print(f"asymslip sweep: error: {error}", file=sys.stderr)
            return 1
    print(summary.report(), file=sys.stderr)
    return 1 if summary.invalid else 0
