"""Result tables: CSV (both engines, same bytes) and Parquet, atomic, refusing bad targets."""

from __future__ import annotations

import csv

import numpy as np
import pytest

from asymslip.errors import InputError
from asymslip.files import Categorical, Input, TextColumn, arrow, open_table
from asymslip.files.writer import table_format

ENGINES = [
    "numpy",
    pytest.param(
        "pyarrow", marks=pytest.mark.skipif(not arrow.available(), reason="pyarrow not installed")
    ),
]
SCHEMA = [
    ("case", "text"),
    ("b", "float"),
    ("width", "float"),
    ("warnings", "category"),
    ("error", "text"),
]
AWKWARD = ["plain", "a,b", 'say "hi"', "two\nlines", "cr\r", "", " spaced ", "ünïcode"]


def chunk(rows: int = len(AWKWARD)) -> dict:
    cases = (AWKWARD * (rows // len(AWKWARD) + 1))[:rows]
    return {
        "case": cases,
        "b": np.linspace(-1, 1, rows) / 3,
        "width": np.where(np.arange(rows) % 3 == 0, np.nan, 1e-7 * np.arange(rows)),
        "warnings": Categorical(np.arange(rows) % 3 - 1, ["eq24 = 0.2 > 0.1", "a, with comma"]),
        "error": TextColumn.from_strings(
            ["P2: must exceed P1" if i % 4 == 0 else "" for i in range(rows)]
        ),
    }


def read_csv(path) -> list[list[str]]:
    with open(path, newline="", encoding="utf-8") as handle:
        return list(csv.reader(handle))


@pytest.mark.parametrize("engine", ENGINES)
def test_csv_text_fields_read_back_as_written(tmp_path, engine):
    out = tmp_path / "r.csv"
    with open_table(out, SCHEMA, engine=engine) as table:
        table.write(chunk())
    rows = read_csv(out)
    assert rows[0] == [name for name, _ in SCHEMA]
    assert [row[0] for row in rows[1:]] == AWKWARD
    assert [row[3] for row in rows[1:4]] == ["", "eq24 = 0.2 > 0.1", "a, with comma"]
    assert [row[4] for row in rows[1:6]] == ["P2: must exceed P1", "", "", "", "P2: must exceed P1"]


@pytest.mark.parametrize("engine", ENGINES)
def test_csv_text_is_always_quoted_and_a_missing_category_is_an_empty_field(tmp_path, engine):
    out = tmp_path / "r.csv"
    with open_table(out, SCHEMA, engine=engine) as table:
        table.write(chunk())
    lines = out.read_bytes().split(b"\n")
    assert lines[1].startswith(b'"plain",') and lines[1].endswith(b',,"P2: must exceed P1"')
    b = repr(float(np.linspace(-1, 1, len(AWKWARD))[1] / 3)).encode()
    assert lines[2] == b'"a,b",' + b + b',1e-7,"eq24 = 0.2 > 0.1",""'


@pytest.mark.parametrize("engine", ENGINES)
def test_csv_numbers_read_back_identically_and_nan_is_an_empty_field(tmp_path, engine):
    out = tmp_path / "r.csv"
    data = chunk(1000)
    with open_table(out, SCHEMA, engine=engine) as table:
        table.write(data)
    rows = read_csv(out)[1:]
    back = np.array([float(row[1]) for row in rows])
    assert np.array_equal(back, data["b"])
    width = np.array([float(row[2]) if row[2] else np.nan for row in rows])
    assert np.array_equal(width, data["width"], equal_nan=True)
    assert sum(row[2] == "" for row in rows) == 334  # rows 0, 3, 6, ...


@pytest.mark.skipif(not arrow.available(), reason="pyarrow not installed")
@pytest.mark.parametrize("quoted", [True, False])
def test_pyarrow_and_numpy_writers_give_the_same_bytes(tmp_path, quoted):
    """Same bytes, not only the same values: both write pyarrow's number layout and put every
    text field in quotes, whatever it holds."""
    data = chunk(5000)
    if not quoted:
        data["case"] = [f"case{i}" for i in range(5000)]
        data["warnings"] = Categorical(data["warnings"].codes, ["w1", "w2"])
    outputs = []
    for engine in ("numpy", "pyarrow"):
        out = tmp_path / f"{engine}.csv"
        with open_table(out, SCHEMA, engine=engine) as table:
            table.write(data)
            table.write(data)
        outputs.append(out.read_bytes())
    assert outputs[0] == outputs[1]


@pytest.mark.skipif(not arrow.available(), reason="pyarrow not installed")
def test_parquet_has_nulls_for_nan_and_a_dictionary_column(tmp_path):
    import pyarrow as pa
    import pyarrow.parquet as pq

    out = tmp_path / "r.parquet"
    data = chunk()
    with open_table(out, SCHEMA) as table:
        table.write(data)
        table.write(data)
    back = pq.read_table(out)
    assert back.num_rows == 16 and table.written.rows == 16 and table.written.format == "parquet"
    assert back["case"].to_pylist() == AWKWARD * 2
    assert back["width"].null_count == 6
    assert back["b"].to_pylist()[:3] == data["b"][:3].tolist()
    assert pa.types.is_dictionary(back.schema.field("warnings").type)
    assert back["warnings"].to_pylist()[:3] == [None, "eq24 = 0.2 > 0.1", "a, with comma"]


def test_parquet_without_pyarrow_names_the_extra(tmp_path, monkeypatch):
    monkeypatch.setattr(arrow, "available", lambda: False)
    needs = r"^out: Parquet output needs pyarrow: .*asymslip\[parquet\]"
    with pytest.raises(InputError, match=needs):
        with open_table(tmp_path / "r.parquet", SCHEMA):
            pass
    assert not list(tmp_path.iterdir())


@pytest.mark.parametrize("name", ["r.txt", "r", "r.csv.gz", "r.xlsx"])
def test_an_unknown_extension_is_refused_naming_the_option(tmp_path, name):
    with pytest.raises(InputError, match=r"^out: .*the extension must be \.csv or \.parquet"):
        table_format(tmp_path / name)
    with pytest.raises(InputError, match=r"^out: "):
        with open_table(tmp_path / name, SCHEMA):
            pass


@pytest.mark.parametrize("suffix", [".csv", ".parquet"])
def test_an_error_mid_write_leaves_no_file_and_the_target_untouched(tmp_path, suffix):
    if suffix == ".parquet" and not arrow.available():
        pytest.skip("pyarrow not installed")
    out = tmp_path / f"r{suffix}"
    out.write_bytes(b"previous results")
    with pytest.raises(KeyboardInterrupt):
        with open_table(out, SCHEMA) as table:
            table.write(chunk())
            raise KeyboardInterrupt  # Ctrl-C between two chunks
    assert out.read_bytes() == b"previous results"
    assert sorted(path.name for path in tmp_path.iterdir()) == [out.name]  # no partial file


def test_a_bad_chunk_is_refused_and_nothing_is_written(tmp_path):
    out = tmp_path / "r.csv"
    with pytest.raises(ValueError, match="missing \\['error'\\]"):
        with open_table(out, SCHEMA) as table:
            table.write({key: value for key, value in chunk().items() if key != "error"})
    with pytest.raises(ValueError, match="differ in length"):
        with open_table(out, SCHEMA) as table:
            table.write({**chunk(), "b": np.zeros(3)})
    assert not list(tmp_path.iterdir())


def test_a_missing_folder_is_an_input_error_naming_the_option(tmp_path):
    with pytest.raises(InputError, match=r"^results: cannot write .*No such file"):
        with open_table(tmp_path / "no" / "r.csv", SCHEMA, option="results"):
            pass


def test_writing_over_an_input_is_refused(tmp_path):
    cases = tmp_path / "cases.csv"
    cases.write_text("P1\n1\n")
    for target in (cases, tmp_path / "." / "cases.csv"):
        with pytest.raises(InputError, match=r"^out: .* is also an input \(the cases"):
            with open_table(target, SCHEMA, inputs=[Input(cases, "cases", "the cases")]):
                pass
    assert cases.read_text() == "P1\n1\n"


def test_written_says_what_was_written(tmp_path):
    out = tmp_path / "r.csv"
    with open_table(out, SCHEMA) as table:
        table.write(chunk())
        with pytest.raises(RuntimeError):
            table.written  # noqa: B018 - not known before the end
    written = table.written
    assert (written.rows, written.columns, written.bytes) == (8, 5, out.stat().st_size)
    assert str(written).startswith(f"wrote 8 rows x 5 columns to {out} (csv, ")
