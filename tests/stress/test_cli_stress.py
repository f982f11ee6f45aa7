"""``asymslip stress`` and ``asymslip nucleation``: what they print and write.

The numbers are those of the API (tested against exact fields in the other modules); here the
keys the issue specifies, the tables pyLife and FatPy read, and the pictures.
"""

from __future__ import annotations

import contextlib
import csv
import io
import json

import numpy as np
import pytest

from asymslip import HertzLaw, LoadCycle
from asymslip.cli import main
from asymslip.stress.asymptote import edge_amplitude

FIG5 = ("--law", "hertz", "--R", "1", "--E-star", "1", "--mu", "0.1")
FIG5 += ("--P1", "100", "--Q1", "0", "--P2", "105", "--Q2", "1")


def _run(*argv: str) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        status = main(list(argv))
    return status, out.getvalue(), err.getvalue()


def test_asymptote_json_has_points_with_amplitude_and_accuracy():
    status, out, _ = _run(
        "stress",
        *FIG5,
        "--x",
        "11.45",
        "11.55",
        "--depth",
        "0",
        "0.02",
        "--source",
        "asymptote",
        "--json",
    )
    assert status == 0
    data = json.loads(out)
    assert data["source"] == "asymptote" and data["edge"] == "right"
    assert len(data["points"]) == 4
    point = data["points"][1]
    assert set(point) == {"x", "depth", "amplitude", "accuracy", "near_edge"}
    assert set(point["amplitude"]) == {"sxx", "syy", "sxy"}
    expected = edge_amplitude(HertzLaw(1, 1), LoadCycle(100, 0, 105, 1), 0.1, [11.45], [0.02])
    assert (point["x"], point["depth"]) == (11.45, 0.02)
    assert point["amplitude"]["syy"] == pytest.approx(float(expected.amplitude.syy[0]), rel=1e-15)


def test_solver_json_has_both_states_and_their_difference():
    status, out, _ = _run(
        "stress", *FIG5, "--x", "11.5", "--depth", "0.01", "--elements", "500", "--json"
    )
    assert status == 0
    (point,) = json.loads(out)["points"]
    assert {"amplitude", "state1", "state2"} <= set(point)
    for key in ("sxx", "syy", "sxy"):
        assert point["amplitude"][key] == pytest.approx(
            point["state2"][key] - point["state1"][key], abs=1e-14
        )


def test_the_table_has_pylife_columns_and_plane_strain_s33(tmp_path):
    target = tmp_path / "field.csv"
    status, out, _ = _run(
        "stress",
        *FIG5,
        "--x",
        "11.5",
        "11.6",
        "--depth",
        "0",
        "--elements",
        "500",
        "--nu",
        "0.3",
        "--out",
        str(target),
        "--json",
    )
    assert status == 0
    with target.open() as handle:
        rows = list(csv.DictReader(handle))
    assert list(rows[0]) == [
        "point",
        "x",
        "depth",
        "state",
        "S11",
        "S22",
        "S33",
        "S12",
        "S13",
        "S23",
        "accuracy",
        "near_edge",
    ]
    assert [row["state"] for row in rows] == ["1", "1", "2", "2", "amplitude", "amplitude"]
    points = json.loads(out)["points"]
    for row in rows:
        values = points[int(float(row["point"]))]
        label = "amplitude" if row["state"] == "amplitude" else f"state{row['state']}"
        assert float(row["S11"]) == values[label]["sxx"]
        assert float(row["S33"]) == pytest.approx(
            0.3 * (values[label]["sxx"] + values[label]["syy"]), rel=1e-15, abs=1e-15
        )
        assert float(row["S13"]) == float(row["S23"]) == 0.0


def test_the_parquet_table_reads_back_as_the_csv(tmp_path):
    pyarrow = pytest.importorskip("pyarrow.parquet")
    argv = ("stress", *FIG5, "--x", "11.5", "11.6", "--depth", "0", "0.05", "--source", "asymptote")
    assert _run(*argv, "--out", str(tmp_path / "f.csv"))[0] == 0
    assert _run(*argv, "--out", str(tmp_path / "f.parquet"))[0] == 0
    table = pyarrow.read_table(tmp_path / "f.parquet").to_pydict()
    with (tmp_path / "f.csv").open() as handle:
        rows = list(csv.DictReader(handle))
    assert np.array_equal(table["S12"], [float(row["S12"]) for row in rows])
    assert table["state"] == ["amplitude"] * 4


def test_a_folder_gets_the_picture_and_the_table(tmp_path):
    pytest.importorskip("matplotlib")
    status, _, err = _run(
        "stress",
        *FIG5,
        "--x",
        "11.3",
        "11.5",
        "11.7",
        "--depth",
        "0",
        "0.1",
        "--source",
        "asymptote",
        "--out",
        str(tmp_path / "field"),
    )
    assert status == 0
    assert (tmp_path / "field" / "stress.png").stat().st_size > 10_000
    assert (tmp_path / "field" / "stress.csv").is_file()
    assert "wrote" in err


def test_nucleation_json_has_each_edge_criterion_and_method(tmp_path):
    status, out, _ = _run(
        "nucleation",
        *FIG5,
        "--elements",
        "400",
        "--E",
        "1.82",
        "--nu",
        "0.3",
        "--k",
        "0.3",
        "--L",
        "0.05",
        "--criteria",
        "ruiz,findley",
        "--json",
    )
    assert status == 0
    data = json.loads(out)
    assert set(data["right"]) == {"ruiz", "findley"}
    assert set(data["right"]["findley"]) == {"peak", "point", "line"}
    assert set(data["right"]["ruiz"]) == {"frictional_work", "ruiz"}
    peak = data["right"]["findley"]["peak"]
    assert set(peak) == {"value", "x", "depth", "angle", "resolution"}
    assert data["right"]["findley"]["point"]["depth"] == pytest.approx(0.025)
    assert data["material"]["k_findley"] == 0.3


def test_nucleation_warns_when_E_and_nu_do_not_give_the_laws_E_star():
    status, out, _ = _run(
        "nucleation",
        *FIG5,
        "--elements",
        "200",
        "--E",
        "2.5",
        "--nu",
        "0.3",
        "--criteria",
        "ruiz",
        "--json",
    )
    assert status == 0
    assert any("E* = E/(2 (1 - nu^2))" in w for w in json.loads(out)["warnings"])
