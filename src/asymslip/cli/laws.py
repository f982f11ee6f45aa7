"""The one registry of contact laws the commands know: ``--law NAME`` and its options.

Each law names the options it needs; the commands that take a law (slip-zone, traction, slip,
sweep) add every law's options through :func:`add_law_options` and build the law with
:func:`build_law`.  A new law is one entry here.
"""

from __future__ import annotations

import argparse
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from ..errors import InputError
from ..files.collisions import Input
from ..laws import ContactLaw, FlatRoundedLaw, HertzLaw, PowerLaw
from .parser import number


@dataclass(frozen=True)
class LawEntry:
    """A law of the command line: the options it requires and how to build it."""

    required: tuple[str, ...]
    build: Callable[[argparse.Namespace], ContactLaw]
    summary: str


def _table(args: argparse.Namespace) -> ContactLaw:
    from ..laws.table import TableLaw

    return TableLaw.from_csv(args.table)


def _calibrated(args: argparse.Namespace) -> ContactLaw:
    from ..calibration import Calibration

    return Calibration.load(args.calibration).law()


def _module(args: argparse.Namespace) -> ContactLaw:
    from ..laws.module_law import ModuleLaw

    values = parse_assignments("param", args.param)
    try:
        return ModuleLaw.from_file(args.module, **values)
    except InputError as error:
        if error.parameter not in values:
            raise
        # The API names the law's parameter (R); on the command line it was set by --param.
        raise InputError("param", f"{error.parameter} {error.rule}", error.value) from None


LAWS: dict[str, LawEntry] = {
    "hertz": LawEntry(
        ("R", "E_star"), lambda a: HertzLaw(R=a.R, E_star=a.E_star), "cylinder of radius R, (29)"
    ),
    "flat-rounded": LawEntry(
        ("c", "R", "E_star"),
        lambda a: FlatRoundedLaw(c=a.c, R=a.R, E_star=a.E_star),
        "flat punch of half-width c with corners of radius R",
    ),
    "power": LawEntry(
        ("A", "n", "E_star"),
        lambda a: PowerLaw(A=a.A, n=a.n, E_star=a.E_star),
        "punch h = A |x|^n, n >= 1",
    ),
    "table": LawEntry(("table",), _table, "a(P) fitted to a CSV of (P, a) points"),
    "module": LawEntry(("module",), _module, "a law module written by `asymslip derive`"),
    "calibrated": LawEntry(
        ("calibration",),
        _calibrated,
        "each edge's own law from `asymslip calibrate --out FILE.json`",
    ),
}

#: API parameter name -> the option that sets it, for error messages.
OPTION_OF = {
    "P1": "--P1",
    "Q1": "--Q1",
    "P2": "--P2",
    "Q2": "--Q2",
    "sigma1": "--sigma1",
    "sigma2": "--sigma2",
    "mu": "--mu",
    "R": "--R",
    "E_star": "--E-star",
    "law": "--law",
    "edge": "--edge",
    "x": "--x",
    "b": "--b",
    "c": "--flat-half-width",
    "A": "--A",
    "n": "--n",
    "table": "--table",
    "module": "--module",
    "param": "--param",
    "P_of_a": "--P-of-a",
    "params": "--params",
    "name": "--name",
    "out": "--out",
    "check": "--check",
    "check_a": "--check-a",
    "cases": "CASES",
    "chunk_rows": "--chunk-rows",
    "workers": "--workers",
    "scheduler": "--scheduler",
    "retries": "--retries",
    "cases_per_task": "--cases-per-task",
    "rows_per_task": "--rows-per-task",
    "cycle": "the load cycle (--P1 --Q1 --P2 --Q2 --sigma1 --sigma2 --mu)",
    "figure": "figure",
    "derive": "derive",
    "P": "--P1/--P2",
    "calibration": "--calibration",
    "traces": "TRACES",
    "origin": "--origin",
    "noise": "--noise",
    "loads": "--loads",
    "path": "--path",
    "profile": "--profile",
    "elements": "--elements",
    "steps": "--steps",
    "profile_table": "--profile-table",
    "data": "--data",
    "depth": "--depth",
    "source": "--source",
    "E": "--E",
    "sigma_y": "--sigma-y",
    "k_findley": "--k",
    "k_fatemi_socie": "--k-fs",
    "L": "--L",
    "criteria": "--criteria",
    "solver": "the reference solver",
    "field": "--field",
    "nu": "--nu",
    "elements_per_half_width": "--elements-per-half-width",
    "ccx": "ccx",
}


def add_law_options(parser: argparse.ArgumentParser) -> None:
    """The ``--law`` option and every law's parameters, in one group."""
    group = parser.add_argument_group("contact law")
    listed = "; ".join(f"{name}: {entry.summary}" for name, entry in LAWS.items())
    group.add_argument("--law", default="hertz", help=f"contact law (default: hertz) -- {listed}")
    group.add_argument(
        "--R", type=number, help="cylinder radius (hertz) or corner radius (flat-rounded) [length]"
    )
    group.add_argument(
        "--E-star",
        dest="E_star",
        type=number,
        help="plane-strain contact modulus E* [force/length^2]",
    )
    group.add_argument(
        "--flat-half-width",
        dest="c",
        type=number,
        help="half-width c of the flat (flat-rounded) [length]",
    )
    group.add_argument("--A", type=number, help="profile coefficient A of h = A |x|^n (power)")
    group.add_argument("--n", type=number, help="profile exponent n >= 1 of h = A |x|^n (power)")
    group.add_argument(
        "--table",
        type=Path,
        metavar="FILE.csv",
        help="table law: CSV with a header naming the columns P and a",
    )
    group.add_argument(
        "--module",
        type=Path,
        metavar="FILE.py",
        help="module law: a file written by `asymslip derive`",
    )
    group.add_argument(
        "--param",
        action="append",
        metavar="NAME=VALUE",
        help="module law (or solve --profile): a parameter value (repeat)",
    )
    group.add_argument(
        "--calibration",
        type=Path,
        metavar="FILE.json",
        help="calibrated law: a file written by `asymslip calibrate --out`",
    )


def build_law(args: argparse.Namespace) -> ContactLaw:
    """The law named by ``--law``, refusing a missing parameter by its option."""
    entry = LAWS.get(args.law)
    if entry is None:
        raise InputError("law", f"unknown contact law; choose one of {', '.join(LAWS)}", args.law)
    for name in entry.required:
        if getattr(args, name) is None:
            raise InputError(name, f"is required with --law {args.law}")
    return entry.build(args)


#: The law options that name a file the law is read from, and what the file is.
LAW_FILES = {
    "table": "the table law",
    "module": "the law module",
    "calibration": "the calibration",
}


def law_inputs(args: argparse.Namespace) -> list[Input]:
    """The files the chosen ``--law`` reads, for
    :func:`~asymslip.files.collisions.refuse_overwriting_inputs`."""
    entry = LAWS.get(args.law)
    required = entry.required if entry is not None else ()
    return [
        Input(Path(getattr(args, option)), option, what)
        for option, what in LAW_FILES.items()
        if option in required and getattr(args, option, None) is not None
    ]


def parse_assignments(option: str, items: list[str] | None) -> dict[str, float]:
    """``["R=1", "E_star=2.5"]`` -> ``{"R": 1.0, "E_star": 2.5}``, refusing anything else."""
    values: dict[str, float] = {}
    for item in items or []:
        name, equals, text = item.partition("=")
        name = name.strip()
        if not equals or not name:
            raise InputError(option, "must be NAME=VALUE", item)
        if name in values:
            raise InputError(option, f"{name} is given twice", item)
        try:
            values[name] = float(text)
        except ValueError:
            raise InputError(option, f"the value of {name} is not a number", item) from None
    return values
