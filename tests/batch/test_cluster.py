"""Studies on a 2-worker Dask ``LocalCluster`` (processes): the same results as one process,
and a worker that dies in the middle of a batch costs nothing but time (issue 22).  Slow: each
test starts its own cluster."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pyarrow.parquet as pq
import pytest

from asymslip.batch import BatchSettings, Cluster, solve_batch
from asymslip.batch.solving import TIMING_COLUMNS

from .helpers import ExitOnce

pytestmark = pytest.mark.slow

SETTINGS = BatchSettings("hertz", (("R", 1.0), ("E_star", 1.0)), mu=0.3, elements=160, steps=8)
#: Twelve cycles with and without tension, one gross-sliding row and one load path.
CASES = (
    "case,P1,Q1,P2,Q2,sigma2,path\n"
    + "".join(f"c{k},100,0,{100 + 2 * k},{0.6 * 2 * k},{0.004 * (k % 3)},\n" for k in range(1, 13))
    + "sliding,100,0,105,40,,\ntriangle,,,,,,100 -5; 120 0; 100 5\n"
)


def rows_of(path: Path) -> list[dict[str, Any]]:
    files = sorted(path.glob("part-*.parquet")) if path.is_dir() else path
    return [
        {key: value for key, value in row.items() if key not in TIMING_COLUMNS}
        for row in pq.read_table(files).to_pylist()
    ]


@pytest.fixture(scope="module")
def one_process(tmp_path_factory: pytest.TempPathFactory) -> list[dict[str, Any]]:
    folder = tmp_path_factory.mktemp("one_process")
    (folder / "cases.csv").write_text(CASES)
    solve_batch(folder / "cases.csv", folder / "out.parquet", SETTINGS, progress=False)
    return rows_of(folder / "out.parquet")


def test_two_workers_give_the_one_process_results(tmp_path: Path, one_process):
    """Every number the same to the last bit (the same solver on the same case, whatever
    process runs it), every error the same; the file is the one-process file's rows."""
    (tmp_path / "cases.csv").write_text(CASES)
    summary = solve_batch(
        tmp_path / "cases.csv",
        tmp_path / "out.parquet",
        SETTINGS,
        cluster=Cluster(workers=2),
        cases_per_task=3,
        progress=False,
    )
    assert summary.parts == 5 and summary.rows == 28
    assert rows_of(tmp_path / "out.parquet") == one_process
    assert sorted(path.name for path in tmp_path.iterdir()) == ["cases.csv", "out.parquet"]


def test_a_worker_killed_in_the_middle_of_a_batch_still_gives_the_complete_result(
    tmp_path: Path, one_process
):
    """Case c6 ends its worker process the first time it is solved (``os._exit``): the
    scheduler re-runs the task on a fresh worker, and the folder holds every case once."""
    (tmp_path / "cases.csv").write_text(CASES)
    marker = tmp_path / "killed"
    solve_batch(
        tmp_path / "cases.csv",
        str(tmp_path / "results") + "/",
        SETTINGS,
        cluster=Cluster(workers=2),
        cases_per_task=2,
        progress=False,
        solver=ExitOnce(str(marker), 112.0),
    )
    assert marker.exists()  # a worker did die
    assert rows_of(tmp_path / "results") == one_process
    assert [path.name for path in tmp_path.iterdir() if path.name.startswith(".")] == []
