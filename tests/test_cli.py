"""The command line: the API's numbers, --json keys, one-line errors with exit status 2."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

from asymslip import HertzLaw, LoadCycle, slip_zone
from asymslip.cli import main

FIG5 = ["--law", "hertz", "--R", "1", "--E-star", "1", "--mu", "0.1", "--P1", "100", "--Q1", "0",
        "--P2", "105", "--Q2", "1"]  # fmt: skip
KEYS = ["a1", "a2", "lam", "eta", "L_I1", "L_I2", "L_II1", "L_II2", "b", "slip_zone_width",
        "b_first_order", "b_exact", "b_corrective_stick", "validity", "warnings"]  # fmt: skip


def test_slip_zone_json_prints_exactly_the_api_result(capsys):
    assert main(["slip-zone", *FIG5, "--json", "--edge", "right"]) == 0
    printed = json.loads(capsys.readouterr().out)
    expected = slip_zone(HertzLaw(1, 1), LoadCycle(100, 0, 105, 1), 0.1).to_dict()
    assert list(printed) == KEYS
    assert printed == json.loads(json.dumps(expected))
    assert set(printed["validity"]) == {"eq24", "eq25", "eq26", "eq27"}


def test_slip_zone_json_for_both_edges_adds_the_left_edge_under_left(capsys):
    assert main(["slip-zone", *FIG5, "--json"]) == 0
    printed = json.loads(capsys.readouterr().out)
    assert list(printed) == [*KEYS, "left"]
    assert list(printed["left"]) == KEYS
    assert printed["left"]["lam"] == -0.2  # the shear force changes sign seen from the left


def test_slip_zone_table_names_every_quantity(capsys):
    assert main(["slip-zone", *FIG5, "--edge", "right"]) == 0
    out = capsys.readouterr().out
    for key in ("a1", "b_exact", "slip_zone_width", "eq27", "warnings"):
        assert key in out


@pytest.mark.parametrize(
    "change, option",
    [
        (["--mu", "-1"], "--mu"),
        (["--mu", "0"], "--mu"),
        (["--mu", "abc"], "--mu"),
        (["--P2", "99"], "--P2"),
        (["--P1", "-100"], "--P1"),
        (["--law", "cube"], "--law"),
        (["--R", "nan"], "--R"),
        (["--E-star", "-1"], "--E-star"),
    ],
)
def test_bad_input_gives_one_line_naming_the_option_and_exit_status_2(change, option):
    arguments = list(FIG5)
    index = arguments.index(change[0])
    arguments[index + 1] = change[1]
    completed = subprocess.run(
        [sys.executable, "-m", "asymslip", "slip-zone", *arguments],
        capture_output=True, text=True,
    )  # fmt: skip
    assert completed.returncode == 2
    lines = completed.stderr.strip().splitlines()
    assert len(lines) == 1 and option in lines[0], completed.stderr
    assert "Traceback" not in completed.stderr


def test_every_command_has_help():
    for command in ([], ["slip-zone"]):
        completed = subprocess.run([sys.executable, "-m", "asymslip", *command, "--help"],
                                   capture_output=True, text=True)  # fmt: skip
        assert completed.returncode == 0 and "usage:" in completed.stdout
