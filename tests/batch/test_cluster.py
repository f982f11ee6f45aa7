"""Studies on a 2-worker Dask ``LocalCluster`` (processes): the same results as one process,
and a worker that dies in the middle of a batch costs nothing but time (issue 22).  Slow: each
test starts its own cluster."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pyarrow as pa
import pyarrow.csv
import pyarrow.parquet as pq
import pytest

from asymslip import HertzLaw
from asymslip.batch import BatchSettings, Cluster, solve_batch
from asymslip.batch.solving import TIMING_COLUMNS
from asymslip.batch.sweep import sweep_study
from asymslip.sweep import sweep_file

from .helpers import ExitAlways, ExitOnce, ExitOnceHertz

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


def test_two_workers_give_the_one_process_results(
    tmp_path: Path, one_process, capsys: pytest.CaptureFixture[str]
):
    """Every number the same to the last bit (the same solver on the same case, whatever
    process runs it), every error the same; the file is the one-process file's rows.  The
    progress is distributed's own bar, on standard output."""
    (tmp_path / "cases.csv").write_text(CASES)
    summary = solve_batch(
        tmp_path / "cases.csv",
        tmp_path / "out.parquet",
        SETTINGS,
        cluster=Cluster(workers=2),
        cases_per_task=3,
        progress=True,
    )
    assert "| 100% Completed |" in capsys.readouterr().out
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


def sweep_cases(rows: int) -> str:
    lines = ["case,P1,Q1,P2,Q2,sigma2"]
    for k in range(rows):
        dP = 1.0 + k % 7
        lines.append(
            f"c{k},{100 + k},0,{100 + k + dP},{(0.15 + 0.01 * (k % 26)) * dP},{0.001 * (k % 3)}"
        )
    return "\n".join(lines + ["sliding,100,0,105,50,0"]) + "\n"


def test_a_sweep_on_two_workers_writes_the_one_process_file_byte_for_byte(tmp_path: Path):
    """CSV in, CSV out: the parts the workers write, joined, are the file ``sweep_file`` writes
    in one process with the same chunks."""
    (tmp_path / "cases.csv").write_text(sweep_cases(3000))
    law = HertzLaw(R=1.0, E_star=1.0)
    sweep_file(tmp_path / "cases.csv", law, tmp_path / "one.csv", mu=0.1, chunk_rows=400)
    summary = sweep_study(
        tmp_path / "cases.csv",
        law,
        tmp_path / "two.csv",
        mu=0.1,
        rows_per_task=400,
        cluster=Cluster(workers=2),
        progress=False,
    )
    assert summary.rows == 3001 and summary.invalid[0][0] == 3002
    assert (tmp_path / "two.csv").read_bytes() == (tmp_path / "one.csv").read_bytes()


def test_a_sweep_survives_a_worker_killed_in_the_middle(tmp_path: Path):
    """A Parquet dataset in, a folder out: the chunk holding P1 = 1500 ends its worker the
    first time; the folder is complete and equals the one-process folder."""
    (tmp_path / "cases.csv").write_text(sweep_cases(3000))
    table = pa.csv.read_csv(tmp_path / "cases.csv")
    (tmp_path / "cases").mkdir()
    pq.write_table(table.slice(0, 1700), tmp_path / "cases" / "a.parquet", row_group_size=300)
    pq.write_table(table.slice(1700), tmp_path / "cases" / "b.parquet")
    plain = HertzLaw(R=1.0, E_star=1.0)
    sweep_study(tmp_path / "cases", plain, f"{tmp_path}/one/", mu=0.1, rows_per_task=250)
    marker = tmp_path / "killed"
    law = ExitOnceHertz(R=1.0, E_star=1.0, marker=str(marker), P1=1500.0)
    sweep_study(
        tmp_path / "cases",
        law,
        f"{tmp_path}/two/",
        mu=0.1,
        rows_per_task=250,
        cluster=Cluster(workers=2),
        progress=False,
    )
    assert marker.exists()
    one = pq.read_table(sorted((tmp_path / "one").glob("part-*.parquet")))
    two = pq.read_table(sorted((tmp_path / "two").glob("part-*.parquet")))
    assert two.num_rows == 3001 and two.equals(one)


def test_the_command_line_runs_a_batch_on_a_running_scheduler(tmp_path: Path, one_process):
    """``--scheduler ADDRESS``: a cluster started elsewhere (here a 1-worker LocalCluster on
    this machine's loopback) does the work; the rows are the one-process rows."""
    from distributed import LocalCluster

    from asymslip.cli import main

    (tmp_path / "cases.csv").write_text(CASES)
    with LocalCluster(n_workers=1, threads_per_worker=1, dashboard_address=":0") as cluster:
        status = main(
            [
                "solve-batch",
                str(tmp_path / "cases.csv"),
                *("--law", "hertz", "--R", "1", "--E-star", "1", "--mu", "0.3"),
                *("--elements", "160", "--steps", "8", "--scheduler", cluster.scheduler_address),
                *("--out", str(tmp_path / "out.parquet")),
            ]
        )
    assert status == 1  # the gross-sliding row
    assert rows_of(tmp_path / "out.parquet") == one_process


def test_a_case_that_kills_every_worker_it_meets_stops_the_study_with_nothing_written(
    tmp_path: Path,
):
    """The scheduler gives up on a task after its worker died three times: one error saying
    so, and no output (the parts the other tasks wrote are removed)."""
    from asymslip.batch.cluster import StudyError

    (tmp_path / "cases.csv").write_text(CASES)
    with pytest.raises(StudyError, match=r"ended its worker process 3 times.*nothing was written"):
        solve_batch(
            tmp_path / "cases.csv",
            tmp_path / "out.parquet",
            SETTINGS,
            cluster=Cluster(workers=2),
            cases_per_task=3,
            progress=False,
            solver=ExitAlways(104.0),
        )
    assert sorted(path.name for path in tmp_path.iterdir()) == ["cases.csv"]
