"""The sweep over partitions (``asymslip.batch.sweep``): a Parquet dataset in, a folder of
parts out, the same numbers as ``sweep_file`` in one process (issue 22)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pyarrow as pa
import pyarrow.csv
import pyarrow.parquet as pq
import pytest

from asymslip import HertzLaw, slip_zone
from asymslip.batch.sweep import sweep_study
from asymslip.cli import main
from asymslip.errors import InputError
from asymslip.sweep import sweep_file
from asymslip.sweep.columns import output_columns

LAW = HertzLaw(R=1.0, E_star=1.0)


def cases_text(rows: int = 40) -> str:
    """Cycles from P = 100 to 100 + dP with lambda from 0.15 to 0.4 (mu = 0.1 default), some
    with tension, one sliding grossly, one with P2 below P1."""
    lines = ["case,P1,Q1,P2,Q2,sigma2"]
    for k in range(rows):
        dP = 1.0 + k % 7
        lines.append(f"c{k},100,0,{100 + dP},{(0.15 + 0.01 * (k % 26)) * dP},{0.001 * (k % 3)}")
    lines += ["sliding,100,0,105,50,0", "down,100,0,90,1,0"]
    return "\n".join(lines) + "\n"


def result_columns(table: pa.Table) -> dict[str, list[object]]:
    names = [name for name in output_columns([], "both")]
    return {name: table.column(name).to_pylist() for name in names}


@pytest.fixture(scope="module")
def reference(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, pa.Table]:
    """``sweep_file`` in one process, CSV in, Parquet out, chunks of 8 rows."""
    folder = tmp_path_factory.mktemp("reference")
    (folder / "cases.csv").write_text(cases_text())
    sweep_file(folder / "cases.csv", LAW, folder / "out.parquet", mu=0.1, chunk_rows=8)
    return folder, pq.read_table(folder / "out.parquet")


def parquet_folder(folder: Path, text: str) -> Path:
    """The cases as a folder of two Parquet files, the first in row groups of 5 rows."""
    (folder / "cases.csv").write_text(text)
    table = pa.csv.read_csv(folder / "cases.csv")
    (folder / "cases").mkdir()
    pq.write_table(table.slice(0, 23), folder / "cases" / "part-a.parquet", row_group_size=5)
    pq.write_table(table.slice(23), folder / "cases" / "part-b.parquet")
    return folder / "cases"


def test_a_folder_of_parts_holds_sweep_files_numbers_to_the_last_bit(tmp_path: Path, reference):
    _, expected = reference
    (tmp_path / "cases.csv").write_text(cases_text())
    summary = sweep_study(tmp_path / "cases.csv", LAW, f"{tmp_path}/out/", mu=0.1, rows_per_task=8)
    parts = sorted((tmp_path / "out").glob("part-*.parquet"))
    assert len(parts) == 6  # 42 rows in tasks of 8
    assert result_columns(pq.read_table(parts)) == result_columns(expected)
    assert [line for line, _ in summary.invalid] == [42, 43]


def test_a_partitioned_parquet_dataset_in_gives_the_same_rows(tmp_path: Path, reference):
    _, expected = reference
    cases = parquet_folder(tmp_path, cases_text())
    summary = sweep_study(cases, LAW, tmp_path / "out.parquet", mu=0.1, rows_per_task=8)
    back = pq.read_table(tmp_path / "out.parquet")
    assert result_columns(back) == result_columns(expected)
    assert back.column("case").to_pylist() == expected.column("case").to_pylist()
    assert back.column("P2").type == pa.float64()  # the numbers the sweep read, as numbers
    assert [line for line, _ in summary.invalid] == [41, 42]  # rows of the dataset


def test_every_row_is_the_apis_slip_zone(tmp_path: Path):
    cases = parquet_folder(tmp_path, cases_text(12))
    sweep_study(cases, LAW, tmp_path / "out.csv", mu=0.1, rows_per_task=5)
    back = pa.csv.read_csv(tmp_path / "out.csv")
    for row in back.slice(0, 12).to_pylist():
        from asymslip import LoadCycle

        cycle = LoadCycle(row["P1"], row["Q1"], row["P2"], row["Q2"], 0.0, row["sigma2"])
        assert row["b"] == float(slip_zone(LAW, cycle, 0.1).b)


def test_an_empty_required_cell_of_a_dataset_is_its_rows_error(tmp_path: Path):
    table = pa.table({"P1": [100.0, None], "Q1": [0, 0], "P2": [105, 105], "Q2": [1, 1]})
    pq.write_table(table, tmp_path / "cases.parquet")
    summary = sweep_study(tmp_path / "cases.parquet", LAW, tmp_path / "out.parquet", mu=0.1)
    assert summary.invalid == [(2, "P1: missing value")]
    errors = pq.read_table(tmp_path / "out.parquet").column("error").to_pylist()
    assert errors == [None, "P1: missing value"]


def test_numbers_stored_as_text_in_a_dataset_are_refused_naming_the_column(tmp_path: Path):
    table = pa.table({"P1": ["100"], "Q1": [0.0], "P2": [105.0], "Q2": [1.0]})
    pq.write_table(table, tmp_path / "cases.parquet")
    with pytest.raises(InputError, match=r"column P1 holds string, not numbers"):
        sweep_study(tmp_path / "cases.parquet", LAW, tmp_path / "out.parquet", mu=0.1)
    assert sorted(path.name for path in tmp_path.iterdir()) == ["cases.parquet"]


def test_files_of_different_columns_in_one_dataset_are_refused(tmp_path: Path):
    (tmp_path / "cases").mkdir()
    pq.write_table(
        pa.table({"P1": [1.0], "Q1": [0.0], "P2": [2.0], "Q2": [0.0]}),
        tmp_path / "cases" / "a.parquet",
    )
    pq.write_table(
        pa.table({"P1": [1.0], "Q1": [0.0], "P2": [2.0]}), tmp_path / "cases" / "b.parquet"
    )
    with pytest.raises(InputError, match=r"b.parquet: its columns .* differ"):
        sweep_study(tmp_path / "cases", LAW, tmp_path / "out.parquet", mu=0.1)


def test_the_command_line_sends_a_dataset_or_a_folder_output_through_the_partitions(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
):
    cases = parquet_folder(tmp_path, cases_text(10))
    hertz = ["--law", "hertz", "--R", "1", "--E-star", "1", "--mu", "0.1"]
    status = main(["sweep", str(cases), *hertz, "--out", f"{tmp_path}/out/", "--chunk-rows", "4"])
    assert status == 1  # two rows break a rule
    assert len(list((tmp_path / "out").glob("part-*.parquet"))) == 3  # 12 rows, 4 a task
    b = pq.read_table(tmp_path / "out").column("b").to_numpy(zero_copy_only=False)
    assert np.isnan(b[-2:]).all() and np.isfinite(b[:-2]).all()
    assert "  row 11: Q2: " in capsys.readouterr().err  # a dataset's rows, not a file's lines
