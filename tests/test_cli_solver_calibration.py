"""`asymslip solve` and `asymslip calibrate`, and `--law calibrated`, as a user types them."""

from __future__ import annotations

import json

import numpy as np
import pytest

from asymslip import HertzLaw, LoadCycle, slip_zone
from asymslip.cli import main

HERTZ = ["--law", "hertz", "--R", "1", "--E-star", "1"]
FIG5 = ["--mu", "0.1", "--P1", "100", "--Q1", "0", "--P2", "105", "--Q2", "1"]


def run_json(capsys, *arguments):
    assert main([*arguments, "--json"]) == 0
    return json.loads(capsys.readouterr().out)


def test_solve_reports_both_edges_with_bounds_and_every_estimate_in_elements(capsys):
    data = run_json(capsys, "solve", *HERTZ, *FIG5, "--elements", "1000")
    assert data["slip_direction"] == 1 and data["left"]["slip_direction"] == -1
    for edge in (data, data["left"]):
        assert edge["b_error"] > 0
        assert set(edge["asymptotes"]) == {
            "b",
            "b_paper",
            "b_first_order",
            "b_corrective_stick",
            "b_exact",
        }
        # Without tension the exact a(P_K) lies within one bound of the solver.
        assert abs(edge["asymptotes"]["b_exact"]["elements"]) < 1


def test_solve_writes_the_curves_and_the_picture(tmp_path, capsys):
    assert main(["solve", *HERTZ, *FIG5, "--elements", "600", "--out", str(tmp_path)]) == 0
    names = sorted(path.name for path in tmp_path.iterdir())
    assert names == ["energy.csv", "slip.csv", "solver.png", "tractions.csv"]
    assert (tmp_path / "solver.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_solve_takes_a_general_load_path_from_a_csv(tmp_path, capsys):
    path = tmp_path / "path.csv"
    path.write_text("P,Q\n100,0\n105,1\n100,0\n")
    data = run_json(
        capsys, "solve", *HERTZ, "--mu", "0.1", "--path", str(path), "--elements", "600"
    )
    # The same cycle as Fig. 5, so the same stick boundary within the bounds.
    assert (
        abs(data["b"] - slip_zone(HertzLaw(1, 1), LoadCycle(100, 0, 105, 1), 0.1).b_exact)
        <= data["b_error"]
    )


def test_solve_takes_a_typed_profile_with_its_modulus(capsys):
    data = run_json(
        capsys,
        "solve",
        "--profile",
        "x**2/(2*R)",
        "--param",
        "R=1",
        "--E-star",
        "1",
        *FIG5,
        "--elements",
        "600",
    )
    exact = slip_zone(HertzLaw(1, 1), LoadCycle(100, 0, 105, 1), 0.1).b_exact
    assert abs(data["b"] - exact) <= data["b_error"]


@pytest.mark.parametrize(
    "arguments, option",
    [
        (["--law", "table", "--table", "t.csv"], "--table"),
        (["--profile", "x**2/2"], "--E-star"),
        (["--law", "hertz", "--R", "1", "--E-star", "1", "--elements", "3"], "--elements"),
    ],
)
def test_solve_refuses_what_it_cannot_solve_in_one_line(
    arguments, option, capsys, tmp_path, monkeypatch
):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "t.csv").write_text("P,a\n1,1\n2,1.4\n3,1.7\n4,2\n")
    assert main(["solve", *arguments, *FIG5]) == 2
    error = capsys.readouterr().err.strip().splitlines()
    assert len(error) == 1 and error[0].startswith("asymslip: error: ")
    assert option in error[0] or (option == "--table" and "--law" in error[0])


@pytest.fixture(scope="module")
def hertz_traces(tmp_path_factory):
    """Nodal pressures of the Hertz law at six loads, 121 nodes across 1.1 a."""
    law, rows = HertzLaw(1, 1), ["P,x,p"]
    for P in (90, 95, 100, 105, 110, 115):
        a = float(law.half_width(P))
        x = np.linspace(-1.1 * a, 1.1 * a, 121)
        rows += [
            f"{P},{float(u)!r},{float(v)!r}" for u, v in zip(x, law.pressure(x, P), strict=True)
        ]
    path = tmp_path_factory.mktemp("traces") / "traces.csv"
    path.write_text("\n".join(rows) + "\n")
    return path


def test_calibrate_then_slip_zone_with_the_calibrated_law_gives_the_hertz_slip_zone(
    hertz_traces, tmp_path, capsys
):
    saved = tmp_path / "cal.json"
    data = run_json(capsys, "calibrate", str(hertz_traces), "--out", str(saved))
    assert {entry["P"] for entry in data["right"]} == {90, 95, 100, 105, 110, 115}
    calibrated = run_json(
        capsys, "slip-zone", "--law", "calibrated", "--calibration", str(saved), *FIG5
    )
    # (17) with the edges' own multipliers: the Hertz law's (22), within the stated accuracy.
    paper = slip_zone(HertzLaw(1, 1), LoadCycle(100, 0, 105, 1), 0.1).b_paper
    assert abs(calibrated["b"] - paper) <= calibrated["b_accuracy"]
    assert calibrated["b_paper"] is None and calibrated["b_exact"] is None  # not derived here


def test_calibrate_s_table_says_whether_each_fit_s_errors_are_estimates_or_bounds(
    hertz_traces, capsys
):
    """Hertz on 121 nodes: every row (six loads, two edges) an estimate."""
    assert main(["calibrate", str(hertz_traces)]) == 0
    lines = capsys.readouterr().out.splitlines()
    headers = [line for line in lines if "a_error" in line]
    assert len(headers) == 2 and all("errors" in line.split() for line in headers)
    rows = [line.split() for line in lines if line.split()[:1] in (["90"], ["115"])]
    assert len(rows) == 4 and all(row[5] == "estimate" for row in rows)


def test_calibrate_refuses_a_single_load_naming_the_file(tmp_path, capsys):
    traces = tmp_path / "one.csv"
    traces.write_text("P,x,p\n100,-1,0\n100,0,1\n100,1,0\n")
    assert main(["calibrate", str(traces)]) == 2
    error = capsys.readouterr().err.strip().splitlines()
    assert len(error) == 1 and "one.csv" in error[0]


def test_traction_and_slip_with_the_calibrated_law_match_the_hertz_law(
    hertz_traces, tmp_path, capsys
):
    saved = tmp_path / "cal.json"
    assert main(["calibrate", str(hertz_traces), "--out", str(saved)]) == 0
    capsys.readouterr()
    x = ["--x", "11.3", "11.5"]
    law = ["--law", "calibrated", "--calibration", str(saved)]
    calibrated = run_json(capsys, "traction", *law, *FIG5, *x)
    hertz = run_json(capsys, "traction", *HERTZ, *FIG5, *x)
    assert calibrated["q_diff"] == pytest.approx(hertz["q_diff"], rel=1e-3)
    slip = run_json(capsys, "slip", *law, "--E-star", "1", *FIG5, *x)
    assert slip["slip"] == pytest.approx(
        run_json(capsys, "slip", *HERTZ, *FIG5, *x)["slip"], rel=1e-3
    )
