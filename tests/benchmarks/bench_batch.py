"""Parameter studies on Dask: 2 local workers against one process, and what a task costs.

* a ``LocalCluster`` of 2 worker processes (one thread each): starting and stopping it;
* ``solve-batch`` (:func:`asymslip.batch.solve_batch`) of 200 cycles -- Hertz, R = E* = 1,
  mu = 0.3, P 100 -> 100 + dP (dP 2 to 10), lambda/mu 1.2 to 2.6, a third with bulk tension --
  at N = 500 elements, to a Parquet file, in tasks of 10 cases: on the 2 workers against one
  process;
* the sweep (:func:`asymslip.batch.sweep.sweep_study`) of 10^7 Hertz rows (random cycles as in
  :mod:`.bench_sweep`), a partitioned Parquet dataset in (10 files) and a folder of parts out,
  tasks of 10^6 rows: on the 2 workers against one process;
* the overhead of a task: 1,000 tasks that do nothing, through ``client.map`` and ``gather``;
  and a sweep of 10^6 rows in 1,000 tasks against the same in 10 (each task reads its
  partition and writes its part), per extra task.

Judged by the wall clock (the work is in other processes).  The cluster is started once and
reused by every row after the first, as a study that keeps its cluster would.  With 2 cores
shared by other people, the speed-up says as much about the load as about Dask: the load
average is in the table's machine line.
"""

from __future__ import annotations

import shutil
import tempfile
import time
from pathlib import Path
from typing import Any

import numpy as np

from asymslip import HertzLaw
from asymslip.batch import BatchSettings, Cluster, solve_batch
from asymslip.batch.cluster import connect, run_tasks
from asymslip.batch.sweep import sweep_study

from .timing import Row, duration, times
from .timing import count as number

MU = 0.3
SETTINGS = BatchSettings("hertz", (("R", 1.0), ("E_star", 1.0)), mu=MU, elements=500)


def write_solve_cases(path: Path, cases: int) -> None:
    lines = ["case,P1,Q1,P2,Q2,sigma2"]
    for k in range(cases):
        dP = 2.0 + 8.0 * (k % 9) / 8
        lam = MU * (1.2 + 1.4 * (k % 11) / 10)
        sigma2 = 0.002 * dP if k % 3 == 0 else 0.0
        lines.append(f"c{k},100,0,{100 + dP!r},{lam * dP!r},{sigma2!r}")
    path.write_text("\n".join(lines) + "\n")


def write_sweep_dataset(folder: Path, rows: int, files: int, seed: int = 0) -> None:
    """Random valid Hertz cycles (as :func:`.bench_sweep.write_cases`), as Parquet files."""
    import pyarrow as pa
    import pyarrow.parquet as pq

    folder.mkdir()
    rng = np.random.default_rng(seed)
    per_file = -(-rows // files)
    for index, start in enumerate(range(0, rows, per_file)):
        count = min(per_file, rows - start)
        P1 = rng.uniform(50.0, 150.0, count)
        dP = P1 * rng.uniform(1e-4, 0.1, count)
        lam = rng.uniform(-1.0, 1.0, count)
        zeros = np.zeros(count)
        table = pa.table(
            {"P1": P1, "Q1": zeros, "sigma1": zeros, "P2": P1 + dP, "Q2": lam * dP, "sigma2": zeros}
        )
        pq.write_table(table, folder / f"cases-{index:03d}.parquet")


def _noop(task: int) -> int:
    return task


def _wall(function: Any) -> float:
    start = time.perf_counter()
    function()
    return time.perf_counter() - start


def bench_batch(quick: bool) -> list[Row]:
    solves = 4 if quick else 200
    rows = 20_000 if quick else 10**7
    rows_per_task = rows // 10
    empty_tasks = 20 if quick else 1000
    overhead_rows = 10_000 if quick else 10**6
    settings = BatchSettings("hertz", SETTINGS.parameters, MU, 100 if quick else 500)
    law = HertzLaw(R=1.0, E_star=1.0)
    out: list[Row] = []
    with tempfile.TemporaryDirectory(prefix="asymslip-bench-batch-") as scratch:
        folder = Path(scratch)
        cases = folder / "cases.csv"
        write_solve_cases(cases, solves)
        dataset = folder / "dataset"
        write_sweep_dataset(dataset, rows, 10)
        small = folder / "small"
        write_sweep_dataset(small, overhead_rows, 1, seed=1)

        started = time.perf_counter()
        with connect(Cluster(workers=2)) as client:
            client.wait_for_workers(2)
            startup = time.perf_counter() - started
            run_tasks(_noop, list(range(4)), client=client)  # the workers' imports, once

            # solve-batch: one process, then the cluster (best of one each: minutes of work)
            one = _wall(
                lambda: solve_batch(cases, folder / "one.parquet", settings, progress=False)
            )
            two = _wall(
                lambda: solve_batch(
                    cases, folder / "two.parquet", settings, progress=False, client=client
                )
            )
            out.append(
                Row(
                    f"`solve-batch`, {solves} solves (N = {settings.elements}), to Parquet: "
                    "2 local workers vs one process",
                    duration(two),
                    duration(one),
                    times(two / one),
                    how=f"wall clock, one run each; speed-up {one / two:.2f}x; tasks of 10 "
                    f"cases; one solve {duration(one / solves)} in one process",
                )
            )

            def sweep(target: str, **options: Any) -> float:
                seconds = _wall(
                    lambda: sweep_study(
                        dataset, law, target, mu=MU, rows_per_task=rows_per_task, **options
                    )
                )
                shutil.rmtree(target)
                return seconds

            one = sweep(f"{folder}/sweep-one/")
            two = sweep(f"{folder}/sweep-two/", client=client, progress=False)
            out.append(
                Row(
                    f"sweep, {number(rows)} rows, Parquet dataset in and out: "
                    "2 local workers vs one process",
                    duration(two),
                    duration(one),
                    times(two / one),
                    how=f"wall clock, one run each; speed-up {one / two:.2f}x; 10 input files, "
                    f"tasks of {number(rows_per_task)} rows, one part each; "
                    f"{rows / one:,.0f} rows/s in one process",
                )
            )

            empty = _wall(lambda: run_tasks(_noop, list(range(empty_tasks)), client=client))
            out.append(
                Row(
                    f"overhead per task: {number(empty_tasks)} tasks that do nothing, "
                    "`client.map` + `gather`",
                    duration(empty / empty_tasks),
                    how="wall clock, one run; per task, on the 2-worker cluster",
                )
            )

            def small_sweep(per_task: int) -> float:
                target = f"{folder}/small-{per_task}/"
                seconds = _wall(
                    lambda: sweep_study(
                        small,
                        law,
                        target,
                        mu=MU,
                        rows_per_task=per_task,
                        client=client,
                        progress=False,
                    )
                )
                shutil.rmtree(target)
                return seconds

            many_tasks, few_tasks = (100 if quick else 1000), 10
            many = small_sweep(overhead_rows // many_tasks)
            few = small_sweep(overhead_rows // few_tasks)
            out.append(
                Row(
                    f"overhead per task of a study: sweep of {number(overhead_rows)} rows in "
                    f"{number(many_tasks)} tasks vs {few_tasks}, per extra task",
                    duration((many - few) / (many_tasks - few_tasks)),
                    how=f"wall clock, one run each ({duration(many)} vs {duration(few)}); "
                    "each task reads its partition and writes its part",
                )
            )
        out.insert(
            0,
            Row(
                "a `LocalCluster` of 2 worker processes: start (until both workers are up)",
                duration(startup),
                how="wall clock, one start; stopping it is not counted",
            ),
        )
    return out
