"""Every bad input is refused in one line; every borderline valid one works (issue 9).

One table of command lines across every command (``slip-zone``, ``traction``, ``slip``,
``figure``, ``derive``, ``sweep``, ``solve``, ``calibrate``).  For each **bad** one: exit
status 2, exactly one line on stderr, naming the option as typed on the command line (``--Q1``,
``--P-of-a``, ``CASES``) and stating the rule it broke, no traceback, and no ``nan``/``inf``
printed as a value anywhere.
For each **borderline valid** one (negative exponents, tiny or huge but finite numbers, a
cycle right at a limit, files as spreadsheets write them): exit status 0 and output whose
numbers are checked against the paper's formulas, transcribed here by hand.

The table runs in-process through :func:`asymslip.cli.main` (pytest runs with ``-W error``, so
a NumPy warning is an error here too); a sample runs as real ``python -m asymslip``
subprocesses under ``PYTHONWARNINGS=error`` for the claims only a process can show (exit
status, traceback, warnings at import), and the missing optional dependencies are simulated in
subprocesses that block their import.
"""

from __future__ import annotations

import contextlib
import csv
import io
import json
import math
import os
import re
import subprocess
import sys
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from pathlib import Path

import pytest

from asymslip import HertzLaw, LoadCycle, cli, slip_zone
from asymslip.cli import main

# --- the paper's formulas, transcribed by hand for the expected values ------------------------


def hertz_a(P: float, R: float = 1.0, E_star: float = 1.0) -> float:
    """(29): a^2 = 4 P R / (pi E*)."""
    return math.sqrt(4 * P * R / (math.pi * E_star))


def hertz_L_I(P: float, R: float = 1.0, E_star: float = 1.0) -> float:
    """(31): L_I = (2P/pi) sqrt(2/a^3)."""
    a = hertz_a(P, R, E_star)
    return 2 * P / math.pi * math.sqrt(2) / a**1.5  # a^3 overflows for P ~ 1e300


def stick_boundary_22(mu: float, lam: float, eta: float, P1: float, P2: float) -> float:
    """(22) for Hertz with R = E* = 1, forward slip."""
    a1, a2 = hertz_a(P1), hertz_a(P2)
    L1, L2 = hertz_L_I(P1), hertz_L_I(P2)
    c2 = (1 - lam / mu - math.pi * a2 / 4 * eta / mu) * L2
    c1 = (1 + lam / mu + math.pi * a1 / 4 * eta / mu) * L1
    return (c2 * a2 + c1 * a1) / (c2 + c1)


def zero_denominator_eta(mu: float, P1: float, P2: float) -> float:
    """eta at which the denominator of (17)/(22) vanishes with lam = 0 (Hertz, R = E* = 1):
    mu (L_I1 + L_I2) + L_II1 - L_II2 = 0 with L_II = (pi eta a/4) L_I (21)."""
    a1, a2 = hertz_a(P1), hertz_a(P2)
    L1, L2 = hertz_L_I(P1), hertz_L_I(P2)
    return mu * (L1 + L2) / (math.pi / 4 * (a2 * L2 - a1 * L1))


# --- the command lines -------------------------------------------------------------------------
HERTZ = ("--law", "hertz", "--R", "1", "--E-star", "1")
FIG5 = {"--mu": "0.1", "--P1": "100", "--Q1": "0", "--P2": "105", "--Q2": "1"}  # lam = 0.2
A2_FIG5 = hertz_a(105.0)
#: a2 exactly as the code computes it (an input: the point right at the edge).
A2_CODE = float(slip_zone(HertzLaw(1, 1), LoadCycle(100, 0, 105, 1), 0.1).a2)


def cycle(**changes: str) -> tuple[str, ...]:
    """The Fig. 5 cycle's options with some changed: ``cycle(Q1="-1e2")`` (keys without --,
    E_star for --E-star); a value of None drops the option."""
    options = dict(FIG5)
    for key, value in changes.items():
        options[f"--{key}"] = value
    return tuple(
        item for key, value in options.items() if value is not None for item in (key, value)
    )


def hertz(**changes: str) -> tuple[str, ...]:
    law = {"--R": "1", "--E-star": "1"}
    for key in ("R", "E_star"):
        if key in changes:
            law["--R" if key == "R" else "--E-star"] = changes.pop(key)
    law_options = ("--law", "hertz", *(i for k, v in law.items() for i in (k, v)))
    return (*law_options, *cycle(**changes))


@dataclass(frozen=True)
class Bad:
    """A command line that must be refused: exit ``status``, one stderr line naming ``option``
    and matching ``rule`` (a regular expression)."""

    id: str
    argv: tuple[str, ...]
    option: str
    rule: str
    status: int = 2


@dataclass(frozen=True)
class Valid:
    """A borderline command line that must work: exit 0; ``check`` gets the parsed output
    (JSON when the command printed JSON, else the text) and the files folder."""

    id: str
    argv: tuple[str, ...]
    check: Callable[..., None] | None = None
    stderr: str = r"^$"  # what stderr may hold (a regular expression over all of it)


@dataclass(frozen=True)
class RowErrors:
    """A sweep with invalid rows: exit 1, each bad row's reason in its error column (naming
    the column and the rule) and on stderr with its 1-based file line; the other rows go on."""

    id: str
    argv: tuple[str, ...]
    out: str
    errors: dict[int, str]  # file line -> regular expression of the error column
    valid_lines: tuple[int, ...] = ()
    extra: dict[str, str] = field(default_factory=dict)


def hertz_traces() -> str:
    """Nodal pressures (48) of the Hertz contact (R = E* = 1) at P = 80, 100, 120, long format
    (P, x, p), 241 nodes over 1.2 a each side."""
    rows = ["P,x,p"]
    for P in (80.0, 100.0, 120.0):
        a = hertz_a(P)
        for k in range(-120, 121):
            x = 1.2 * a * k / 120
            p = 2 * P / (math.pi * a * a) * math.sqrt(max(a * a - x * x, 0.0))
            rows.append(f"{P!r},{x!r},{p!r}")
    return "\n".join(rows) + "\n"


# --- the files the table reads ------------------------------------------------------------------
HERTZ_TABLE = "P,a\n" + "".join(f"{P:g},{hertz_a(P)!r}\n" for P in (60, 80, 100, 120, 140))
FILES = {
    # table laws
    "hertz.csv": HERTZ_TABLE,
    "table_bom.csv": "\ufeff" + HERTZ_TABLE,
    "table_crlf.csv": HERTZ_TABLE.replace("\n", "\r\n"),
    "table_quoted.csv": '"P","a"\n' + HERTZ_TABLE.split("\n", 1)[1],
    "table_commented.csv": "# from the FE model, run 12\n\nsource,P,a\n"
    + "".join(f"fe,{P:g},{hertz_a(P)!r}\n" for P in (60, 80, 100, 120, 140)),
    "table_empty.csv": "",
    "table_comments_only.csv": "# nothing here\n\n",
    "table_no_P.csv": "load,a\n1,1\n2,2\n3,3\n4,4\n",
    "table_no_a.csv": "P,width\n1,1\n2,2\n3,3\n4,4\n",
    # line numbers as an editor shows them: a comment and a blank line come first
    "table_text.csv": "# FE\n\nP,a\n60,8.7\n80,ten\n100,11.3\n120,12.4\n",
    "table_fields.csv": "P,a\n60,8.7\n80,10.1,3\n100,11.3\n120,12.4\n",
    "table_nan.csv": "# FE\nP,a\n60,8.7\n80,10.1\n100,nan\n120,12.4\n",
    "table_negative.csv": "P,a\n60,8.7\n80,-10.1\n100,11.3\n120,12.4\n",
    "table_unsorted.csv": "# FE\n\nP,a\n60,8.7\n100,11.3\n80,10.1\n120,12.4\n",
    "table_decreasing.csv": "P,a\n60,8.7\n80,10.1\n100,9.0\n120,12.4\n",
    "table_three.csv": "P,a\n60,8.7\n80,10.1\n100,11.3\n",
    "table_binary.csv": b"P,a\n60,\xff\xfe\n",
    # sweeps
    "cases.csv": "P1,Q1,P2,Q2\n100,0,105,1\n100,-1e-1,105,5e-1\n",
    "cases_empty.csv": "",
    "cases_comments.csv": "# no header\n\n",
    "cases_no_Q2.csv": "P1,Q1,P2\n100,0,105\n",
    "cases_header_only.csv": "P1,Q1,P2,Q2\n",
    "cases_field_counts.csv": "P1,Q1,P2,Q2\n100,0,105\n1,000,0,105,1\n",
    "cases_binary.csv": b"P1,Q1,P2,Q2\n100,0,105,1\n100,0,\xff05,1\n",
    "cases_clash.csv": "P1,Q1,P2,Q2,b\n100,0,105,1,3\n",
    "cases_wide.csv": "P1,Q1,P2,Q2\n100,-9,1e4,999\n100,0,105,1\n",
    "cases_spreadsheet.csv": "\ufeffP1,Q1,P2,Q2\r\n100,0,105,1\r\n100,-1e-1,105,5e-1\r\n",
    # a mu column: lines 3 and 6 fine (6 takes --mu), 4 zero, 5 text
    "cases_mu.csv": "P1,Q1,P2,Q2,mu\n100,0,105,1,0.1\n100,0,105,1,0\n100,0,105,1,high\n"
    "100,0,105,1,\n",
    # line 3 fine; 4 text; 5 P2 <= P1; 6 gross sliding; 7 nan; 8 empty Q1; 9 fine
    "cases_bad_rows.csv": "# cycles\nP1,Q1,P2,Q2,case\n100,0,105,1,good\n100,0,1o5,1,typo\n"
    "100,0,100,1,flat\n100,900,105,1,sliding\n100,nan,105,1,nan\n100,,105,1,empty\n"
    "1e2,-1e-1,1.05e2,5e-1,good\n",
    # solve-batch: a case, and a table with neither a cycle nor a path
    "batch.csv": "case,P1,Q1,P2,Q2\nfig5,100,0,105,1\n",
    "batch_no_cycle.csv": "case,P1,Q1\na,100,0\n",
    # module laws: one row inside the cubic's range, one beyond its maximum load
    "cases_cubic.csv": "P1,Q1,P2,Q2\n1,0,1.05,0.01\n100,0,105,1\n2,0,2.1,0.02\n",
    "not_a_law.py": "x = 1\n",
    # solve: a load path and profile tables; calibrate: Hertz pressure traces at 3 loads
    "path.csv": "P,Q\n100,0\n105,1\n",
    "profile.csv": "x,h\n" + "".join(f"{x:g},{x * x / 2!r}\n" for x in range(-30, 31)),
    "profile_one_point.csv": "x,h\n0,0\n",
    # inputs named like the files solve --out writes (tractions.csv, slip.csv)
    "tractions.csv": "P,Q\n100,0\n105,1\n",
    "slip.csv": "x,h\n" + "".join(f"{x:g},{x * x / 2!r}\n" for x in range(-30, 31)),
    "traces.csv": hertz_traces(),
    "traces_nan.csv": hertz_traces().replace("\n80.0,0.0,", "\n80.0,nan,", 1),
    "calibration_bad.json": "{not json",
    # issue 17: semicolons, a load given twice, pressures integrating to twice the load
    "traces_semicolons.csv": hertz_traces().replace(",", ";"),
    "traces_twice.csv": hertz_traces() + hertz_traces().split("\n", 1)[1].split("\n100.0,")[0],
    "traces_double.csv": "P,x,p\n"
    + "".join(
        f"{P},{x},{2 * float(p)!r}\n"
        for P, x, p in (row.split(",") for row in hertz_traces().splitlines()[1:])
    ),
    "not_frd.frd": "hello\n",
    "surface.vtu": "<VTKFile/>\n",  # a mesh file: reading it needs meshio (the fe extra)
    # law modules written by hand in the form `asymslip derive` writes (which refuses these)
    "inverse.py": "import numpy\n__asymslip_law__ = {'name': 'inverse', 'params': []}\n"
    "def load(a):\n    return 1 / a\ndef load_slope(a):\n    return -1 / a**2\n"
    "def normal_edge_multiplier(a):\n    return numpy.sqrt(2 / a) / numpy.pi * load_slope(a)\n",
    "linear_down.py": "import numpy\n__asymslip_law__ = {'name': 'linear_down', 'params': ['k']}\n"
    "def load(a, k):\n    return k - a\ndef load_slope(a, k):\n    return -1 + 0 * a\n"
    "def normal_edge_multiplier(a, k):\n"
    "    return numpy.sqrt(2 / a) / numpy.pi * load_slope(a, k)\n",
    "broken_law.py": "def load(a:\n",
    # a law module in form, but its import would run code (line 2)
    "runs_code.py": "__asymslip_law__ = {'name': 'runs', 'params': []}\nprint('ran')\n"
    "def load(a):\n    return a\ndef load_slope(a):\n    return 1 + 0 * a\n"
    "def normal_edge_multiplier(a):\n    return a\n",
    "law.txt": "P(a) = a**2\n",
}


@pytest.fixture(scope="module")
def files(tmp_path_factory: pytest.TempPathFactory) -> Path:
    folder = tmp_path_factory.mktemp("bad_input")
    for name, content in FILES.items():
        path = folder / name
        if isinstance(content, bytes):
            path.write_bytes(content)
        else:
            path.write_bytes(content.encode("utf-8"))
    (folder / "a_file").write_text("not a folder\n")
    os.symlink(folder / "cases.csv", folder / "cases_symlink.csv")
    os.link(folder / "cases.csv", folder / "cases_hardlink.csv")
    (folder / "a_folder").mkdir()
    (folder / "batch_dataset").mkdir()  # a Parquet dataset of solve-batch cases
    import pyarrow
    import pyarrow.parquet

    pyarrow.parquet.write_table(
        pyarrow.table({"P1": [100.0], "Q1": [0.0], "P2": [105.0], "Q2": [1.0]}),
        folder / "batch_dataset" / "part.parquet",
    )
    (folder / "folder.py").mkdir()
    # The law modules of `asymslip derive` that the table uses (their derivation is a case of
    # its own below too).
    status, out, err = run(
        ["calibrate", str(folder / "traces.csv"), "--out", str(folder / "calibration.json")]
    )
    assert status == 0, err
    for name, formula, params in (
        ("cubic", "E_star*a**2 - k*a**3", "E_star k"),
        ("tanh_law", "k*tanh(a)", "k"),
        ("selfpow", "a**a", ""),
        ("tower", "a**a**a", ""),
    ):
        status, out, err = run(
            [
                "derive",
                "--P-of-a",
                formula,
                "--params",
                params,
                "--name",
                name,
                "--out",
                str(folder / f"{name}.py"),
            ]
        )
        assert status == 0, err
    return folder


@pytest.fixture(scope="module", autouse=True)
def one_parser() -> Iterator[None]:
    """``main`` builds the parser of every command on each call (a few ms, most of an
    in-process case); the table builds it once.  Parsing does not change a parser."""
    parser = cli.build_parser()
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(cli, "build_parser", lambda: parser)
        yield


def run(argv: list[str]) -> tuple[int, str, str]:
    """``asymslip ARGV`` in this process: (exit status, stdout, stderr).  An exception that
    escapes ``main`` is a failure of the case, reported with its traceback."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            status = main(argv)
        except SystemExit as exit_:  # argparse's own errors
            status = exit_.code if isinstance(exit_.code, int) else 1
    return status, out.getvalue(), err.getvalue()


def expand(argv: tuple[str, ...], folder: Path) -> list[str]:
    return [item.replace("{d}", str(folder)) for item in argv]


#: A non-finite number printed as a value: nan, inf, -inf, Infinity, NaN (any case).  The
#: phrase that states the finiteness rule itself ("must be finite (not inf or nan)") names
#: them and is taken out first.
NON_FINITE = re.compile(r"(?i)(?<![\w.])[-+]?(nan|inf|infinity)(?![\w])")
RULE_PHRASE = "not inf or nan"


def printed_non_finite(text: str) -> list[str]:
    return NON_FINITE.findall(text.replace(RULE_PHRASE, ""))


def names_option(line: str, option: str) -> bool:
    """The option appears as typed, as a whole word (``--R`` is not ``--R2``)."""
    return re.search(rf"(?<![\w-]){re.escape(option)}(?![\w-])", line) is not None


# --- the checks of valid output -----------------------------------------------------------------
def edge_is_sane(
    result: dict,
    P1: float,
    P2: float,
    Q1: float,
    Q2: float,
    s1: float = 0.0,
    s2: float = 0.0,
    R: float = 1.0,
    E: float = 1.0,
    rel: float = 1e-12,
) -> None:
    """What every edge of every valid Hertz result must satisfy: the contact law (29), the
    slopes (18), a stick boundary inside the contact, every number finite or null."""
    assert result["a1"] == pytest.approx(hertz_a(P1, R, E), rel=rel)
    assert result["a2"] == pytest.approx(hertz_a(P2, R, E), rel=rel)
    assert abs(result["lam"]) == pytest.approx(abs((Q2 - Q1) / (P2 - P1)), rel=1e-12)
    assert result["eta"] == pytest.approx((s2 - s1) / (P2 - P1), rel=1e-12, abs=0)
    for key in ("b", "b_paper", "b_first_order", "b_exact", "b_corrective_stick"):
        value = result[key]
        assert value is None or 0 < value <= result["a2"] * (1 + 1e-15), (key, value)
    assert 0 <= result["slip_zone_width"] <= result["a1"]
    assert result["slip_zone_width"] == pytest.approx(
        result["a1"] - result["b"], rel=1e-9, abs=1e-12 * result["a1"]
    )
    for value in result["validity"].values():
        assert math.isfinite(value) and value >= 0


def slip_zone_check(
    P1: float,
    Q1: float,
    P2: float,
    Q2: float,
    mu: float,
    s1: float = 0.0,
    s2: float = 0.0,
    *,
    slips: bool | None = None,
    R: float = 1.0,
    E: float = 1.0,
    warns: str | None = None,
    rel: float = 1e-12,
) -> Callable[..., None]:
    def check(result: dict, folder: Path) -> None:
        for edge in (result, result["left"]):
            edge_is_sane(edge, P1, P2, Q1, Q2, s1, s2, R, E, rel)
        lam, eta = (Q2 - Q1) / (P2 - P1), (s2 - s1) / (P2 - P1)
        # (21): the right edge slips on loading iff |L_II2| > mu L_I2
        right_slips = abs(lam + math.pi * eta * hertz_a(P2, R, E) / 4) > mu
        if slips is not None:
            assert right_slips is slips
        if not right_slips:  # |lam| <= mu, eta = 0: no slip at the right edge, b = a1 exactly
            assert result["slip_direction"] == 0 and result["b"] == result["a1"]
        elif eta == 0 and R == E == 1 and lam > 0 and result["b_paper"] is not None:
            assert result["b_paper"] == pytest.approx(
                stick_boundary_22(mu, lam, 0.0, P1, P2), rel=1e-9
            )
        if warns is not None:
            assert any(re.search(warns, text) for text in result["warnings"]), result["warnings"]

    return check


def traction_check(points: list[float], near: list[bool]) -> Callable[..., None]:
    def check(result: dict, folder: Path) -> None:
        assert result["x"] == points
        assert result["near_edge"] == near
        assert all(math.isfinite(q) for q in result["q_diff"])

    return check


# --- the table: bad inputs ----------------------------------------------------------------------
FLAT = ("--law", "flat-rounded", "--flat-half-width", "5", "--R", "10", "--E-star", "1")
POWER = ("--law", "power", "--A", "0.5", "--n", "2", "--E-star", "1")
TEXT, FINITE, POSITIVE = r"'abc' is not a number", r"must be finite", r"must be > 0"


def _swap(options: tuple[str, ...], option: str, value: str) -> tuple[str, ...]:
    items = list(options)
    items[items.index(option) + 1] = value
    return tuple(items)


def number_option_cases() -> list[Bad]:
    """Every number option of every command with text, nan, inf, -inf, and 0 and a negative
    number where it must be positive."""
    cases: list[Bad] = []

    def add(
        command: str,
        argv: tuple[str, ...],
        option: str,
        positive: str | None,
        swap: Callable[[str], tuple[str, ...]],
    ) -> None:
        cases.append(Bad(f"{command} {option} text", swap("abc"), option, TEXT))
        for value in ("nan", "inf", "-inf"):
            cases.append(Bad(f"{command} {option} {value}", swap(value), option, FINITE))
        if positive is not None:
            for value in ("0", "-1"):
                cases.append(Bad(f"{command} {option} {value}", swap(value), option, positive))

    for key, positive in (
        ("P1", POSITIVE),
        ("Q1", None),
        ("P2", POSITIVE),
        ("Q2", None),
        ("sigma1", None),
        ("sigma2", None),
        ("mu", POSITIVE),
        ("R", POSITIVE),
        ("E_star", POSITIVE),
    ):
        option = "--E-star" if key == "E_star" else f"--{key}"
        add("slip-zone", (), option, positive, lambda v, key=key: ("slip-zone", *hertz(**{key: v})))
    for option, positive, base in (
        ("--flat-half-width", None, FLAT),
        ("--R", POSITIVE, FLAT),
        ("--A", POSITIVE, POWER),
        ("--n", r"must be >= 1", POWER),
        ("--E-star", POSITIVE, POWER),
    ):
        law = base[1]
        add(
            f"slip-zone --law {law}",
            (),
            option,
            positive,
            lambda v, o=option, b=base: ("slip-zone", *_swap(b, o, v), *cycle()),
        )
    cases.append(
        Bad(
            "slip-zone --flat-half-width -1",
            ("slip-zone", *_swap(FLAT, "--flat-half-width", "-1"), *cycle()),
            "--flat-half-width",
            r"must be >= 0",
        )
    )
    cases.append(
        Bad(
            "slip-zone --n 0.5 (not an incomplete contact)",
            ("slip-zone", *_swap(POWER, "--n", "0.5"), *cycle()),
            "--n",
            r"must be >= 1",
        )
    )
    # traction, slip: the positions, and a cycle option each
    for command in ("traction", "slip"):
        add(command, (), "--x", None, lambda v, c=command: (c, *hertz(), "--x", "0.1", v))
        add(command, (), "--mu", POSITIVE, lambda v, c=command: (c, *hertz(mu=v), "--x", "11"))
    # sweep: the default friction coefficient and the chunk size
    add(
        "sweep",
        (),
        "--mu",
        POSITIVE,
        lambda v: ("sweep", "{d}/cases.csv", *HERTZ, "--mu", v, "--out", "{d}/o.csv"),
    )
    for value, rule in (
        ("abc", r"'abc' is not a whole number"),
        ("1.5", r"not a whole number"),
        ("0", r"must be >= 1"),
        ("-1", r"must be >= 1"),
    ):
        cases.append(
            Bad(
                f"sweep --chunk-rows {value}",
                (
                    "sweep",
                    "{d}/cases.csv",
                    *HERTZ,
                    "--mu",
                    "0.1",
                    "--chunk-rows",
                    value,
                    "--out",
                    "{d}/o.csv",
                ),
                "--chunk-rows",
                rule,
            )
        )
    # derive: the check points and check values
    derive = (
        "derive",
        "--P-of-a",
        "E_star*a**2 - k*a**3",
        "--params",
        "E_star k",
        "--name",
        "cubic",
        "--out",
        "{d}/checked.py",
        "--check",
        "E_star=1",
    )
    add(
        "derive",
        (),
        "--check-a",
        r"must be > 0",
        lambda v: (*derive, "--check", "k=0.1", "--check-a", v),
    )
    for value, rule in (
        ("abc", r"not a number"),
        ("nan", FINITE),
        ("inf", FINITE),
        ("-inf", FINITE),
        ("0", POSITIVE),
        ("-1", POSITIVE),
    ):
        cases.append(
            Bad(
                f"derive --check k={value}",
                (*derive, "--check", f"k={value}", "--check-a", "1"),
                "--check",
                rule,
            )
        )
    # module law: a parameter's value
    module = ("--law", "module", "--module", "{d}/tanh_law.py")
    for value, rule in (
        ("abc", r"not a number"),
        ("nan", FINITE),
        ("inf", FINITE),
        ("-inf", FINITE),
        ("0", POSITIVE),
        ("-1", POSITIVE),
    ):
        cases.append(
            Bad(
                f"module law --param k={value}",
                ("slip-zone", *module, "--param", f"k={value}", *cycle()),
                "--param",
                rule,
            )
        )
    return cases


def physics_cases() -> list[Bad]:
    """The cycle is not a steady partial-slip state the asymptotic solution can answer."""
    P1, P2, mu = 100.0, 105.0, 0.1
    eta_zero = zero_denominator_eta(mu, P1, P2)
    a2 = repr(A2_CODE)
    return [
        Bad("P2 == P1", ("slip-zone", *hertz(P2="100")), "--P2", r"must exceed P1"),
        Bad("P2 < P1", ("slip-zone", *hertz(P2="99")), "--P2", r"must exceed P1.*swap"),
        Bad(
            "gross sliding at state 1",
            ("slip-zone", *hertz(Q1="900")),
            "--Q1",
            r"\|Q1\| = 900 must be < mu P1 = 10: .*gross sliding",
        ),
        Bad(
            "gross sliding at state 2",
            ("slip-zone", *hertz(Q2="11")),
            "--Q2",
            r"\|Q2\| = 11 must be < mu P2 = 10.5: .*gross sliding",
        ),
        Bad(
            "--Q1 -1e2 with mu 0.1 is gross sliding",
            ("slip-zone", *hertz(Q1="-1e2")),
            "--Q1",
            r"\|Q1\| = 100 must be < mu P1 = 10",
        ),
        Bad(
            "--P1 1,5 (decimal comma)",
            ("slip-zone", *hertz(P1="1,5")),
            "--P1",
            r"'1,5' is not a number",
        ),
        Bad(
            "gross sliding right at the limit |Q1| = mu P1",
            ("slip-zone", *hertz(Q1="-10")),
            "--Q1",
            r"must be < mu P1 = 10",
        ),
        Bad(
            "mu = 1e-300 slides at state 2",
            ("slip-zone", *hertz(mu="1e-300")),
            "--Q2",
            r"gross sliding",
        ),
        Bad(
            "--Q1=1e308 --Q2=-1e308 overflows",
            ("slip-zone", *HERTZ, *cycle(Q1=None, Q2=None), "--Q1=1e308", "--Q2=-1e308"),
            "--Q2",
            r"overflows double precision",
        ),
        Bad(
            "--P2 1.7e308 overflows the law",
            ("slip-zone", *hertz(P2="1.7e308")),
            "--P2",
            r"non-finite contact half-width.*overflow",
        ),
        Bad(
            "bulk tension that overflows the denominator of (17)",
            ("slip-zone", *hertz(R="1e300", P1="1e-300", sigma2="1.7e308")),
            "--sigma2",
            r"bulk-tension change sigma2 - sigma1 is too large for mu = 0\.1: .* is not "
            r"positive \(a negative number beyond double precision\)",
        ),
        Bad(
            "--sigma2 1e300 names the tension, not --mu",
            ("slip-zone", *hertz(sigma2="1e300")),
            "--sigma2",
            r"bulk-tension change sigma2 - sigma1 is too large for mu = 0\.1: at the right edge "
            r"the denominator of \(17\).*is not positive \(-1\.569\d*e\+299\)",
        ),
        Bad(
            "--sigma1 -1e300 names the tension (at state 2's option)",
            ("slip-zone", *hertz(sigma1="-1e300")),
            "--sigma2",
            r"bulk-tension change sigma2 - sigma1 is too large",
        ),
        Bad(
            "gross sliding with a subnormal P1 and Q1 (mu P1 rounds to 0)",
            ("slip-zone", *hertz(P1="5e-324", Q1="5e-324", P2="1e-323", Q2="0")),
            "--Q1",
            r"gross sliding",
        ),
        Bad(
            "a subnormal P1 is no gross sliding: its contact growth overflows",
            ("slip-zone", *hertz(P1="5e-324")),
            "--P1",
            r"non-finite eq24 at the right edge",
        ),
        Bad(
            "power law: A = 1e300 overflows",
            ("slip-zone", *_swap(POWER, "--A", "1e300"), *cycle()),
            "--P1",
            r"overflow in double precision",
        ),
        Bad(
            "power law: E* = 1e300 overflows",
            ("slip-zone", *_swap(POWER, "--E-star", "1e300"), *cycle()),
            "--P1",
            r"overflow in double precision",
        ),
        Bad(
            "power law: n = 1.7e308",
            ("slip-zone", *_swap(POWER, "--n", "1.7e308"), *cycle()),
            "--n",
            r"too large: the factor K\(n\).*overflows",
        ),
        Bad(
            "zero denominator of (17) (bulk tension)",
            ("slip-zone", *hertz(Q2="0", sigma2=repr(eta_zero * (P2 - P1)))),
            "--sigma2",
            r"bulk-tension change .* denominator of \(17\).*not positive",
        ),
        Bad(
            "stick boundary beyond the contact (bulk tension)",
            ("slip-zone", *hertz(P2="101", Q2="-9.999", sigma2="-1.25")),
            "--sigma2",
            r"left edge the stick boundary b = 11\.43.* lies outside the contact \(0, a2\]",
        ),
        Bad(
            "traction at the edge x = a2", ("traction", *hertz(), "--x", a2), "--x", r"must be < a2"
        ),
        Bad(
            "traction beyond the edge",
            ("traction", *hertz(), "--x", "0", "11.6"),
            "--x",
            r"must be < a2 = 11\.56.*element 1",
        ),
        Bad(
            "traction beyond the far edge",
            ("traction", *hertz(), "--x", "-11.6"),
            "--x",
            r"must be > -a2",
        ),
        Bad(
            "traction at the left edge x = -a2",
            ("traction", *hertz(), "--edge", "left", "--x", "-" + a2),
            "--x",
            r"must be > -a2",
        ),
        Bad(
            "slip with E* = 5e-324 (1/E* overflows)",
            ("slip", *hertz(E_star="5e-324"), "--x", "0", "11"),
            "--E-star",
            r"is too small: the slip displacement scales as 1/E\*",
        ),
        Bad("slip beyond the edge", ("slip", *hertz(), "--x", "12"), "--x", r"must be < a2"),
        Bad(
            "traction: exact b with bulk tension",
            ("traction", *hertz(sigma2="0.01"), "--x", "11", "--b", "exact"),
            "--b",
            r"does not exist",
        ),
        Bad(
            "slip: exact b with bulk tension",
            ("slip", *hertz(sigma2="0.01"), "--x", "11", "--b", "exact"),
            "--b",
            r"does not exist",
        ),
        Bad("slip --b weird", ("slip", *hertz(), "--x", "11", "--b", "weird"), "--b", "invalid"),
        Bad(
            "traction: an edge that does not slip",
            ("traction", *hertz(Q2="0.4"), "--x", "11"),
            "--Q2",
            r"right edge does not slip",
        ),
        Bad(
            "slip: table law without --E-star",
            ("slip", "--law", "table", "--table", "{d}/hertz.csv", *cycle(), "--x", "11"),
            "--E-star",
            r"required for the slip displacement",
        ),
    ]


def law_cases() -> list[Bad]:
    """Unknown laws, missing parameters, table files and module laws that cannot be used."""
    table = ("slip-zone", "--law", "table", "--table")
    module = ("slip-zone", "--law", "module", "--module")
    cases = [
        Bad(
            "unknown law",
            ("slip-zone", "--law", "cube", *cycle()),
            "--law",
            r"unknown contact law; choose one of hertz",
        ),
        Bad(
            "hertz without --R",
            ("slip-zone", "--law", "hertz", "--E-star", "1", *cycle()),
            "--R",
            r"is required with --law hertz",
        ),
        Bad(
            "hertz without --E-star",
            ("slip-zone", "--law", "hertz", "--R", "1", *cycle()),
            "--E-star",
            r"is required with --law hertz",
        ),
        Bad(
            "flat-rounded without --flat-half-width",
            ("slip-zone", "--law", "flat-rounded", "--R", "1", "--E-star", "1", *cycle()),
            "--flat-half-width",
            r"is required with --law flat-rounded",
        ),
        Bad(
            "power without --n",
            ("slip-zone", "--law", "power", "--A", "1", "--E-star", "1", *cycle()),
            "--n",
            r"is required with --law power",
        ),
        Bad(
            "power without --A",
            ("slip-zone", "--law", "power", "--n", "2", "--E-star", "1", *cycle()),
            "--A",
            r"is required with --law power",
        ),
        Bad(
            "table without --table",
            ("slip-zone", "--law", "table", *cycle()),
            "--table",
            r"is required with --law table",
        ),
        Bad(
            "module without --module",
            ("slip-zone", "--law", "module", *cycle()),
            "--module",
            r"is required with --law module",
        ),
        # table-law files: each error names the file line as an editor shows it (1-based)
        Bad("table file missing", (*table, "{d}/nowhere.csv", *cycle()), "--table", r"cannot read"),
        Bad(
            "table file is a folder", (*table, "{d}/a_folder", *cycle()), "--table", r"cannot read"
        ),
        Bad(
            "table file empty",
            (*table, "{d}/table_empty.csv", *cycle()),
            "--table",
            r"has no header",
        ),
        Bad(
            "table file only comments",
            (*table, "{d}/table_comments_only.csv", *cycle()),
            "--table",
            r"has no header",
        ),
        Bad(
            "table file not UTF-8",
            (*table, "{d}/table_binary.csv", *cycle()),
            "--table",
            r"line 2.*UTF-8|UTF-8.*line 2",
        ),
        Bad(
            "table header without P",
            (*table, "{d}/table_no_P.csv", *cycle()),
            "--table",
            r"line 1: the header has no column P",
        ),
        Bad(
            "table header without a",
            (*table, "{d}/table_no_a.csv", *cycle()),
            "--table",
            r"line 1: the header has no column a",
        ),
        Bad(
            "table value not a number",
            (*table, "{d}/table_text.csv", *cycle()),
            "--table",
            r"line 5: a: 'ten' is not a number",
        ),
        Bad(
            "table row with extra fields",
            (*table, "{d}/table_fields.csv", *cycle()),
            "--table",
            r"line 3: line has 3 fields, the header has 2",
        ),
        Bad(
            "table value nan",
            (*table, "{d}/table_nan.csv", *cycle()),
            "--table",
            r"must be finite.*line 5",
        ),
        Bad(
            "table value negative",
            (*table, "{d}/table_negative.csv", *cycle()),
            "--table",
            r"must be > 0 \(line 3\)",
        ),
        Bad(
            "table not sorted by P",
            (*table, "{d}/table_unsorted.csv", *cycle()),
            "--table",
            r"strictly increasing \(line 6 does not exceed line 5\)",
        ),
        Bad(
            "table law decreasing",
            (*table, "{d}/table_decreasing.csv", *cycle()),
            "--table",
            r"a: table values must be strictly increasing \(line 4 does not exceed line 3\)",
        ),
        Bad(
            "table with three points",
            (*table, "{d}/table_three.csv", *cycle()),
            "--table",
            r"at least 4 points",
        ),
        # module laws
        Bad(
            "module file missing",
            (*module, "{d}/nowhere.py", *cycle()),
            "--module",
            r"no such file",
        ),
        Bad(
            "module file not Python",
            (*module, "{d}/law.txt", *cycle()),
            "--module",
            r"not a Python module",
        ),
        Bad(
            "module file not a law module",
            (*module, "{d}/not_a_law.py", *cycle()),
            "--module",
            r"not an asymslip law module",
        ),
        Bad(
            "module file is a folder",
            (*module, "{d}/a_folder", *cycle()),
            "--module",
            r"is a folder, not a law module file",
        ),
        Bad(
            "module file whose import would run code",
            (*module, "{d}/runs_code.py", *cycle()),
            "--module",
            r"not an asymslip law module: line 2 evaluates an expression.*nothing of it was run",
        ),
        Bad(
            "a**a below its rising branch",
            (*module, "{d}/selfpow.py", *cycle(P1="0.5", P2="0.6", Q2="0.01")),
            "--P1",
            r"no contact half-width of the selfpow law .* loads above 0\.692201 only",
        ),
        Bad(
            "module file with a syntax error",
            (*module, "{d}/broken_law.py", *cycle()),
            "--module",
            r"could not be imported \(SyntaxError",
        ),
        Bad(
            "module law: a parameter missing",
            (*module, "{d}/cubic.py", "--param", "k=0.1", *cycle()),
            "--param",
            r"E_star required",
        ),
        Bad(
            "module law: an unknown parameter",
            (*module, "{d}/tanh_law.py", "--param", "k=1", "--param", "z=1", *cycle()),
            "--param",
            r"z is not a parameter",
        ),
        Bad(
            "module law: --param without =",
            (*module, "{d}/tanh_law.py", "--param", "k", *cycle()),
            "--param",
            r"must be NAME=VALUE",
        ),
        Bad(
            "module law: --param twice",
            (*module, "{d}/tanh_law.py", "--param", "k=1", "--param", "k=2", *cycle()),
            "--param",
            r"k is given twice",
        ),
        # derived laws used beyond what they can carry
        Bad(
            "a module for 1/a written by hand",
            (*module, "{d}/inverse.py", *cycle()),
            "--P1",
            r"no root a > 0 where P increases with a",
        ),
        Bad(
            "a module for k - a written by hand",
            (*module, "{d}/linear_down.py", "--param", "k=200", *cycle()),
            "--P1",
            r"no root a > 0 where P increases with a",
        ),
        Bad(
            "cubic law beyond its maximum load",
            (*module, "{d}/cubic.py", "--param", "E_star=1", "--param", "k=0.1", *cycle()),
            "--P1",
            r"no contact half-width of the cubic law carries this load",
        ),
        Bad(
            "cubic law: only state 2 beyond its maximum",
            (
                *module,
                "{d}/cubic.py",
                "--param",
                "E_star=1",
                "--param",
                "k=0.1",
                *cycle(P1="14", P2="15", Q2="0"),
            ),
            "--P2",
            r"outside the law's range",
        ),
        Bad(
            "tanh law at its bound",
            (*module, "{d}/tanh_law.py", "--param", "k=10", *cycle(P1="9", P2="10", Q2="0")),
            "--P2",
            r"no contact half-width of the tanh_law law carries this load",
        ),
        Bad(
            "tanh law beyond its bound",
            (*module, "{d}/tanh_law.py", "--param", "k=10", *cycle(P1="11", P2="12", Q2="0")),
            "--P1",
            r"outside the law's range",
        ),
    ]
    return cases


def derive_cases() -> list[Bad]:
    def derive(
        formula: str, params: str = "k", *, name: str = "law", out: str = "{d}/derived.py"
    ) -> tuple[str, ...]:
        return ("derive", "--P-of-a", formula, "--params", params, "--name", name, "--out", out)

    huge = "+".join(["a"] * 50_000)  # 100 kB
    return [
        Bad("derive 1/a (decreasing)", derive("1/a"), "--P-of-a", r"decreases with a"),
        Bad("derive k - a (decreasing)", derive("k - a"), "--P-of-a", r"decreases with a"),
        Bad(
            "derive -1/a (nowhere positive)",
            ("derive", "--P-of-a=-1/a", "--name", "law", "--out", "{d}/derived.py"),
            "--P-of-a",
            r"positive",
        ),
        Bad("derive a constant", derive("5*k"), "--P-of-a", r"does not depend on a"),
        Bad("derive a 100 kB expression", derive(huge), "--P-of-a", r"characters"),
        Bad(
            "derive a tower of powers (369 million digits)",
            derive("a*9**9**9"),
            "--P-of-a",
            r"9\*\*\(9\*\*9\) is outside double precision",
        ),
        Bad(
            "derive a number beyond double range",
            derive("1e999*a"),
            "--P-of-a",
            r"1\.00e\+999 is outside double precision",
        ),
        Bad(
            "derive a number below double range",
            derive("1e-400*a + a**2"),
            "--P-of-a",
            r"outside double precision",
        ),
        Bad(
            "derive a division by zero",
            derive("a/0"),
            "--P-of-a",
            r"1/0 is not a finite real number",
        ),
        Bad("derive log(0)", derive("a + log(0)"), "--P-of-a", r"log\(0\) is not a finite real"),
        Bad(
            "derive sqrt(-1)",
            derive("sqrt(-1)*a"),
            "--P-of-a",
            r"sqrt\(-1\) is not a finite real number",
        ),
        Bad("derive deep nesting", derive("(" * 200 + "a" + ")" * 200), "--P-of-a", r"nest"),
        Bad("derive an unknown name", derive("q*a**2"), "--P-of-a", r"\bq\b"),
        Bad("derive code injection", derive("__import__('os').system('true')"), "--P-of-a", r"."),
        Bad("derive attribute access", derive("a.real"), "--P-of-a", r"."),
        Bad("derive a syntax error", derive("a**"), "--P-of-a", r"."),
        Bad("derive an empty formula", derive(""), "--P-of-a", r"empty|no formula|."),
        Bad("derive a refused function", derive("gamma(a)"), "--P-of-a", r"SciPy"),
        Bad("derive Max", derive("Max(a, k)"), "--P-of-a", r"step function"),
        Bad("derive a bad name", derive("k*a**2", name="1law"), "--name", r"Python identifier"),
        Bad(
            "derive a keyword as name",
            derive("k*a**2", name="class"),
            "--name",
            r"Python identifier",
        ),
        Bad(
            "derive --out not .py",
            derive("k*a**2", out="{d}/law.txt"),
            "--out",
            r"must be a \.py file",
        ),
        Bad(
            "derive --out in a missing folder",
            derive("k*a**2", out="{d}/missing/law.py"),
            "--out",
            r"cannot write",
        ),
        Bad(
            "derive --out an existing folder",
            derive("k*a**2", out="{d}/folder.py"),
            "--out",
            r"cannot write",
        ),
        Bad(
            "derive --out under a file",
            derive("k*a**2", out="{d}/a_file/law.py"),
            "--out",
            r"cannot write",
        ),
        Bad(
            "derive --out numpy.py (would shadow NumPy)",
            derive("k*a**2", name="numpy", out="{d}/numpy.py"),
            "--out",
            r"numpy\.py would shadow an installed module .*numpy.*choose another file name",
        ),
        Bad(
            "derive --out json.py (would shadow the standard library)",
            derive("k*a**2", out="{d}/json.py"),
            "--out",
            r"json\.py would shadow a module of Python's standard library",
        ),
        Bad(
            "derive --out asymslip.py (would shadow asymslip)",
            derive("k*a**2", out="{d}/asymslip.py"),
            "--out",
            r"asymslip\.py would shadow asymslip's own package",
        ),
        Bad("derive a parameter named a", derive("k*a**2", "a k"), "--params", r"\ba\b"),
        Bad("derive a parameter twice", derive("k*a**2", "k k"), "--params", r"distinct|twice"),
        Bad(
            "derive a parameter named like a function",
            derive("sqrt*a**2", "sqrt"),
            "--params",
            r"sqrt",
        ),
        Bad(
            "derive --check missing a parameter",
            (
                "derive",
                "--P-of-a",
                "E_star*a**2 - k*a**3",
                "--params",
                "E_star k",
                "--name",
                "cubic",
                "--out",
                "{d}/derived.py",
                "--check",
                "E_star=1",
                "--check-a",
                "1",
            ),
            "--check",
            r"missing k",
        ),
        Bad(
            "derive --check: decreasing at the checked point",
            (
                "derive",
                "--P-of-a",
                "E_star*a**2 - k*a**3",
                "--params",
                "E_star k",
                "--name",
                "cubic",
                "--out",
                "{d}/derived.py",
                "--check",
                "E_star=1",
                "--check",
                "k=1",
                "--check-a",
                "1",
            ),
            "--P-of-a",
            r"dP/da = -1 is not > 0 at a = 1",
        ),
    ]


def sweep_cases() -> list[Bad]:
    def sweep(cases: str, *options: str, out: str = "{d}/out.csv") -> tuple[str, ...]:
        return ("sweep", cases, *HERTZ, "--mu", "0.1", *options, "--out", out)

    return [
        Bad("sweep: CASES missing", sweep("{d}/nowhere.csv"), "CASES", r"cannot read"),
        Bad("sweep: CASES is a folder", sweep("{d}/a_folder"), "CASES", r"cannot read"),
        Bad("sweep: CASES empty", sweep("{d}/cases_empty.csv"), "CASES", r"no header"),
        Bad("sweep: CASES only comments", sweep("{d}/cases_comments.csv"), "CASES", r"no header"),
        Bad(
            "sweep: CASES with a header and no rows",
            sweep("{d}/cases_header_only.csv"),
            "CASES",
            r"has a header but no rows",
        ),
        Bad(
            "sweep: CASES not UTF-8",
            sweep("{d}/cases_binary.csv"),
            "CASES",
            r"line 3: is not UTF-8",
        ),
        Bad(
            "sweep: CASES without Q2",
            sweep("{d}/cases_no_Q2.csv"),
            "CASES",
            r"line 1: the header has no column Q2",
        ),
        Bad(
            "sweep: an input column named like an output",
            sweep("{d}/cases_clash.csv"),
            "CASES",
            r"input column b has the name of an output column",
        ),
        Bad(
            "sweep: --out is the input",
            sweep("{d}/cases.csv", out="{d}/cases.csv"),
            "--out",
            r"is also an input",
        ),
        Bad(
            "sweep: --out is the input by another path",
            sweep("{d}/cases.csv", out="{d}/a_folder/../cases.csv"),
            "--out",
            r"is also an input",
        ),
        Bad(
            "sweep: --out a symbolic link to the input",
            sweep("{d}/cases.csv", out="{d}/cases_symlink.csv"),
            "--out",
            r"cases_symlink\.csv is also an input \(the cases, .*cases\.csv\)",
        ),
        Bad(
            "sweep: --out a hard link of the input",
            sweep("{d}/cases.csv", out="{d}/cases_hardlink.csv"),
            "--out",
            r"cases_hardlink\.csv is also an input \(the cases",
        ),
        Bad(
            "sweep: --out is the table law's file",
            (
                "sweep",
                "{d}/cases.csv",
                "--law",
                "table",
                "--table",
                "{d}/hertz.csv",
                "--mu",
                "0.1",
                "--out",
                "{d}/hertz.csv",
            ),
            "--out",
            r"hertz\.csv is also an input \(the table law",
        ),
        Bad(
            "sweep: --out is the law module",
            (
                "sweep",
                "{d}/cases.csv",
                "--law",
                "module",
                "--module",
                "{d}/tanh_law.py",
                "--param",
                "k=10",
                "--mu",
                "0.1",
                "--out",
                "{d}/./tanh_law.py",
            ),
            "--out",
            r"tanh_law\.py is also an input \(the law module",
        ),
        Bad(
            "sweep: --out is the calibration",
            (
                "sweep",
                "{d}/cases.csv",
                "--law",
                "calibrated",
                "--calibration",
                "{d}/calibration.json",
                "--mu",
                "0.1",
                "--out",
                "{d}/calibration.json",
            ),
            "--out",
            r"calibration\.json is also an input \(the calibration",
        ),
        Bad(
            "sweep: --out in a missing folder",
            sweep("{d}/cases.csv", out="{d}/missing/o.csv"),
            "--out",
            r"cannot write",
        ),
        Bad(
            "sweep: --out under a file",
            sweep("{d}/cases.csv", out="{d}/a_file/o.csv"),
            "--out",
            r"cannot write",
        ),
        Bad(
            "sweep: --out a bad extension",
            sweep("{d}/cases.csv", out="{d}/o.txt"),
            "--out",
            r"extension must be \.csv or \.parquet",
        ),
        Bad(
            "sweep: --out a folder",
            sweep("{d}/cases.csv", out="{d}/a_folder"),
            "--out",
            r"extension|folder|directory",
        ),
        Bad(
            "sweep: no friction coefficient",
            ("sweep", "{d}/cases.csv", *HERTZ, "--out", "{d}/o.csv"),
            "--mu",
            r"is required",
        ),
        Bad(
            "sweep: unknown law",
            ("sweep", "{d}/cases.csv", "--law", "cube", "--mu", "0.1", "--out", "{d}/o.csv"),
            "--law",
            r"unknown contact law",
        ),
        Bad(
            "sweep: hertz without --E-star",
            (
                "sweep",
                "{d}/cases.csv",
                "--law",
                "hertz",
                "--R",
                "1",
                "--mu",
                "0.1",
                "--out",
                "{d}/o.csv",
            ),
            "--E-star",
            r"is required",
        ),
    ]


def command_line_cases() -> list[Bad]:
    """What argparse itself refuses, and the figure command."""
    return [
        Bad("no command", (), "command", r"required"),
        Bad("unknown command", ("slipzone",), "command", r"invalid choice"),
        Bad("unknown option", ("slip-zone", *hertz(), "--Q3", "1"), "--Q3", r"unrecognized"),
        Bad("missing --Q2", ("slip-zone", *hertz(Q2=None)), "--Q2", r"required"),
        Bad("missing --x", ("traction", *hertz()), "--x", r"required"),
        Bad("--edge top", ("slip-zone", *hertz(), "--edge", "top"), "--edge", r"invalid choice"),
        Bad(
            "--b weird",
            ("traction", *hertz(), "--x", "11", "--b", "weird"),
            "--b",
            r"invalid choice",
        ),
        Bad(
            "--P1 without a value",
            ("slip-zone", *HERTZ, *cycle(P1=None), "--P1"),
            "--P1",
            r"expected one argument",
        ),
        Bad(
            "figure: unknown figure",
            ("figure", "fig6", "--out", "{d}/figs"),
            "FIGURE",
            r"invalid choice",
        ),
        Bad(
            "figure: --out is a file",
            ("figure", "fig5", "--out", "{d}/a_file"),
            "--out",
            r"must be a folder",
        ),
        Bad(
            "figure: --out under a file",
            ("figure", "fig5", "--out", "{d}/a_file/figs"),
            "--out",
            r"cannot|folder",
        ),
        Bad(
            "figure: --check a folder without fig5.csv",
            ("figure", "fig5", "--check", "{d}/a_folder"),
            "--check",
            r"fig5\.csv",
        ),
        Bad("figure: neither --out nor --check", ("figure", "fig5"), "--out", r"required"),
        Bad(
            "figure: error map --out under a file",
            ("figure", "error-map", "--out", "{d}/a_file/figs", "--redraw"),
            "--out",
            r"cannot create the folder",
        ),
        Bad(
            "figure: error map --check a folder without error_map.csv",
            ("figure", "error-map", "--check", "{d}/a_folder"),
            "--check",
            r"error_map\.csv",
        ),
        Bad(
            "figure: error map --redraw without the CSV",
            ("figure", "error-map", "--out", "{d}/figs", "--data", "{d}/a_folder", "--redraw"),
            "--data",
            r"no error_map\.csv",
        ),
        Bad(
            "figure: --data with fig5",
            ("figure", "fig5", "--out", "{d}/figs", "--data", "{d}/a_folder"),
            "--data",
            r"error map only",
        ),
    ]


def match_cases() -> list[Bad]:
    """The laboratory match: the rig's options, and the requests no rig can answer."""

    def match(*options: str) -> tuple[str, ...]:
        return ("match", *hertz(), *options)

    near_flat = (
        "--law",
        "flat-rounded",
        "--flat-half-width",
        "10",
        "--R",
        "1",
        "--E-star",
        "1",
        "--mu",
        "0.3",
        "--P1",
        "0.0960507665409116",
        "--Q1",
        "-0.025256618057330878",
        "--P2",
        "0.14251897820901327",
        "--Q2",
        "0.037475467694606364",
    )
    return [
        Bad("match without --rig", match(), "--rig", r"required"),
        Bad("match --rig cylinder", match("--rig", "cylinder"), "--rig", r"invalid choice"),
        Bad(
            "match --rig-E-star -1",
            match("--rig", "hertz", "--rig-E-star", "-1"),
            "--rig-E-star",
            r"must be > 0",
        ),
        Bad("match --rig-mu 0", match("--rig", "hertz", "--rig-mu", "0"), "--rig-mu", r"> 0"),
        Bad(
            "match --rig-mu -inf",
            match("--rig", "hertz", "--rig-mu", "-inf"),
            "--rig-mu",
            FINITE,
        ),
        Bad(
            "match --rig-R -1",
            match("--rig", "hertz", "--rig-R", "-1", "2"),
            "--rig-R",
            r"every value must be > 0",
        ),
        Bad(
            "match --rig-R and --rig-R-range",
            match("--rig", "hertz", "--rig-R", "1", "--rig-R-range", "1", "2"),
            "--rig-R",
            r"either --rig-R or --rig-R-range",
        ),
        Bad(
            "match --rig-R-range upside down",
            match("--rig", "hertz", "--rig-R-range", "2", "1"),
            "--rig-R",
            r"upper end must be >= the lower end",
        ),
        Bad(
            "match: a flat half-width on a Hertz rig",
            match("--rig", "hertz", "--rig-flat-half-width", "1"),
            "--rig-flat-half-width",
            r"needs --rig flat-rounded",
        ),
        Bad(
            "match --rig-max-P 0",
            match("--rig", "hertz", "--rig-max-P", "0"),
            "--rig-max-P",
            r"must be > 0",
        ),
        Bad(
            "match --rig-max-Q nan",
            match("--rig", "hertz", "--rig-max-Q", "nan"),
            "--rig-max-Q",
            r"must be > 0",
        ),
        Bad(
            "match: an edge that does not slip",
            ("match", *hertz(Q2="0.1"), "--rig", "hertz"),
            "--edge",
            r"does not slip in this cycle",
        ),
        Bad(
            "match: the prototype's L_I falls along the path",
            (
                "match",
                "--law",
                "power",
                "--A",
                "0.05",
                "--n",
                "1.2",
                "--E-star",
                "1",
                "--mu",
                "0.3",
                "--P1",
                "1",
                "--Q1",
                "0",
                "--P2",
                "1.05",
                "--Q2",
                "0.02",
                "--rig",
                "hertz",
            ),
            "--law",
            r"L_I does not rise along the path",
        ),
        Bad(
            "match: every rig cycle slides grossly",
            ("match", *near_flat, "--rig", "hertz"),
            "--rig",
            r"every rig cycle .* slides grossly",
        ),
        Bad(
            "match: no rig within the limits comes near",
            match("--rig", "hertz", "--rig-R", "1000", "--rig-max-P", "1e-3"),
            "--rig",
            r"no rig within its limits",
        ),
        Bad(
            "match --verify-profile without --verify-E-star",
            match("--rig", "hertz", "--verify", "--verify-profile", "x**2/2"),
            "--verify-E-star",
            r"is required with a --verify profile",
        ),
        Bad(
            "match --elements 10 --verify",
            match("--rig", "hertz", "--verify", "--elements", "10"),
            "--elements",
            r"must be at least 64",
        ),
    ]


SOLVE = ("--elements", "100", "--steps", "3")


def solve_cases() -> list[Bad]:
    """The reference solver's command: its grid, its profiles, its load path."""

    def solve(*options: str) -> tuple[str, ...]:
        return ("solve", *options, *SOLVE)

    profile = ("--E-star", "1", *cycle())
    return [
        Bad(
            "solve --elements 0",
            ("solve", *hertz(), "--elements", "0"),
            "--elements",
            r"must be at least 64",
        ),
        Bad(
            "solve --elements 1.5",
            ("solve", *hertz(), "--elements", "1.5"),
            "--elements",
            r"'1\.5' is not a whole number",
        ),
        Bad(
            "solve --elements nan",
            ("solve", *hertz(), "--elements", "nan"),
            "--elements",
            r"must be a finite whole number",
        ),
        Bad(
            "solve --steps 0", ("solve", *hertz(), "--steps", "0"), "--steps", r"must be at least 1"
        ),
        Bad("solve --mu -inf", solve(*hertz(mu="-inf")), "--mu", FINITE),
        Bad(
            "solve: gross sliding at state 2",
            solve(*hertz(Q2="11")),
            "--Q2",
            r"\|Q2\| = 11 must be < mu P2 = 10\.5",
        ),
        Bad("solve: P2 < P1", solve(*hertz(P2="99")), "--P2", r"must exceed P1"),
        Bad(
            "solve: no cycle and no path",
            solve(*HERTZ, "--mu", "0.1"),
            "--P1",
            r"needs --P1 --Q1 --P2 --Q2 \(or --path PATH\.csv\)",
        ),
        Bad(
            "solve: a path and a cycle",
            solve(*hertz(), "--path", "{d}/path.csv"),
            "--path",
            r"give either --path or",
        ),
        Bad(
            "solve: a path file missing",
            solve(*HERTZ, "--mu", "0.1", "--path", "{d}/nowhere.csv"),
            "--path",
            r"cannot read",
        ),
        Bad(
            "solve: a law without a profile",
            solve("--law", "table", "--table", "{d}/hertz.csv", *cycle()),
            "--law",
            r"has no profile for the solver",
        ),
        Bad(
            "solve: a falling profile -x**2",
            solve("--profile=-x**2", *profile),
            "--profile",
            r"no finite contact was found",
        ),
        Bad(
            "solve: a profile with an unknown name",
            solve("--profile", "x**2/(2*R)", *profile),
            "--profile",
            r"unknown name R: give each parameter's value with --param",
        ),
        Bad(
            "solve: a profile without --E-star",
            solve("--profile", "x**2/2", *cycle()),
            "--E-star",
            r"is required with --profile",
        ),
        Bad(
            "solve: a profile table missing",
            solve("--profile-table", "{d}/nowhere.csv", *profile),
            "--profile-table",
            r"cannot read",
        ),
        Bad(
            "solve: a profile table of one point",
            solve("--profile-table", "{d}/profile_one_point.csv", *profile),
            "--profile-table",
            r"at least 3 points",
        ),
        Bad(
            "solve: loads of 1e300 overflow the solver",
            solve(*hertz(P1="1e300", P2="1.05e300", Q2="1e298")),
            "--P1",
            r"reference solver overflows double precision",
        ),
        Bad(
            "solve: --path inside --out, named as a file solve writes",
            solve(*HERTZ, "--mu", "0.1", "--path", "{d}/tractions.csv", "--out", "{d}"),
            "--out",
            r"tractions\.csv is also an input \(the load path",
        ),
        Bad(
            "solve: --profile-table inside --out, named as a file solve writes",
            solve("--profile-table", "{d}/slip.csv", *profile, "--out", "{d}/."),
            "--out",
            r"slip\.csv is also an input \(the profile table",
        ),
        Bad(
            "solve --out under a file",
            solve(*hertz(), "--out", "{d}/a_file/solver"),
            "--out",
            r"cannot create",
        ),
        Bad(
            "solve --elements 1000000000: more memory than any machine has",
            ("solve", *hertz(), "--elements", "1000000000"),
            "--elements",
            r"1,000,000,000 elements need about 1\.\d+ TB of memory .* give at most about",
        ),
        Bad(
            "solve --refine: the finest grid (4 N) does not fit",
            ("solve", *hertz(), "--refine", "--elements", "400000000"),
            "--elements",
            r"the finest grid \(1,600,000,000 elements\) needs about",
        ),
    ]


#: fe-model's options but --Q2 (steel, R = 50, the cycle of tests/fe).
FE_MODEL = (
    "--R",
    "50",
    "--E-star",
    "115384.6",
    "--mu",
    "0.5",
    "--P1",
    "1000",
    "--Q1",
    "-100",
    "--P2",
    "1100",
)


def calibrate_cases() -> list[Bad]:
    """Calibration from pressure traces, and the calibrated law it writes."""
    traces = "{d}/traces.csv"
    calibrated = ("slip-zone", "--law", "calibrated", "--calibration")
    return [
        Bad(
            "calibrate: TRACES missing", ("calibrate", "{d}/nowhere.csv"), "TRACES", r"cannot read"
        ),
        Bad(
            "calibrate: TRACES without p",
            ("calibrate", "{d}/path.csv"),
            "TRACES",
            r"line 1: the header has no column x or p",
        ),
        Bad(
            "calibrate: a nan pressure",
            ("calibrate", "{d}/traces_nan.csv"),
            "TRACES",
            r"line \d+: column x: is not a finite number",
        ),
        Bad(
            "calibrate --noise -1",
            ("calibrate", traces, "--noise", "-1"),
            "--noise",
            r"must be a finite number >= 0",
        ),
        Bad(
            "calibrate --noise nan",
            ("calibrate", traces, "--noise", "nan"),
            "--noise",
            r"must be a finite number >= 0",
        ),
        Bad(
            "calibrate --noise inf",
            ("calibrate", traces, "--noise", "inf"),
            "--noise",
            r"must be a finite number >= 0",
        ),
        Bad(
            "calibrate --origin -inf",
            ("calibrate", traces, "--origin", "-inf"),
            "--origin",
            r"must be a finite number",
        ),
        Bad(
            "calibrate --origin outside the contact",
            ("calibrate", traces, "--origin", "1e300"),
            "--origin",
            r"is not inside the contact",
        ),
        Bad(
            "calibrate --loads with a CSV",
            ("calibrate", traces, "--loads", "1", "2"),
            "--loads",
            r"column P gives the loads",
        ),
        Bad(
            "calibrate --out is TRACES",
            ("calibrate", traces, "--out", traces),
            "--out",
            r"is also an input",
        ),
        Bad(
            "calibrate --out is TRACES by another path",
            ("calibrate", traces, "--out", "{d}/a_folder/../traces.csv"),
            "--out",
            r"is also an input \(the traces",
        ),
        Bad(
            "calibrate --out in a missing folder",
            ("calibrate", traces, "--out", "{d}/missing/calibration.json"),
            "--out",
            r"cannot write",
        ),
        Bad(
            "calibrate: semicolons between fields",
            ("calibrate", "{d}/traces_semicolons.csv"),
            "TRACES",
            r"the fields are separated by ';'",
        ),
        Bad(
            "calibrate: a load given twice",
            ("calibrate", "{d}/traces_twice.csv"),
            "TRACES",
            r"P = 80 is given twice",
        ),
        Bad(
            "calibrate: pressures integrating to twice the load",
            ("calibrate", "{d}/traces_double.csv"),
            "TRACES",
            r"the pressures integrate to 2(\.0+)? times the load",
        ),
        Bad(
            "calibrate --field on a CSV",
            ("calibrate", traces, "--field", "CPRESS"),
            "--field",
            r"is for mesh files",
        ),
        Bad(
            "calibrate: an .frd that is not one",
            ("calibrate", "{d}/not_frd.frd"),
            "TRACES",
            r"not a CalculiX .frd file",
        ),
        Bad(
            "fe-model: gross sliding",
            ("fe-model", *FE_MODEL, "--Q2", "600", "--out", "{d}/fe"),
            "--Q2",
            r"gross sliding at state 2",
        ),
        Bad(
            "fe-model --nu 0.5",
            ("fe-model", *FE_MODEL, "--Q2", "150", "--nu", "0.5", "--out", "{d}/fe"),
            "--nu",
            r"must be in \[0, 0.5\)",
        ),
        Bad(
            "fe-model --elements-per-half-width 4",
            (
                "fe-model",
                *FE_MODEL,
                "--Q2",
                "150",
                "--elements-per-half-width",
                "4",
                "--out",
                "{d}/fe",
            ),
            "--elements-per-half-width",
            r"must be an integer >= 8",
        ),
        Bad(
            "fe-model: a contact not small beside R",
            ("fe-model", *FE_MODEL, "--Q2", "150", "--R", "0.5", "--out", "{d}/fe"),
            "--R",
            r"is not small beside",
        ),
        Bad(
            "fe-model --out is a file",
            ("fe-model", *FE_MODEL, "--Q2", "150", "--out", "{d}/a_file"),
            "--out",
            r"is not a folder",
        ),
        Bad(
            "calibrated law without --calibration",
            ("slip-zone", "--law", "calibrated", *cycle()),
            "--calibration",
            r"is required",
        ),
        Bad(
            "calibrated law: file missing",
            (*calibrated, "{d}/nowhere.json", *cycle()),
            "--calibration",
            r"cannot read",
        ),
        Bad(
            "calibrated law: not JSON",
            (*calibrated, "{d}/calibration_bad.json", *cycle()),
            "--calibration",
            r"line 1: not valid JSON",
        ),
        Bad(
            "calibrated law: a negative load",
            (*calibrated, "{d}/calibration.json", *cycle(P1="-5")),
            "--P1",
            POSITIVE,
        ),
    ]


def stress_cases() -> list[Bad]:
    """The stress field and the crack-nucleation parameters (issue 18)."""
    near = ("--x", "11.5", "--depth", "0")
    asymptote = ("stress", *hertz(), *near, "--source", "asymptote")
    nucleation = ("nucleation", *hertz(), "--elements", "100", "--E", "1.82", "--nu", "0.3")
    return [
        Bad(
            "stress --depth -1",
            ("stress", *hertz(), "--x", "11.5", "--depth", "-1", "--source", "asymptote"),
            "--depth",
            r"must be >= 0",
        ),
        Bad(
            "stress --depth nan",
            ("stress", *hertz(), "--x", "11.5", "--depth", "nan"),
            "--depth",
            FINITE,
        ),
        Bad("stress --x text", ("stress", *hertz(), "--x", "abc", "--depth", "0"), "--x", TEXT),
        Bad("stress --depth missing", ("stress", *hertz(), "--x", "11.5"), "--depth", r"required"),
        Bad(
            "stress: the asymptote at the centre",
            ("stress", *hertz(), "--x", "0", "--depth", "0", "--source", "asymptote"),
            "--x",
            r"must lie within 0\.5 a1",
        ),
        Bad(
            "stress: --elements with the asymptote",
            (*asymptote, "--elements", "100"),
            "--elements",
            r"applies to --source solver only",
        ),
        Bad("stress --nu 0.5", (*asymptote, "--nu", "0.5"), "--nu", r"0 < nu < 0\.5"),
        Bad(
            "stress --out with another extension",
            (*asymptote, "--out", "{d}/field.txt"),
            "--out",
            r"must end in \.csv or \.parquet",
        ),
        Bad(
            "stress --source bogus",
            ("stress", *hertz(), *near, "--source", "fem"),
            "--source",
            r"invalid choice",
        ),
        Bad(
            "stress: a table law has no profile for the solver",
            ("stress", "--law", "table", "--table", "{d}/hertz.csv", *cycle(), *near),
            "--law",
            r"has no profile for the solver",
        ),
        Bad(
            "stress: gross sliding",
            ("stress", *hertz(Q2="11"), *near, "--elements", "100"),
            "--Q2",
            r"must be < mu P2",
        ),
        Bad("nucleation --nu 0.5", _swap(nucleation, "--nu", "0.5"), "--nu", r"0 < nu < 0\.5"),
        Bad("nucleation --E 0", _swap(nucleation, "--E", "0"), "--E", r"Young's modulus > 0"),
        Bad("nucleation --E text", _swap(nucleation, "--E", "abc"), "--E", TEXT),
        Bad("nucleation --L -1", (*nucleation, "--L", "-1"), "--L", r"must be finite and > 0"),
        Bad(
            "nucleation: findley without k",
            (*nucleation, "--criteria", "findley"),
            "--criteria",
            r"findley needs its constant k",
        ),
        Bad(
            "nucleation: fs without sigma-y",
            (*nucleation, "--criteria", "fs", "--k", "0.5"),
            "--criteria",
            r"fs \(Fatemi-Socie\) needs",
        ),
        Bad(
            "nucleation: an unknown criterion",
            (*nucleation, "--criteria", "swt,miner"),
            "--criteria",
            r"unknown criterion 'miner'",
        ),
        Bad(
            "nucleation --elements 10",
            _swap(nucleation, "--elements", "10"),
            "--elements",
            r"must be at least 64",
        ),
        Bad(
            "nucleation --out a file",
            (*nucleation, "--criteria", "swt", "--out", "{d}/hertz.csv"),
            "--out",
            r"not a folder",
        ),
    ]


def solve_batch_cases() -> list[Bad]:
    def batch(*options: str, cases: str = "{d}/batch.csv", out: str = "{d}/o.parquet") -> tuple:
        return ("solve-batch", cases, *HERTZ, "--mu", "0.1", *options, "--out", out)

    return [
        Bad("solve-batch: CASES missing", batch(cases="{d}/nowhere.csv"), "CASES", "cannot read"),
        Bad(
            "solve-batch: CASES an empty folder",
            batch(cases="{d}/a_folder"),
            "CASES",
            r"cannot read .*no \.parquet file",
        ),
        Bad(
            "solve-batch: CASES with neither a cycle nor a path",
            batch(cases="{d}/batch_no_cycle.csv"),
            "CASES",
            r"no column P2, Q2 and no path column",
        ),
        Bad(
            "solve-batch: a law without a profile",
            (
                "solve-batch",
                "{d}/batch.csv",
                "--law",
                "table",
                "--table",
                "{d}/table.csv",
                "--mu",
                "0.1",
                "--out",
                "{d}/o.parquet",
            ),
            "--law",
            r"solves a law's profile",
        ),
        Bad(
            "solve-batch: no radius",
            ("solve-batch", "{d}/batch.csv", "--E-star", "1", "--mu", "0.1", "--out", "{d}/o.csv"),
            "--R",
            r"is required with --law hertz",
        ),
        Bad(
            "solve-batch: no friction coefficient",
            ("solve-batch", "{d}/batch.csv", *HERTZ, "--out", "{d}/o.parquet"),
            "--mu",
            r"is required",
        ),
        Bad("solve-batch: --mu 0", batch("--mu", "0"), "--mu", r"must be > 0"),
        Bad("solve-batch: too few elements", batch("--elements", "10"), "--elements", "at least"),
        Bad("solve-batch: no steps", batch("--steps", "0"), "--steps", "at least 1"),
        Bad(
            "solve-batch: no cases per task",
            batch("--cases-per-task", "0"),
            "--cases-per-task",
            ">= 1",
        ),
        Bad("solve-batch: no workers", batch("--workers", "0"), "--workers", ">= 1"),
        Bad(
            "solve-batch: workers and a scheduler",
            batch("--workers", "2", "--scheduler", "tcp://127.0.0.1:8786"),
            "--scheduler",
            r"either --workers or --scheduler",
        ),
        Bad(
            "solve-batch: --out is the input",
            batch(out="{d}/batch.csv"),
            "--out",
            r"is also an input \(the cases",
        ),
        Bad(
            "solve-batch: --out a folder without its slash",
            batch(out="{d}/a_folder"),
            "--out",
            r"is a folder: end it with /",
        ),
        Bad(
            "solve-batch: --out a file of the cases folder",
            (
                "solve-batch",
                "{d}/batch_dataset",
                *HERTZ,
                "--mu",
                "0.1",
                "--out",
                "{d}/batch_dataset/part.parquet",
            ),
            "--out",
            r"part\.parquet is also an input \(a file of the cases",
        ),
        Bad(
            "solve-batch: --out a folder holding the input",
            batch(out="{d}/"),
            "--out",
            r"holds an input",
        ),
        Bad(
            "solve-batch: --out a bad extension",
            batch(out="{d}/o.txt"),
            "--out",
            r"name a \.csv or \.parquet file",
        ),
        Bad(
            "sweep: no workers",
            (
                "sweep",
                "{d}/cases.csv",
                *HERTZ,
                "--mu",
                "0.1",
                "--workers",
                "0",
                "--out",
                "{d}/o.csv",
            ),
            "--workers",
            ">= 1",
        ),
    ]


BAD: list[Bad] = [
    *number_option_cases(),
    *physics_cases(),
    *law_cases(),
    *derive_cases(),
    *sweep_cases(),
    *command_line_cases(),
    *solve_cases(),
    *calibrate_cases(),
    *match_cases(),
    *stress_cases(),
    *solve_batch_cases(),
]


# --- the table: borderline valid inputs ---------------------------------------------------------
def solve_increasing(
    function: Callable[[float], float], target: float, low: float, high: float
) -> float:
    """Bisection to the last bit: an independent inverse of a contact law P(a)."""
    for _ in range(200):
        middle = 0.5 * (low + high)
        if function(middle) < target:
            low = middle
        else:
            high = middle
    return 0.5 * (low + high)


def module_law_check(
    law: Callable[[float], float], high: float, P1: float, P2: float, low: float = 0.0
) -> Callable[..., None]:
    """a1, a2 against bisection of the law on (low, high), where it increases."""

    def check(result: dict, folder: Path) -> None:
        for key, P in (("a1", P1), ("a2", P2)):
            assert result[key] == pytest.approx(solve_increasing(law, P, low, high), rel=1e-12)
        assert 0 < result["b"] <= result["a2"]

    return check


def table_check(P1: float, P2: float, warns: str | None = None) -> Callable[..., None]:
    def check(result: dict, folder: Path) -> None:
        # The fit of a Hertz table (5 points, 60 <= P <= 140) reproduces (29) closely.
        assert result["a1"] == pytest.approx(hertz_a(P1), rel=1e-4)
        assert result["a2"] == pytest.approx(hertz_a(P2), rel=1e-4)
        assert 0 < result["b"] <= result["a2"]
        if warns is not None:
            assert any(re.search(warns, text) for text in result["warnings"]), result["warnings"]

    return check


def power_check(n: float, A: float, P1: float, P2: float) -> Callable[..., None]:
    # P = K E* A a^n, K = sqrt(pi) Gamma((n + 1)/2) / Gamma(n/2) (README), E* = 1.
    K = math.sqrt(math.pi) * math.exp(math.lgamma((n + 1) / 2) - math.lgamma(n / 2))

    def check(result: dict, folder: Path) -> None:
        assert result["a1"] == pytest.approx((P1 / (K * A)) ** (1 / n), rel=1e-12)
        assert result["a2"] == pytest.approx((P2 / (K * A)) ** (1 / n), rel=1e-12)
        assert 0 < result["b"] <= result["a2"]

    return check


def sweep_check(out: str, lam: list[float]) -> Callable[..., None]:
    def check(text: str, folder: Path) -> None:
        with open(folder / out, newline="") as handle:
            rows = list(csv.DictReader(handle))
        assert [float(row["lam"]) for row in rows] == pytest.approx(lam, rel=1e-15)
        assert all(row["error"] == "" for row in rows)

    return check


def slip_check(points: list[float]) -> Callable[..., None]:
    """Fig. 5's cycle slips forward at the right edge: no slip in the stick zone (x < b), and
    delta < 0 in the slip zone (opposite to q2 - q1 > 0; see ``asymslip slip --help``)."""

    def check(result: dict, folder: Path) -> None:
        assert result["x"] == points
        for x, delta in zip(result["x"], result["slip"], strict=True):
            assert delta == 0 if x < result["b"] else delta < 0

    return check


def wide_sweep_check(text: str, folder: Path) -> None:
    with open(folder / "wide.csv", newline="") as handle:
        wide, fig5 = csv.DictReader(handle)
    # P1 = 100 -> P2 = 1e4: the corrective-stick (40) b is far outside the contact; (22) is not.
    assert wide["b_corrective_stick"] == "" and "(40) puts the stick boundary" in wide["warnings"]
    assert 0 < float(wide["b"]) <= hertz_a(1e4)
    assert float(fig5["b_corrective_stick"]) == pytest.approx(float(fig5["b"]), rel=1e-3)
    assert fig5["warnings"] == ""


def wedge_apex_check(result: dict, folder: Path) -> None:
    """The wedge's pressure is infinite at its apex: (47) there is left out, (49) is not."""
    assert result["q_diff_exact"][:2] == [None, None]
    assert math.isfinite(result["q_diff_exact"][2])
    assert all(math.isfinite(q) for q in result["q_diff"])
    assert any(
        "q_diff_exact (47) is left out (null) at 2 point(s) where it is not a finite "
        "double: the law's pressure is infinite there (the apex x = 0 of a wedge)" in text
        for text in result["warnings"]
    )


def paper_left_out_check(result: dict, folder: Path) -> None:
    """Just short of the zero denominator of (22) (bulk tension), (22) puts the stick
    boundary far outside the contact: null, with a warning; b (the second-order b2) is not."""
    assert result["b_paper"] is None
    assert any(
        text.startswith(
            "b_paper: the estimate (22) puts the stick boundary outside the contact (0, a2]"
        )
        for text in result["warnings"]
    )
    assert 0 < result["b"] <= result["a2"]


def solve_check(result: dict, folder: Path) -> None:
    """Fig. 5's cycle on the Hertz contact (also as a profile h = x^2/2, or along the same
    path): the solver's b within its own error bound of the exact (34)."""
    b34 = math.sqrt(2 / math.pi * (100 + 105 - (1 - 0) / 0.1))
    assert abs(result["b"] - b34) <= result["b_error"], result  # the right edge's keys


def calibrate_check(result: dict, folder: Path) -> None:
    """Each edge's a and L_I from the traces against (29) and (31), within 1e-4."""
    for side in ("right", "left"):
        for fit in result[side]:
            assert fit["a"] == pytest.approx(hertz_a(fit["P"]), rel=1e-4)
            assert fit["L_I"] == pytest.approx(hertz_L_I(fit["P"]), rel=1e-3)


def derive_check(name: str, summary: str) -> Callable[..., None]:
    def check(text: str, folder: Path) -> None:
        assert re.search(summary, text), text
        assert (folder / f"{name}.py").read_text().startswith("#")

    return check


def sz(**changes: str) -> tuple[str, ...]:
    """``slip-zone --json`` on the Hertz law (R = E* = 1) and the Fig. 5 cycle, changed."""
    return ("slip-zone", *hertz(**changes), "--json")


def valid_cases() -> list[Valid]:
    P1, P2, mu = 100.0, 105.0, 0.1
    eta_zero = zero_denominator_eta(mu, P1, P2)
    module = ("slip-zone", "--law", "module", "--module")
    table = ("slip-zone", "--law", "table", "--table")
    a1 = hertz_a(P1)
    return [
        # numbers as people type them
        Valid(
            "--Q1 -1e-1 (negative exponent)",
            sz(Q1="-1e-1", Q2="5e-1"),
            slip_zone_check(100, -0.1, 105, 0.5, 0.1, slips=True),
        ),
        Valid(
            "--Q1 -1e2 (negative exponent, mu 1.5)",
            ("slip-zone", *hertz(Q1="-1e2", mu="1.5"), "--json"),
            slip_zone_check(100, -100, 105, 1, 1.5, slips=True),
        ),
        Valid(
            "--Q1=-1E+0 and --Q2 -.5",
            ("slip-zone", *HERTZ, *cycle(Q1=None, Q2="-.5"), "--Q1=-1E+0", "--json"),
            slip_zone_check(100, -1, 105, -0.5, 0.1, slips=False),
        ),
        Valid(
            "--sigma1 -2.5e-3 (small tension)",
            ("slip-zone", *hertz(sigma1="-2.5e-3"), "--json"),
            slip_zone_check(100, 0, 105, 1, 0.1, -2.5e-3, 0.0),
        ),
        Valid(
            "--P1 1e2 --P2 1.05E2",
            ("slip-zone", *hertz(P1="1e2", P2="1.05E2"), "--json"),
            slip_zone_check(100, 0, 105, 1, 0.1, slips=True),
        ),
        # friction coefficients: tiny, subnormal, huge
        Valid(
            "mu = 1e-300, no shear",
            ("slip-zone", *hertz(mu="1e-300", Q2="0"), "--json"),
            slip_zone_check(100, 0, 105, 0, 1e-300, slips=False),
        ),
        Valid(
            "mu = 1e-300, partial slip",
            sz(mu="1e-300", Q2="5e-299"),
            slip_zone_check(100, 0, 105, 5e-299, 1e-300, slips=True),
        ),
        Valid(
            "mu = 5e-324 (subnormal)",
            ("slip-zone", *hertz(mu="5e-324", Q2="0"), "--json"),
            slip_zone_check(100, 0, 105, 0, 5e-324, slips=False),
        ),
        Valid(
            "mu = 1e300",
            ("slip-zone", *hertz(mu="1e300"), "--json"),
            slip_zone_check(100, 0, 105, 1, 1e300, slips=False),
        ),
        # loads: huge and tiny but finite, far apart, very close
        Valid(
            "P1 = 1e300, P2 = 1.05e300",
            sz(P1="1e300", P2="1.05e300", Q2="1e298"),
            slip_zone_check(1e300, 0, 1.05e300, 1e298, 0.1, slips=True),
        ),
        Valid(
            "P1 = 1e-100, P2 = 1.05e-100",
            ("slip-zone", *hertz(P1="1e-100", P2="1.05e-100", Q2="1e-101"), "--json"),
            slip_zone_check(1e-100, 0, 1.05e-100, 1e-101, 0.1, slips=True),
        ),
        Valid(
            "P1 = 1e-320 (subnormal), P2 = 2e-320",
            ("slip-zone", *hertz(P1="1e-320", P2="2e-320", Q2="0"), "--json"),
            slip_zone_check(1e-320, 0, 2e-320, 0, 0.1, slips=False, rel=1e-3),
        ),
        Valid(
            "P1 = 5e-324 (mu P1 rounds to 0), Q1 = 0: not gross sliding",
            ("slip-zone", *hertz(P1="5e-324", P2="1e-323", Q2="0"), "--json"),
            slip_zone_check(5e-324, 0, 1e-323, 0, 0.1, slips=False, rel=1e-3),
        ),
        Valid(
            "P1 = 1, P2 = 1e6 (no slip; eq24 flagged)",
            ("slip-zone", *hertz(P1="1", P2="1e6"), "--json"),
            slip_zone_check(1, 0, 1e6, 1, 0.1, slips=False, warns=r"^eq24 > 0\.1"),
        ),
        Valid(
            "P1 = 100, P2 = 1e4, slipping (every estimate inside the contact or null)",
            ("slip-zone", *hertz(Q1="-9", P2="1e4", Q2="999"), "--json"),
            slip_zone_check(100, -9, 1e4, 999, 0.1, slips=True, warns=r"^eq24 > 0\.1"),
        ),
        Valid(
            "dP/P1 = 1e-12",
            ("slip-zone", *hertz(P2="100.0000000001", Q2="2e-11"), "--json"),
            slip_zone_check(100, 0, 100.0000000001, 2e-11, 0.1, slips=True),
        ),
        # limits of the cycle
        Valid(
            "right at the no-slip limit lam = mu",
            ("slip-zone", *hertz(Q2="0.5"), "--json"),
            slip_zone_check(100, 0, 105, 0.5, 0.1, slips=False),
        ),
        Valid(
            "just inside gross sliding",
            sz(Q1="9.999999", Q2="10.4"),
            slip_zone_check(100, 9.999999, 105, 10.4, 0.1),
        ),
        Valid(
            "bulk tension at half the zero-denominator value",
            ("slip-zone", *hertz(Q2="0", sigma2=repr(0.5 * eta_zero * 5)), "--json"),
            slip_zone_check(100, 0, 105, 0, 0.1, 0.0, 0.5 * eta_zero * 5),
        ),
        Valid(
            "(22) near its zero denominator is left out, not printed",
            sz(Q2="0", sigma2=repr(0.999 * eta_zero * 5)),
            paper_left_out_check,
        ),
        Valid("--edge left", ("slip-zone", *hertz(Q2="-1"), "--edge", "left"), None),
        # laws at their edges
        Valid(
            "flat-rounded with c = 0 is Hertz",
            ("slip-zone", *_swap(FLAT, "--flat-half-width", "0"), *cycle(), "--json"),
            slip_zone_check(100, 0, 105, 1, 0.1, R=10),
        ),
        Valid(
            "power n = 2, A = 1/2 is Hertz",
            ("slip-zone", *POWER, *cycle(), "--json"),
            slip_zone_check(100, 0, 105, 1, 0.1, slips=True),
        ),
        Valid(
            "power n = 1 (wedge)",
            ("slip-zone", *_swap(POWER, "--n", "1"), *cycle(), "--json"),
            power_check(1.0, 0.5, 100, 105),
        ),
        Valid(
            "power n = 1e3",
            ("slip-zone", *_swap(POWER, "--n", "1e3"), *cycle(), "--json"),
            power_check(1e3, 0.5, 100, 105),
        ),
        Valid("table law", (*table, "{d}/hertz.csv", *cycle(), "--json"), table_check(100, 105)),
        Valid(
            "table law with a byte-order mark",
            (*table, "{d}/table_bom.csv", *cycle(), "--json"),
            table_check(100, 105),
        ),
        Valid(
            "table law with CRLF line ends",
            (*table, "{d}/table_crlf.csv", *cycle(), "--json"),
            table_check(100, 105),
        ),
        Valid(
            "table law with a quoted header",
            (*table, "{d}/table_quoted.csv", *cycle(), "--json"),
            table_check(100, 105),
        ),
        Valid(
            "table law with comments and another column",
            (*table, "{d}/table_commented.csv", *cycle(), "--json"),
            table_check(100, 105),
        ),
        Valid(
            "table law beyond its loads (flagged)",
            (*table, "{d}/hertz.csv", *cycle(P1="150", P2="157.5", Q2="1.5"), "--json"),
            table_check(150, 157.5, warns=r"P1 is outside"),
        ),
        Valid(
            "cubic module law inside its range",
            (
                *module,
                "{d}/cubic.py",
                "--param",
                "E_star=1",
                "--param",
                "k=0.1",
                *cycle(P1="1", P2="1.05", Q2="0.01"),
                "--json",
            ),
            module_law_check(lambda a: a**2 - 0.1 * a**3, 2 / 0.3, 1.0, 1.05),
        ),
        Valid(
            "tanh module law below its bound",
            (
                *module,
                "{d}/tanh_law.py",
                "--param",
                "k=10",
                *cycle(P1="1", P2="1.05", Q2="0.01"),
                "--json",
            ),
            module_law_check(lambda a: 10 * math.tanh(a), 50.0, 1.0, 1.05),
        ),
        Valid(
            "a**a module law on its rising branch",
            (*module, "{d}/selfpow.py", *cycle(P1="2", P2="2.1", Q2="0.01"), "--json"),
            module_law_check(lambda a: a**a, 3.0, 2.0, 2.1, low=1 / math.e),
        ),
        Valid(
            "a**a**a module law at P = 1e300",
            (*module, "{d}/tower.py", *cycle(P1="1e300", P2="1.05e300", Q2="1e298"), "--json"),
            module_law_check(
                lambda a: math.exp(math.log(a) * a**a) if a < 4.27 else math.inf,
                4.3,
                1e300,
                1.05e300,
                low=1.0,
            ),
        ),
        # tractions and slip: far from the edge is reported, not refused
        Valid(
            "traction --x 0.1 -1e-2",
            ("traction", *hertz(), "--x", "0.1", "-1e-2", "--json"),
            traction_check([0.1, -0.01], [False, False]),
        ),
        Valid(
            "traction --x -0.44 (far from the edge)",
            ("traction", *hertz(), "--x", "-0.44", "--json"),
            traction_check([-0.44], [False]),
        ),
        Valid(
            "traction near the edge",
            ("traction", *hertz(), "--x", repr(0.95 * A2_FIG5), "--json"),
            traction_check([0.95 * A2_FIG5], [True]),
        ),
        Valid(
            "traction at x = a1",
            ("traction", *hertz(), "--x", repr(a1), "--json"),
            traction_check([a1], [True]),
        ),
        Valid(
            "traction at the apex of a wedge",
            (
                "traction",
                *_swap(POWER, "--n", "1"),
                *cycle(),
                "--x",
                "0",
                "5e-324",
                "0.1",
                "--json",
            ),
            wedge_apex_check,
        ),
        Valid(
            "traction on a contact of 1e200 (the exact pressure overflows)",
            (
                "traction",
                "--law",
                "power",
                "--A",
                "50",
                "--n",
                "1.5",
                "--E-star",
                "1e-300",
                *cycle(),
                "--x",
                "0.1",
                "--b",
                "exact",
                "--json",
            ),
            lambda result, folder: (
                result["q_diff_exact"] == [None] and math.isfinite(result["q_diff"][0])
            )
            or pytest.fail(str(result)),
        ),
        Valid(
            "traction at the left edge",
            ("traction", *hertz(), "--edge", "left", "--x", "-11.5", "0.44", "--json"),
            traction_check([-11.5, 0.44], [True, False]),
        ),
        Valid(
            "slip --x -1e-2 11.5",
            ("slip", *hertz(), "--x", "-1e-2", "11.5", "--json"),
            slip_check([-0.01, 11.5]),
        ),
        Valid(
            "slip with a table law and --E-star",
            (
                "slip",
                "--law",
                "table",
                "--table",
                "{d}/hertz.csv",
                "--E-star",
                "1",
                *cycle(),
                "--x",
                "0",
                "11.5",
                "--json",
            ),
            slip_check([0.0, 11.5]),
        ),
        # derive, sweep, figure
        Valid(
            "derive a law given with a leading minus",
            (
                "derive",
                "--P-of-a",
                "-1/a+k",
                "--params",
                "k",
                "--name",
                "minus",
                "--out",
                "{d}/minus.py",
            ),
            derive_check("minus", r"positive and increasing for a > 1/k"),
        ),
        Valid(
            "derive a tower of powers",
            ("derive", "--P-of-a", "a**a**a**a", "--name", "tower4", "--out", "{d}/tower4.py"),
            derive_check("tower4", r"was not established symbolically"),
        ),
        Valid(
            "derive a long sum",
            (
                "derive",
                "--P-of-a",
                "+".join(["a"] * 999),
                "--name",
                "long_sum",
                "--out",
                "{d}/long_sum.py",
            ),
            derive_check("long_sum", r"positive and increasing for every a > 0"),
        ),
        Valid(
            "derive cubic",
            (
                "derive",
                "--P-of-a",
                "E_star*a**2 - k*a**3",
                "--params",
                "E_star k",
                "--name",
                "cubic2",
                "--out",
                "{d}/cubic2.py",
            ),
            derive_check("cubic2", r"0 < a < 2\*E_star/\(3\*k\)"),
        ),
        Valid(
            "sweep with negative exponents",
            ("sweep", "{d}/cases.csv", *HERTZ, "--mu", "0.1", "--out", "{d}/valid.csv"),
            sweep_check("valid.csv", [0.2, 0.12]),
            stderr=r"^asymslip sweep: 2 rows written",
        ),
        Valid(
            "sweep --chunk-rows 1e5",
            (
                "sweep",
                "{d}/cases.csv",
                *HERTZ,
                "--mu",
                "0.1",
                "--chunk-rows",
                "1e5",
                "--out",
                "{d}/chunks.csv",
            ),
            sweep_check("chunks.csv", [0.2, 0.12]),
            stderr=r"^asymslip sweep: 2 rows",
        ),
        Valid(
            "sweep of a spreadsheet's CSV (byte-order mark, CRLF)",
            (
                "sweep",
                "{d}/cases_spreadsheet.csv",
                *HERTZ,
                "--mu",
                "0.1",
                "--out",
                "{d}/spreadsheet.csv",
            ),
            sweep_check("spreadsheet.csv", [0.2, 0.12]),
            stderr=r"^asymslip sweep: 2 rows",
        ),
        Valid(
            "sweep: an estimate outside the contact is left empty, with its warning",
            (
                "sweep",
                "{d}/cases_wide.csv",
                *HERTZ,
                "--mu",
                "0.1",
                "--edge",
                "right",
                "--out",
                "{d}/wide.csv",
            ),
            wide_sweep_check,
            stderr=r"^asymslip sweep: 2 rows",
        ),
        Valid("solve the Fig. 5 cycle", ("solve", *hertz(), *SOLVE, "--json"), solve_check),
        Valid(
            "solve --elements 1e2 --steps 3 along a path",
            (
                "solve",
                *HERTZ,
                "--mu",
                "0.1",
                "--path",
                "{d}/path.csv",
                "--elements",
                "1e2",
                "--steps",
                "3",
                "--json",
            ),
            solve_check,
        ),
        Valid(
            "solve a tabulated profile",
            (
                "solve",
                "--profile-table",
                "{d}/profile.csv",
                "--E-star",
                "1",
                *cycle(),
                *SOLVE,
                "--json",
            ),
            solve_check,
        ),
        Valid("calibrate Hertz traces", ("calibrate", "{d}/traces.csv", "--json"), calibrate_check),
        Valid(
            "slip-zone with the calibrated law",
            (
                "slip-zone",
                "--law",
                "calibrated",
                "--calibration",
                "{d}/calibration.json",
                *cycle(),
                "--json",
            ),
            table_check(100, 105),
        ),
        Valid(
            "figure --check of the committed Fig. 5",
            ("figure", "fig5", "--check", str(Path(__file__).parents[1] / "generated" / "figures")),
            lambda text, folder: None,
        ),
    ]


VALID = valid_cases()

ROW_ERRORS = [
    RowErrors(
        "sweep: bad rows",
        ("sweep", "{d}/cases_bad_rows.csv", *HERTZ, "--mu", "0.1", "--out", "{d}/rows.csv"),
        "rows.csv",
        {
            4: r"^P2: '1o5' is not a number",
            5: r"^P2: must exceed P1",
            6: r"^Q1: \|Q1\| = 900 must be < mu P1 = 10",
            7: r"^Q1: must be finite",
            8: r"^Q1: missing",
        },
        (3, 9),
    ),
    RowErrors(
        "sweep: no row with the header's field count (pyarrow read it as an empty file)",
        (
            "sweep",
            "{d}/cases_field_counts.csv",
            *HERTZ,
            "--mu",
            "0.1",
            "--out",
            "{d}/field_counts.csv",
        ),
        "field_counts.csv",
        {
            2: r"^line has 3 fields, the header has 4: '100,0,105'",
            3: r"^line has 5 fields, the header has 4: '1,000,0,105,1'",
        },
    ),
    RowErrors(
        "sweep: bad values in the mu column",
        ("sweep", "{d}/cases_mu.csv", *HERTZ, "--mu", "0.1", "--out", "{d}/mu.csv"),
        "mu.csv",
        {3: r"^mu: must be > 0", 4: r"^mu: 'high' is not a number"},
        (2, 5),
    ),
    RowErrors(
        "sweep: module law beyond its maximum in one row",
        (
            "sweep",
            "{d}/cases_cubic.csv",
            "--law",
            "module",
            "--module",
            "{d}/cubic.py",
            "--param",
            "E_star=1",
            "--param",
            "k=0.1",
            "--mu",
            "0.1",
            "--out",
            "{d}/cubic.csv",
        ),
        "cubic.csv",
        {3: r"^P1: no contact half-width of the cubic law"},
        (2, 4),
    ),
]


# --- the tests ----------------------------------------------------------------------------------
@pytest.mark.parametrize("case", BAD, ids=[case.id for case in BAD])
def test_bad_input_is_refused_in_one_line_naming_the_option_and_the_rule(case: Bad, files: Path):
    status, out, err = run(expand(case.argv, files))
    assert "Traceback" not in err
    lines = err.splitlines()
    assert status == case.status, err
    assert len(lines) == 1, err
    line = lines[0]
    assert re.match(r"^asymslip( [a-z-]+)?: error: ", line), line
    assert names_option(line, case.option), line
    assert re.search(case.rule, line), line
    assert not printed_non_finite(out + err), out + err


@pytest.mark.parametrize("case", VALID, ids=[case.id for case in VALID])
def test_borderline_valid_input_works(case: Valid, files: Path):
    status, out, err = run(expand(case.argv, files))
    assert status == 0, err
    assert re.search(case.stderr, err), err
    assert not printed_non_finite(out), out
    if case.check is not None:
        case.check(json.loads(out) if "--json" in case.argv else out, files)


@pytest.mark.parametrize("case", ROW_ERRORS, ids=[case.id for case in ROW_ERRORS])
def test_sweep_rows_that_break_a_rule_get_their_reason_and_the_others_go_on(
    case: RowErrors, files: Path
):
    status, out, err = run(expand(case.argv, files))
    assert status == 1, err
    assert "Traceback" not in err
    with open(files / case.out, newline="") as handle:
        reader = csv.DictReader(handle)
        rows = list(reader)
    source = Path(expand((case.argv[1],), files)[0]).read_text().splitlines()
    # output row k comes from the k-th data line of the input (blank and comment lines skipped)
    data_lines = [
        number
        for number, line in enumerate(source, start=1)
        if line.strip() and not line.startswith("#")
    ][1:]
    assert len(rows) == len(data_lines)
    by_line = dict(zip(data_lines, rows, strict=True))
    for line, rule in case.errors.items():
        assert re.search(rule, by_line[line]["error"]), by_line[line]["error"]
        assert re.search(rf"line {line}: ", err), err
        assert by_line[line]["b"] == ""
    for line in case.valid_lines:
        assert by_line[line]["error"] == ""
        assert float(by_line[line]["b"]) > 0
    assert not printed_non_finite(out + err), err


def test_the_table_has_at_least_80_cases_across_every_command():
    commands = {case.argv[0] for case in BAD if case.argv} | {case.argv[0] for case in VALID}
    assert {
        "slip-zone",
        "traction",
        "slip",
        "figure",
        "derive",
        "sweep",
        "solve",
        "calibrate",
        "stress",
        "nucleation",
    } <= commands
    assert len(BAD) + len(VALID) + len(ROW_ERRORS) >= 80


SWEEP_FILE_CASES = [case for case in BAD if case.id.startswith("sweep: CASES")]


@pytest.mark.parametrize("case", SWEEP_FILE_CASES, ids=[case.id for case in SWEEP_FILE_CASES])
def test_bad_cases_files_are_refused_the_same_without_pyarrow(
    case: Bad, files: Path, monkeypatch: pytest.MonkeyPatch
):
    """The sweep reads with NumPy alone when pyarrow (the parquet extra) is not installed."""
    from asymslip.files import arrow

    monkeypatch.setattr(arrow, "available", lambda: False)
    status, out, err = run(expand(case.argv, files))
    assert status == 2 and len(err.splitlines()) == 1, err
    assert names_option(err, case.option) and re.search(case.rule, err), err


# --- real processes: exit status, traceback, warnings at import, missing extras ----------------
#: A sample of the table run as real `python -m asymslip` processes under PYTHONWARNINGS=error.
PROCESS_SAMPLE = (
    "slip-zone --Q1 -inf",
    "--Q1=1e308 --Q2=-1e308 overflows",
    "traction --x nan",
    "figure: --out under a file",
    "sweep: --out is the input",
    "solve: a falling profile -x**2",
)
VALID_PROCESS_SAMPLE = ("--Q1 -1e-1 (negative exponent)",)

#: (extra, the package it provides, a command that needs it, the file it must not leave).
MISSING_EXTRAS = [
    (
        "plot",
        "matplotlib",
        ("figure", "fig5", "--out", "{d}/figures_without_matplotlib"),
        "figures_without_matplotlib",
    ),
    (
        "special",
        "scipy",
        (
            "traction",
            "--law",
            "power",
            "--A",
            "1",
            "--n",
            "3",
            "--E-star",
            "1",
            *cycle(),
            "--x",
            "1",
        ),
        None,
    ),
    (
        "derive",
        "sympy",
        ("derive", "--P-of-a", "a**2", "--name", "square", "--out", "{d}/square.py"),
        "square.py",
    ),
    (
        "parquet",
        "pyarrow",
        ("sweep", "{d}/cases.csv", *HERTZ, "--mu", "0.1", "--out", "{d}/out.parquet"),
        "out.parquet",
    ),
    (
        "dask",
        "distributed",
        (
            "solve-batch",
            "{d}/batch.csv",
            *HERTZ,
            "--mu",
            "0.1",
            "--workers",
            "2",
            "--out",
            "{d}/batch_on_dask.csv",
        ),
        "batch_on_dask.csv",
    ),
    (
        "fe",
        "meshio",
        ("calibrate", "{d}/surface.vtu", "--out", "{d}/cal_without_meshio.json"),
        "cal_without_meshio.json",
    ),
]
#: (package, a command that must work without it): only what needs an extra may refuse.
WITHOUT_EXTRAS = [
    (
        "scipy",
        (
            "slip-zone",
            "--law",
            "power",
            "--A",
            "1",
            "--n",
            "2.5",
            "--E-star",
            "1",
            *cycle(),
            "--json",
        ),
    ),
    (
        "pyarrow",
        ("sweep", "{d}/cases.csv", *HERTZ, "--mu", "0.1", "--out", "{d}/without_pyarrow.csv"),
    ),
    (
        "distributed",
        (
            "solve-batch",
            "{d}/batch.csv",
            *HERTZ,
            "--mu",
            "0.1",
            "--elements",
            "100",
            "--out",
            "{d}/batch_in_one_process.csv",
        ),
    ),
]


#: One process with every optional package unimportable, as if none were installed
#: (``sys.modules[name] = None`` makes every import of it fail), running the commands given as
#: JSON one after the other and printing each one's (exit status, stdout, stderr) as JSON.
WITHOUT_OPTIONAL_PACKAGES = """
import contextlib, io, json, sys
for package in ("matplotlib", "scipy", "sympy", "pyarrow", "meshio", "dask", "distributed"):
    sys.modules[package] = None
from asymslip.cli import main
results = []
for argv in json.loads(sys.argv[1]):
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            status = main(argv)
        except SystemExit as exit_:
            status = exit_.code
    results.append((status, out.getvalue(), err.getvalue()))
print(json.dumps(results))
"""


@pytest.fixture(scope="module", autouse=True)
def processes(files: Path) -> Iterator[dict[tuple[str, str], subprocess.Popen[str]]]:
    """Every real process of this file, started together before the first test, so that they
    run beside one another and beside the in-process table (about one process per core of
    wall time in all); the tests at the end collect them."""
    bad = {case.id: case for case in BAD}
    valid = {case.id: case for case in VALID}
    commands: dict[tuple[str, str], list[str]] = {}
    for name in PROCESS_SAMPLE:
        commands["sample", name] = ["-m", "asymslip", *expand(bad[name].argv, files)]
    for name in VALID_PROCESS_SAMPLE:
        commands["sample", name] = ["-m", "asymslip", *expand(valid[name].argv, files)]
    extras = [expand(argv, files) for _, _, argv, _ in MISSING_EXTRAS] + [
        expand(argv, files) for _, argv in WITHOUT_EXTRAS
    ]
    commands["extras", "none installed"] = ["-c", WITHOUT_OPTIONAL_PACKAGES, json.dumps(extras)]
    environment = {**os.environ, "PYTHONWARNINGS": "error"}
    commands["pipe", "closed"] = ["-m", "asymslip", "slip-zone", *hertz()]
    running = {
        key: subprocess.Popen(
            [sys.executable, *arguments],
            cwd=files,
            env=environment,
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
        )
        for key, arguments in commands.items()
    }
    # `asymslip ... | head -1`: the reader is gone before the command prints.
    running["pipe", "closed"].stdout.close()
    running["pipe", "closed"].stdout = None
    yield running
    for process in running.values():  # none is left behind, whatever the tests did
        if process.poll() is None:
            process.kill()
        process.communicate()


def finish(
    running: dict[tuple[str, str], subprocess.Popen[str]], kind: str
) -> dict[str, tuple[int, str, str]]:
    """Wait for the processes of one kind: name -> (exit status, stdout, stderr)."""
    results = {}
    for (group, name), process in running.items():
        if group == kind:
            out, err = process.communicate(timeout=300)
            results[name] = (process.returncode, out, err)
    return results


def test_a_sample_of_the_table_behaves_the_same_in_real_processes_under_warnings_as_errors(
    files: Path, processes: dict
):
    bad = {case.id: case for case in BAD}
    valid = {case.id: case for case in VALID}
    for name, (status, out, err) in finish(processes, "sample").items():
        assert "Traceback" not in err, (name, err)
        if name in bad:
            case = bad[name]
            assert status == 2, (name, err)
            assert len(err.splitlines()) == 1, (name, err)
            assert names_option(err, case.option) and re.search(case.rule, err), (name, err)
            assert not printed_non_finite(out + err), (name, out + err)
        else:
            assert status == 0 and err == "", (name, err)
            valid[name].check(json.loads(out), files)
    assert (files / "cases.csv").read_bytes() == FILES["cases.csv"].encode()  # input intact


def extras_results(processes: dict) -> list[tuple[int, str, str]]:
    """Each command's (status, stdout, stderr) from the process without optional packages."""
    status, out, err = finish(processes, "extras")["none installed"]
    assert status == 0 and err == "", err
    return json.loads(out)


def test_a_missing_optional_dependency_is_one_line_naming_the_extra(files: Path, processes: dict):
    results = extras_results(processes)
    for (extra, _, _, written), (status, _, err) in zip(
        MISSING_EXTRAS, results[: len(MISSING_EXTRAS)], strict=True
    ):
        assert status == 2, (extra, err)
        assert "Traceback" not in err and len(err.splitlines()) == 1, (extra, err)
        assert f"pip install 'asymslip[{extra}]'" in err, (extra, err)
        if written is not None:
            assert not (files / written).exists()


def test_what_needs_no_optional_dependency_works_without_them(files: Path, processes: dict):
    results = dict(
        zip(
            (package for package, _ in WITHOUT_EXTRAS),
            extras_results(processes)[len(MISSING_EXTRAS) :],
            strict=True,
        )
    )
    for package, _ in WITHOUT_EXTRAS:
        status, out, err = results[package]
        assert status == 0 and "Traceback" not in err, (package, err)
    assert json.loads(results["scipy"][1])["a1"] > 0  # the power law's slip zone: no 2F1
    with open(files / "without_pyarrow.csv", newline="") as handle:
        assert [float(row["lam"]) for row in csv.DictReader(handle)] == [0.2, 0.12]
    with open(files / "batch_in_one_process.csv", newline="") as handle:  # no pyarrow, no Dask
        assert [row["edge"] for row in csv.DictReader(handle)] == ["right", "left"]


def test_a_reader_that_goes_away_stops_the_command_quietly(processes: dict):
    """``asymslip slip-zone ... | head -1``: no BrokenPipeError traceback, the status of a
    command stopped by SIGPIPE (128 + 13)."""
    status, out, err = finish(processes, "pipe")["closed"]
    assert (status, err) == (141, "")


@pytest.mark.parametrize("eta, other_edge", [(0.0, 1.0), (0.01, 1.0), (-0.02, -1.0)])
def test_the_second_order_width_in_scaled_units_is_the_kernel_at_ordinary_values(eta, other_edge):
    """slip_zones evaluates b2 with mu = 1 in units of a1 and dP (so that loads of 1e300 and
    mu = 1e-300 do not overflow its terms); at ordinary values that is the kernel itself."""
    from asymslip_gen.second_order import slip_zone_width_second_order_from_multiplier as kernel

    law, mu, P1, dP, lam = HertzLaw(1, 1), 0.1, 100.0, 5.0, 0.2
    state = law.cycle_state(P1, dP)
    a1 = float(state.a1)
    direct = kernel(mu, lam, eta, a1, state.a_slope1, state.L_I1, state.L_I_slope1, dP, other_edge)
    scaled = a1 * kernel(
        1.0,
        lam / mu,
        eta * a1 / mu,
        1.0,
        state.a_slope1 * dP / a1,
        state.L_I1 * a1**1.5 / dP,
        state.L_I_slope1 * a1**1.5,
        1.0,
        other_edge,
    )
    assert float(scaled) == pytest.approx(float(direct), rel=1e-14)
    sigma2 = eta * dP
    result = slip_zone(law, LoadCycle(P1, 0.0, P1 + dP, lam * dP, 0.0, sigma2), mu)
    if other_edge == 1.0:  # the left edge slips the same way in the global frame here
        assert result.slip_zone_width == pytest.approx(float(direct), rel=1e-14)
