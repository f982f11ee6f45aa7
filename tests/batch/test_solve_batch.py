"""``solve-batch`` in one process: each case is the reference solver's answer for that row,
two rows a case, failures kept in their rows, the output complete or absent (issue 22)."""

from __future__ import annotations

import math
import os
from pathlib import Path
from typing import Any

import pyarrow as pa
import pyarrow.csv
import pyarrow.parquet as pq
import pytest

from asymslip import HertzLaw, LoadCycle
from asymslip.batch import BatchSettings, solve_batch
from asymslip.batch.cases import parse_path
from asymslip.errors import InputError
from asymslip.solver import solve

from .helpers import RaiseAt

HERTZ = BatchSettings("hertz", (("R", 1.0), ("E_star", 1.0)), mu=0.1, elements=200, steps=10)


def hertz_a(P: float, R: float = 1.0, E_star: float = 1.0) -> float:
    """(29): a^2 = 4 P R / (pi E*)."""
    return math.sqrt(4 * P * R / (math.pi * E_star))


def permanent_stick_load(P1: float, Q1: float, P2: float, Q2: float, mu: float) -> float:
    """(33): P_K = (P1 + P2)/2 - (Q2 - Q1)/(2 mu)."""
    return (P1 + P2) / 2 - (Q2 - Q1) / (2 * mu)


def rows_of(path: Path) -> list[dict[str, Any]]:
    return pq.read_table(path).to_pylist()


def write(path: Path, text: str) -> Path:
    path.write_text(text)
    return path


CASES = (
    "case,P1,Q1,P2,Q2,mu,R,path\n"
    "fig5,100,0,105,1,,,\n"  # the paper's Fig. 5 cycle
    "radius2,100,0,105,2,0.2,2,\n"  # its own mu and R
    "triangle,,,,,0.3,,100 -5; 120 0; 100 5\n"  # a load path
    "slides,100,0,105,50,,,\n"  # gross sliding at state 2
    "bad_radius,100,0,105,1,,-1,\n"
)


@pytest.fixture(scope="module")
def batch(tmp_path_factory: pytest.TempPathFactory) -> tuple[Any, list[dict[str, Any]]]:
    folder = tmp_path_factory.mktemp("batch")
    cases = write(folder / "cases.csv", CASES)
    summary = solve_batch(cases, folder / "out.parquet", HERTZ, progress=False)
    return summary, rows_of(folder / "out.parquet")


def test_every_case_gives_two_rows_right_edge_then_left(batch):
    summary, rows = batch
    assert (summary.cases, summary.rows, len(rows)) == (5, 10, 10)
    assert [row["edge"] for row in rows] == ["right", "left"] * 5
    assert [row["case"] for row in rows[::2]] == [
        "fig5",
        "radius2",
        "triangle",
        "slides",
        "bad_radius",
    ]


def test_the_fig5_stick_boundary_is_a_of_P_K_within_the_solvers_bound(batch):
    _, rows = batch
    exact = hertz_a(permanent_stick_load(100, 0, 105, 1, 0.1))  # sqrt(390/pi) = 11.1419
    for row in rows[0:2]:
        assert abs(row["b"] - exact) <= row["b_error"]
        assert row["slip_direction"] == (1 if row["edge"] == "right" else -1)


def test_a_rows_own_mu_and_radius_replace_the_options(batch):
    _, rows = batch
    exact = hertz_a(permanent_stick_load(100, 0, 105, 2, 0.2), R=2.0)
    for row in rows[2:4]:
        assert abs(row["b"] - exact) <= row["b_error"]
        assert row["mu"] == 0.2 and row["R"] == 2.0  # Parquet keeps the numbers as numbers


def test_a_batch_row_is_the_solvers_own_answer_for_that_case(batch):
    _, rows = batch
    direct = solve(HertzLaw(R=2, E_star=1), LoadCycle(100, 0, 105, 2), 0.2, elements=200, steps=10)
    assert [rows[2]["b"], rows[3]["b"]] == [direct.right.b, direct.left.b]
    assert rows[2]["solver_elements"] == 200 and rows[2]["solver_steps_per_segment"] == 10


def test_the_paper_cycle_carries_every_asymptote_and_its_difference_in_elements(batch):
    _, rows = batch
    fig5 = rows[0]
    for name in ("b", "b_paper", "b_first_order", "b_corrective_stick", "b_exact"):
        difference = fig5[f"asymptote_{name}"] - fig5["b"]
        assert fig5[f"asymptote_{name}_difference"] == pytest.approx(difference, abs=1e-12)
        assert fig5[f"asymptote_{name}_elements"] == pytest.approx(
            difference / fig5["solver_element_size"], abs=1e-9
        )
    # a(P_K) from (29) and (33) by hand
    exact = hertz_a(permanent_stick_load(100, 0, 105, 1, 0.1))
    assert fig5["asymptote_b_exact"] == pytest.approx(exact, rel=1e-14)
    assert fig5["asymptote_b_exact_within_error"] == 1.0


def test_a_load_path_row_has_no_asymptotes_and_its_largest_contact_at_the_largest_load(batch):
    _, rows = batch
    for row in rows[4:6]:
        assert row["error"] is None
        assert row["asymptote_b"] is None and row["a1"] is None  # a path has no states 1, 2
        assert abs(row["a_max"] - hertz_a(120)) <= row["solver_element_size"]


def test_a_failed_case_keeps_its_two_rows_with_the_reason_and_the_others_go_on(batch):
    summary, rows = batch
    assert [row["error"] for row in rows[6:8]] == [rows[6]["error"]] * 2
    assert rows[6]["error"].startswith("Q2: ") and "gross sliding" in rows[6]["error"]
    assert rows[8]["error"] == "R: must be > 0 (got -1.0)"
    assert rows[6]["b"] is None
    assert [line for line, _ in summary.failed] == [5, 6]  # file lines, header on line 1


def test_csv_output_holds_the_same_numbers_as_parquet(tmp_path: Path, batch):
    _, rows = batch
    cases = write(tmp_path / "cases.csv", CASES)
    solve_batch(cases, tmp_path / "out.csv", HERTZ, progress=False)
    text = pa.csv.read_csv(tmp_path / "out.csv").to_pylist()
    assert [row["b"] for row in text] == [row["b"] for row in rows]


def test_partitioned_parquet_in_and_out_round_trip(tmp_path: Path, batch):
    """Cases split over two Parquet files in a folder, results as a folder of parts of two
    cases each: the same rows, in order, as one CSV in and one file out."""
    _, rows = batch
    table = pa.csv.read_csv(
        write(tmp_path / "cases.csv", CASES),
        convert_options=pa.csv.ConvertOptions(column_types={"path": pa.string()}),
    )
    (tmp_path / "cases").mkdir()
    pq.write_table(table.slice(0, 3), tmp_path / "cases" / "a.parquet", row_group_size=2)
    pq.write_table(table.slice(3), tmp_path / "cases" / "b.parquet")
    summary = solve_batch(
        tmp_path / "cases", str(tmp_path / "results") + "/", HERTZ, cases_per_task=2, progress=False
    )
    parts = sorted(path.name for path in (tmp_path / "results").iterdir())
    assert parts == [
        "_asymslip.json",
        "part-000000.parquet",
        "part-000001.parquet",
        "part-000002.parquet",
    ]
    back = pq.read_table(sorted((tmp_path / "results").glob("part-*.parquet"))).to_pylist()
    numbers = [name for name in rows[0] if name not in ("solver_seconds",)]
    assert [[row[name] for name in numbers] for row in back] == [
        [row[name] for name in numbers] for row in rows
    ]
    assert [line for line, _ in summary.failed] == [4, 5]  # rows of the dataset
    assert summary.unit == "row"


def test_an_error_in_the_middle_leaves_no_output_and_no_hidden_folder(tmp_path: Path):
    cases = write(tmp_path / "cases.csv", CASES)
    for out in (tmp_path / "out.parquet", str(tmp_path / "results") + "/"):
        with pytest.raises(RuntimeError, match="not the case's fault"):
            solve_batch(cases, out, HERTZ, cases_per_task=1, progress=False, solver=RaiseAt(105.0))
        assert sorted(path.name for path in tmp_path.iterdir()) == ["cases.csv"]


def test_a_folder_this_tool_wrote_is_replaced_whole(tmp_path: Path):
    cases = write(tmp_path / "cases.csv", "P1,Q1,P2,Q2\n100,0,105,1\n100,0,105,1\n")
    out = str(tmp_path / "results") + "/"
    solve_batch(cases, out, HERTZ, cases_per_task=1, progress=False)
    write(tmp_path / "cases.csv", "P1,Q1,P2,Q2\n100,0,105,1\n")
    solve_batch(cases, out, HERTZ, cases_per_task=1, progress=False)
    assert sorted(path.name for path in (tmp_path / "results").iterdir()) == [
        "_asymslip.json",
        "part-000000.parquet",
    ]
    assert [path.name for path in tmp_path.iterdir() if path.name.startswith(".")] == []


@pytest.mark.parametrize(
    "out, rule",
    [
        ("cases.csv", "is also an input"),
        ("mine/", "did not write"),
        ("./", "holds an input"),
        ("mine", "is a folder: end it with /"),
        ("out.txt", "name a .csv or .parquet file"),
    ],
)
def test_an_output_that_would_replace_an_input_or_a_strangers_folder_is_refused(
    tmp_path: Path, out: str, rule: str
):
    cases = write(tmp_path / "cases.csv", "P1,Q1,P2,Q2\n100,0,105,1\n")
    (tmp_path / "mine").mkdir()
    write(tmp_path / "mine" / "notes.txt", "keep me\n")
    with pytest.raises(InputError, match=rule):
        solve_batch(cases, str(tmp_path) + "/" + out, HERTZ, progress=False)
    assert (tmp_path / "mine" / "notes.txt").read_text() == "keep me\n"
    assert cases.read_text() == "P1,Q1,P2,Q2\n100,0,105,1\n"


def test_a_cluster_without_the_dask_extra_is_refused_naming_the_extra(monkeypatch):
    from asymslip.batch import cluster

    monkeypatch.setattr(cluster, "dask_available", lambda: False)
    with pytest.raises(InputError, match=r"workers: .*pip install 'asymslip\[dask\]'"):
        cluster.cluster_from_options(2, None)


@pytest.mark.parametrize(
    "text, rule",
    [
        ("100 -5; 120", "point 2 must be 'P Q"),
        ("100 -5; 120 x", "point 2 holds something not a number"),
        ("100 0", "at least 2 points"),
        ("100 -5; -1 0", "P must be > 0"),
    ],
)
def test_a_load_path_in_a_cell_that_breaks_a_rule_names_the_point(text: str, rule: str):
    with pytest.raises(InputError, match=rule):
        parse_path(text)


def test_a_scheduler_that_cannot_be_reached_is_one_error_naming_it(monkeypatch, tmp_path: Path):
    from asymslip.batch import cluster

    monkeypatch.setattr(cluster, "SCHEDULER_TIMEOUT", "1s")
    cases = write(tmp_path / "cases.csv", "P1,Q1,P2,Q2\n100,0,105,1\n")
    with pytest.raises(InputError, match=r"^scheduler: cannot reach the scheduler at tcp://"):
        solve_batch(
            cases,
            tmp_path / "out.parquet",
            HERTZ,
            cluster=cluster.Cluster(scheduler="tcp://127.0.0.1:9"),
            progress=False,
        )
    assert sorted(path.name for path in tmp_path.iterdir()) == ["cases.csv"]


def test_the_parts_a_killed_study_left_are_removed_by_the_next_and_a_running_ones_kept(
    tmp_path: Path,
):
    from asymslip.files.partials import host_tag, process_is_running

    dead = next(pid for pid in range(4_000_000, 4_100_000) if process_is_running(pid) is False)
    left = tmp_path / f".out.parquet.asymslip-{dead}-{host_tag()}-0badf00d.parts"
    running = tmp_path / f".out.parquet.asymslip-{os.getppid()}-{host_tag()}-0badf00d.parts"
    for folder in (left, running):
        folder.mkdir()
        write(folder / "part-000000.parquet", "half a part")
    cases = write(tmp_path / "cases.csv", "P1,Q1,P2,Q2\n100,0,105,1\n")
    solve_batch(cases, tmp_path / "out.parquet", HERTZ, cluster=None, progress=False)
    assert not left.exists() and running.exists()
