"""The command line: the API's numbers, --json keys, one-line errors with exit status 2.

Commands run in this process through ``main`` (what the console script and ``python -m
asymslip`` call, with argparse's exits caught); one test runs ``python -m asymslip`` itself.
"""

from __future__ import annotations

import json
import subprocess
import sys

import mpmath
import pytest

from asymslip import HertzLaw, LoadCycle, slip_zone
from asymslip.cli import main
from tests.accuracy.references import (
    flat_half_width_mp,
    flat_load_slope_mp,
    normal_multiplier_19,
    power_half_width_mp,
    power_shape_factor,
    stick_boundary_22,
)
from tests.test_fig5 import asymptotic_error, paper_state

FIG5 = [
    "--law",
    "hertz",
    "--R",
    "1",
    "--E-star",
    "1",
    "--mu",
    "0.1",
    "--P1",
    "100",
    "--Q1",
    "0",
    "--P2",
    "105",
    "--Q2",
    "1",
]


def run(arguments, capsys) -> subprocess.CompletedProcess:
    """``asymslip *arguments`` in this process: exit status, stdout and stderr."""
    try:
        status = main(list(arguments))
    except SystemExit as exit:  # argparse: --help, and errors in the options themselves
        status = exit.code
    captured = capsys.readouterr()
    return subprocess.CompletedProcess(arguments, status, captured.out, captured.err)


KEYS = [
    "a1",
    "a2",
    "lam",
    "eta",
    "L_I1",
    "L_I2",
    "L_II1",
    "L_II2",
    "b",
    "slip_zone_width",
    "b_accuracy",
    "b_paper",
    "b_first_order",
    "b_exact",
    "b_corrective_stick",
    "slip_direction",
    "validity",
    "warnings",
]


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
def test_bad_input_gives_one_line_naming_the_option_and_exit_status_2(change, option, capsys):
    arguments = list(FIG5)
    index = arguments.index(change[0])
    arguments[index + 1] = change[1]
    completed = run(["slip-zone", *arguments], capsys)
    assert completed.returncode == 2
    lines = completed.stderr.strip().splitlines()
    assert len(lines) == 1 and option in lines[0], completed.stderr
    assert completed.stdout == ""


def test_python_dash_m_asymslip_exits_with_the_status_and_the_one_line_of_main():
    arguments = list(FIG5)
    arguments[arguments.index("--mu") + 1] = "-1"
    completed = subprocess.run(
        [sys.executable, "-m", "asymslip", "slip-zone", *arguments], capture_output=True, text=True
    )
    assert completed.returncode == 2
    assert completed.stderr.startswith("asymslip: error: --mu: must be > 0")
    assert len(completed.stderr.strip().splitlines()) == 1 and "Traceback" not in completed.stderr


@pytest.mark.parametrize(
    "command",
    [[], ["slip-zone"], ["traction"], ["figure"], ["derive"], ["sweep"]],
    ids=lambda command: " ".join(command) or "asymslip",
)
def test_every_command_has_help(command, capsys):
    completed = run([*command, "--help"], capsys)
    assert completed.returncode == 0 and completed.stdout.startswith("usage: ")
    assert completed.stderr == ""


def test_traction_json_gives_the_paper_fig5_errors_at_the_centre_and_near_the_edge(capsys):
    a2 = float(paper_state()["a2"])  # (29) by hand
    assert main(["traction", *FIG5, "--x", "0", repr(0.9 * a2), "--b", "exact", "--json"]) == 0
    printed = json.loads(capsys.readouterr().out)
    assert list(printed) == [
        "edge",
        "x",
        "q_diff",
        "q_diff_exact",
        "near_edge",
        "near_edge_from",
        "b",
        "stick_boundary",
        "warnings",
    ]
    # Near the edge means x >= 0.9 a2 (the paper's "10 % of the distance in from the contact
    # edge"): not the centre, where the edge asymptote is not meant to hold.  The point 0.9 a2
    # lies on that limit itself (to the last bit of a2): its flag must follow the limit printed.
    assert printed["near_edge_from"] == pytest.approx(0.9 * a2, rel=1e-15)
    assert printed["near_edge"] == [False, printed["x"][1] >= printed["near_edge_from"]]
    errors = [q - e for q, e in zip(printed["q_diff"], printed["q_diff_exact"], strict=True)]
    # Section 3.4: "about 0.01 at the centre" and "about 0.004" at x = 0.9 a2; by (47) by hand
    # and (49) by quadrature, 0.0113733 and 0.0040988 (tests/test_fig5.py).
    assert errors[0] == pytest.approx(asymptotic_error(0.0), rel=1e-9)
    assert errors[1] == pytest.approx(asymptotic_error(0.9 * a2), rel=1e-9)


def test_traction_refuses_a_point_at_or_beyond_the_edge(capsys):
    completed = run(["traction", *FIG5, "--x", "12"], capsys)
    assert completed.returncode == 2
    assert completed.stderr.startswith("asymslip: error: --x: must be < a2")


def test_figure_fig5_writes_the_png_and_the_csv(tmp_path, capsys):
    assert main(["figure", "fig5", "--out", str(tmp_path)]) == 0
    assert (tmp_path / "fig5.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert (tmp_path / "fig5.csv").read_text().count("\n") > 2000


@pytest.mark.parametrize(
    "law_options",
    [
        ["--law", "flat-rounded", "--flat-half-width", "5", "--R", "10", "--E-star", "1"],
        ["--law", "power", "--A", "0.5", "--n", "2.5", "--E-star", "1"],
        ["--law", "power", "--A", "0.5", "--n", "1", "--E-star", "1"],
    ],
    ids=["flat-rounded", "power-2.5", "wedge"],
)
def test_every_built_in_law_reports_the_same_keys_and_an_exact_stick_boundary(law_options, capsys):
    cycle = ["--mu", "0.1", "--P1", "100", "--Q1", "0", "--P2", "105", "--Q2", "1"]
    assert main(["slip-zone", *law_options, *cycle, "--json"]) == 0
    printed = json.loads(capsys.readouterr().out)
    assert list(printed) == [*KEYS, "left"]
    # The law's a(P) and dP/da by mpmath from the published or quadrature law, (19), (22) and
    # a(P_K) with P_K = 97.5 from (33): lam = 0.2, mu = 0.1, dP = 5.
    options = dict(zip(law_options[::2], law_options[1::2], strict=True))
    with mpmath.workdps(30):
        half_width, load_slope = _law_by_hand(options)
        a1, a2, a_K = (half_width(P) for P in (100, 105, 97.5))
        L_I1, L_I2 = (normal_multiplier_19(a, load_slope(a)) for a in (a1, a2))
        b = stick_boundary_22(mpmath.mpf("0.1"), mpmath.mpf("0.2"), 0, a1, a2, L_I1, L_I2)
    for key, expected in (("a1", a1), ("a2", a2), ("b_exact", a_K), ("b_paper", b)):
        assert printed[key] == pytest.approx(float(expected), rel=1e-12), key
    # (22) and a(P_K) agree to first order in dP/P1 = 0.05: they differ at eps^2.
    assert 0 < abs(printed["b_paper"] - printed["b_exact"]) / printed["a1"] < 0.05**2


def _law_by_hand(options):
    """a(P) and dP/da of a built-in law from its defining relation, in mpmath."""
    E_star = mpmath.mpf(options["--E-star"])
    if options["--law"] == "flat-rounded":  # the published law, P(a) in closed form
        c, R = mpmath.mpf(options["--flat-half-width"]), mpmath.mpf(options["--R"])
        return (
            lambda P: flat_half_width_mp(P, c, R, E_star),
            lambda a: flat_load_slope_mp(a, c, R, E_star),
        )
    # P = K E* A a^n, K from quadrature of the plane-contact relation
    A, n = mpmath.mpf(options["--A"]), mpmath.mpf(options["--n"])
    K = power_shape_factor(n)
    return (
        lambda P: power_half_width_mp(P, n, A, E_star, K),
        lambda a: n * K * E_star * A * a ** (n - 1),
    )


@pytest.mark.parametrize(
    "law_options, option",
    [
        (["--law", "flat-rounded", "--R", "10", "--E-star", "1"], "--flat-half-width"),
        (["--law", "power", "--A", "0.5", "--n", "0.5", "--E-star", "1"], "--n"),
        (["--law", "power", "--A", "-1", "--n", "2", "--E-star", "1"], "--A"),
    ],
)
def test_missing_or_invalid_law_parameters_name_their_option(law_options, option, capsys):
    cycle = ["--mu", "0.1", "--P1", "100", "--Q1", "0", "--P2", "105", "--Q2", "1"]
    completed = run(["slip-zone", *law_options, *cycle], capsys)
    assert completed.returncode == 2
    assert completed.stderr.startswith(f"asymslip: error: {option}:"), completed.stderr


def test_version_prints_the_installed_version_and_exits_0():
    """``asymslip --version`` said a command was required (issue 17).  It prints the version of
    pyproject.toml, which is also the installed distribution's."""
    import importlib.metadata
    import pathlib
    import tomllib

    project = tomllib.loads((pathlib.Path(__file__).parents[1] / "pyproject.toml").read_text())
    version = project["project"]["version"]
    assert importlib.metadata.version("asymslip") == version
    done = subprocess.run(
        [sys.executable, "-m", "asymslip", "--version"], capture_output=True, text=True
    )
    assert (done.returncode, done.stdout, done.stderr) == (0, f"asymslip {version}\n", "")
