"""``asymslip match`` on the command line: the --json keys as issue 19 lists them, the round trip
through ``asymslip slip-zone``, calibrated prototypes, and --verify."""

from __future__ import annotations

import contextlib
import io
import json
from pathlib import Path

import numpy as np
import pytest

from asymslip.cli import main
from tests.match.cases import BLADE, relative

BLADE_OPTIONS = tuple(
    "--law flat-rounded --flat-half-width 1 --R 10 --E-star 1 --mu 0.3 "
    "--P1 0.5 --Q1 0 --P2 0.52 --Q2 0.04 --sigma2 0.002".split()
)
MATCHED = ("L_I1", "L_I2", "L_II1", "L_II2", "a2_minus_a1", "slip_zone_width")


def run(*argv: str) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        status = main(list(argv))
    return status, out.getvalue(), err.getvalue()


def run_json(*argv: str) -> dict:
    status, out, err = run(*argv, "--json")
    assert status == 0, err
    return json.loads(out)


def test_the_json_has_the_keys_the_issue_lists():
    data = run_json("match", *BLADE_OPTIONS, "--rig", "hertz")
    assert {"rig", "cycle", "edge", "matched", "exact"} <= set(data)
    assert set(data["rig"]) == {"law", "R", "E_star", "mu"}
    assert set(data["cycle"]) == {"P1", "Q1", "sigma1", "P2", "Q2", "sigma2"}
    assert set(data["matched"]) == set(MATCHED)
    for key in MATCHED:
        assert {"prototype", "rig"} <= set(data["matched"][key])
    assert data["edge"] == "right" and data["exact"] is True
    assert "verification" not in data
    flat = run_json("match", *BLADE_OPTIONS, "--rig", "flat-rounded")
    assert set(flat["rig"]) == {"law", "c", "R", "E_star", "mu"}


def test_the_rig_cycle_through_slip_zone_gives_back_the_prototype_edge_to_1e_9():
    data = run_json("match", *BLADE_OPTIONS, "--rig", "hertz", "--edge", "left")
    rig, cycle = data["rig"], data["cycle"]
    options = [f"--{key}" if key != "E_star" else "--E-star" for key in ("R", "E_star")]
    rig_options = [
        item
        for option, key in zip(options, ("R", "E_star"), strict=True)
        for item in (option, repr(rig[key]))
    ]
    cycle_options = [item for key, value in cycle.items() for item in (f"--{key}", repr(value))]
    edge = run_json(
        "slip-zone",
        "--law",
        "hertz",
        *rig_options,
        "--mu",
        repr(rig["mu"]),
        *cycle_options,
        "--edge",
        "left",
    )
    prototype = run_json("slip-zone", *BLADE_OPTIONS, "--edge", "left")
    for key in ("L_I1", "L_I2", "L_II1", "L_II2"):
        assert relative(edge[key], prototype[key]) < 1e-9, key
        assert relative(edge[key], data["matched"][key]["rig"]) < 1e-12, key
    # a2 - a1 from the printed half-widths: a difference, good to about 1e-14 * a1/da here.
    assert relative(edge["a2"] - edge["a1"], prototype["a2"] - prototype["a1"]) < 1e-9


def test_the_text_answer_names_the_rig_the_cycle_and_the_match():
    status, out, err = run("match", *BLADE_OPTIONS, "--rig", "hertz", "--rig-no-tension")
    assert status == 0, err
    assert "Rig: law = hertz" in out and "Match: approximate" in out
    assert "Not matched:" in out and "bulk tension" in out
    assert "sigma1   0" in out


def test_verify_on_the_command_line_reports_the_solver_widths():
    data = run_json("match", *BLADE_OPTIONS, "--rig", "hertz", "--verify", "--elements", "600")
    check = data["verification"]
    assert check["widths_agree"] is True
    assert check["prototype"]["elements"] == 600
    # The rig's elements have the prototype's size.
    assert check["rig"]["element_size"] == pytest.approx(
        check["prototype"]["element_size"], rel=0.02
    )
    # Each solve's largest |q2 - q1| is LT2's peak shear change to the edge expansions' next
    # terms, (a2 - b)/a1 (the solver against the asymptote, both contacts).
    for side in ("prototype", "rig"):
        solved, asymptotic = check["shear_change_peak"][side], data["peak_shear_change"][side]
        assert abs(solved / asymptotic - 1) <= check["expansion_allowance"], side
    stress = check["stress_amplitude"]
    assert sorted(stress) == ["asymptote", "solver"]
    assert stress["asymptote"]["points"] == stress["solver"]["points"] == 24
    # The amplitude's uniform sxx is half the prototype's tension change, 0.002 (by hand).
    assert stress["asymptote"]["uniform_sxx"]["prototype"] == pytest.approx(0.001, rel=1e-12)
    assert stress["solver"]["within_stated_accuracy"] is True


def test_verify_text_shows_the_near_edge_stress_amplitude_of_both_sources():
    status, out, err = run(
        "match", *BLADE_OPTIONS, "--rig", "hertz", "--verify", "--elements", "600"
    )
    assert status == 0, err
    assert "near-edge stress amplitude" in out
    assert "    asymptote largest |component|: prototype" in out
    assert "    solver    largest |component|: prototype" in out
    assert "largest |q2 - q1|: prototype" in out
    assert "uniform sxx of the amplitude (dsigma/2" in out


def test_a_calibrated_prototype_is_taken_as_slip_zone_takes_it(tmp_path: Path):
    x = np.linspace(-4.0, 4.0, 801)
    rows = ["P,x,p"]
    for P in (0.46, 0.48, 0.5, 0.52, 0.54, 0.56):
        rows += [
            f"{P!r},{float(xi)!r},{float(pi)!r}"
            for xi, pi in zip(x, BLADE.pressure(x, P), strict=True)
        ]
    traces = tmp_path / "traces.csv"
    traces.write_text("\n".join(rows) + "\n")
    status, _, err = run("calibrate", str(traces), "--out", str(tmp_path / "cal.json"))
    assert status == 0, err
    calibrated = (
        "--law",
        "calibrated",
        "--calibration",
        str(tmp_path / "cal.json"),
        *"--mu 0.3 --P1 0.5 --Q1 0 --P2 0.52 --Q2 0.04 --sigma2 0.002".split(),
    )
    status, _, err = run("match", *calibrated, "--rig", "hertz")
    assert status == 2 and "--rig-E-star" in err and "is required" in err
    data = run_json("match", *calibrated, "--rig", "hertz", "--rig-E-star", "1")
    exact = run_json("match", *BLADE_OPTIONS, "--rig", "hertz")
    assert data["exact"] is True
    # The calibrated edge is the rounded flat's to the calibration's accuracy.
    assert relative(data["rig"]["R"], exact["rig"]["R"]) < 0.01
    status, _, err = run("match", *calibrated, "--rig", "hertz", "--rig-E-star", "1", "--verify")
    assert status == 2 and "--verify-profile" in err


@pytest.mark.slow
def test_a_calibrated_prototype_is_verified_on_its_tabulated_profile(tmp_path: Path):
    x = np.linspace(-4.0, 4.0, 801)
    rows = ["P,x,p"]
    for P in (0.46, 0.48, 0.5, 0.52, 0.54, 0.56):
        pressure = BLADE.pressure(x, P)
        rows += [f"{P!r},{float(a)!r},{float(b)!r}" for a, b in zip(x, pressure, strict=True)]
    (tmp_path / "traces.csv").write_text("\n".join(rows) + "\n")
    assert (
        run("calibrate", str(tmp_path / "traces.csv"), "--out", str(tmp_path / "cal.json"))[0] == 0
    )
    fine = np.linspace(-4.0, 4.0, 4001)
    gap = BLADE.profile(fine)  # the rounded flat's own gap, as a drawing would give it
    table = "\n".join(f"{float(a)!r},{float(b)!r}" for a, b in zip(fine, gap, strict=True))
    (tmp_path / "profile.csv").write_text("x,h\n" + table + "\n")
    data = run_json(
        "match",
        "--law",
        "calibrated",
        "--calibration",
        str(tmp_path / "cal.json"),
        *"--mu 0.3 --P1 0.5 --Q1 0 --P2 0.52 --Q2 0.04 --sigma2 0.002".split(),
        *"--rig hertz --rig-E-star 1 --verify --verify-E-star 1 --elements 1000".split(),
        "--verify-profile-table",
        str(tmp_path / "profile.csv"),
    )
    check = data["verification"]
    assert check["widths_agree"] is True and check["prototype"]["elements"] == 1000
    assert check["shear_change_difference"] < check["expansion_allowance"]
