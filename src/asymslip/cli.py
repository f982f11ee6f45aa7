"""The ``asymslip`` command line: a thin layer over the Python API.

Every command prints what the corresponding API call returns, so a notebook user and a shell
user get the same numbers.  Bad input gives one line naming the option, and exit status 2.
"""

from __future__ import annotations

import argparse
import json
import sys
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import NoReturn

from . import cli_extra
from .cycle import LoadCycle
from .edge_solution import VALIDITY_MEANING, SlipZoneResult, slip_zone
from .errors import InputError
from .laws import ContactLaw, FlatRoundedLaw, HertzLaw, PowerLaw
from .tractions import traction_difference

#: API parameter name -> the option that sets it, for error messages.
OPTION_OF = {
    "P1": "--P1", "Q1": "--Q1", "P2": "--P2", "Q2": "--Q2", "sigma1": "--sigma1",
    "sigma2": "--sigma2", "mu": "--mu", "R": "--R", "E_star": "--E-star", "law": "--law",
    "edge": "--edge", "x": "--x", "b": "--b", "c": "--flat-half-width", "A": "--A", "n": "--n",
}  # fmt: skip

LawBuilder = Callable[[argparse.Namespace], ContactLaw]


def _require_options(args: argparse.Namespace, law: str, names: Sequence[str]) -> None:
    for name in names:
        if getattr(args, name) is None:
            raise InputError(name, f"is required with --law {law}")


def _hertz(args: argparse.Namespace) -> ContactLaw:
    _require_options(args, "hertz", ["R", "E_star"])
    return HertzLaw(R=args.R, E_star=args.E_star)


def _flat_rounded(args: argparse.Namespace) -> ContactLaw:
    _require_options(args, "flat-rounded", ["c", "R", "E_star"])
    return FlatRoundedLaw(c=args.c, R=args.R, E_star=args.E_star)


def _power(args: argparse.Namespace) -> ContactLaw:
    _require_options(args, "power", ["A", "n", "E_star"])
    return PowerLaw(A=args.A, n=args.n, E_star=args.E_star)


LAWS: dict[str, LawBuilder] = {
    "hertz": _hertz,
    "flat-rounded": _flat_rounded,
    "power": _power,
    **cli_extra.LAWS,
}
OPTION_OF.update(cli_extra.OPTION_OF)


class _Parser(argparse.ArgumentParser):
    """argparse with one-line errors (no usage dump) and exit status 2."""

    def error(self, message: str) -> NoReturn:
        self.exit(2, f"{self.prog}: error: {message}\n")


def _add_law_options(parser: argparse.ArgumentParser) -> None:
    group = parser.add_argument_group("contact law")
    group.add_argument("--law", default="hertz", help="contact law (default: hertz); one of: "
                       + ", ".join(sorted(LAWS)))
    group.add_argument("--R", type=float,
                       help="cylinder radius (hertz) or corner radius (flat-rounded)")
    group.add_argument("--E-star", dest="E_star", type=float,
                       help="plane-strain modulus E* (hertz, flat-rounded, power)")
    group.add_argument("--flat-half-width", dest="c", type=float,
                       help="half-width c of the flat (flat-rounded)")
    group.add_argument("--A", type=float, help="profile coefficient A of h = A |x|^n (power)")
    group.add_argument("--n", type=float, help="profile exponent n >= 1 of h = A |x|^n (power)")
    cli_extra.add_law_options(group)


def _add_cycle_options(parser: argparse.ArgumentParser) -> None:
    group = parser.add_argument_group("load cycle (state 2 has the larger normal load)")
    for name, required, text in [
        ("P1", True, "normal load at state 1"), ("Q1", True, "shear force at state 1"),
        ("P2", True, "normal load at state 2 (> P1)"), ("Q2", True, "shear force at state 2"),
        ("sigma1", False, "bulk tension at state 1 (default 0)"),
        ("sigma2", False, "bulk tension at state 2 (default 0)"),
    ]:  # fmt: skip
        group.add_argument(f"--{name}", type=float, required=required,
                           default=None if required else 0.0, help=text)
    parser.add_argument("--mu", type=float, required=True, help="coefficient of friction (> 0)")


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(
        prog="asymslip",
        description="Steady-state partial slip at contact edges: slip-zone size, tractions "
        "and figures from the asymptotic corrective-slip solution (TAFM 2022, 103457).",
    )
    commands = parser.add_subparsers(dest="command", required=True, parser_class=_Parser)
    slip = commands.add_parser(
        "slip-zone",
        help="slip-zone size at the contact edges for one load cycle",
        description="Stick boundary b from (22), slip-zone width a1 - b, first-order b (28), "
        "exact b = a(P_K) when eta = 0, and the validity measures (24)-(27).",
    )
    _add_law_options(slip)
    _add_cycle_options(slip)
    slip.add_argument("--edge", choices=["right", "left", "both"], default="both",
                      help="which edge (default both: the right edge's keys at the top level "
                      "and the left edge's under 'left')")
    slip.add_argument("--json", action="store_true", help="print one JSON object")
    slip.set_defaults(run=_run_slip_zone)

    traction = commands.add_parser(
        "traction",
        help="shear-traction difference q2 - q1 near the right-hand edge",
        description="Asymptotic q_diff of (49), in closed form, and the exact (47) where the "
        "law has a pressure distribution and eta = 0, at the given positions x (measured from "
        "the contact centre, -a2 < x < a2).",
    )
    _add_law_options(traction)
    _add_cycle_options(traction)
    traction.add_argument("--x", type=float, nargs="+", required=True, metavar="X",
                          help="positions from the contact centre")
    traction.add_argument("--b", choices=["consistent", "exact"], default="consistent",
                          help="stick boundary in (15): consistent = (17)/(22) (default), "
                          "exact = a(P_K), the paper's choice for Fig. 5")
    traction.add_argument("--json", action="store_true", help="print one JSON object")
    traction.set_defaults(run=_run_traction)

    figure = commands.add_parser(
        "figure", help="draw one of the paper's figures",
        description="Write the paper's Fig. 5 (exact solid, asymptotic dashed) as PNG and CSV.",
    )  # fmt: skip
    figure.add_argument("name", choices=["fig5"], help="which figure")
    figure.add_argument("--out", type=Path, required=True, help="output folder")
    figure.set_defaults(run=_run_figure)
    cli_extra.register(commands, _add_law_options)
    return parser


def build_law(args: argparse.Namespace) -> ContactLaw:
    builder = LAWS.get(args.law)
    if builder is None:
        raise InputError("law", f"unknown contact law; choose one of {', '.join(sorted(LAWS))}",
                         args.law)
    return builder(args)


def build_cycle(args: argparse.Namespace) -> LoadCycle:
    return LoadCycle(args.P1, args.Q1, args.P2, args.Q2, args.sigma1, args.sigma2)


def _format_number(value: float | None) -> str:
    return "null" if value is None else f"{value:.12g}"


def format_table(result: SlipZoneResult, edge: str, law: str, mu: float) -> str:
    lines = [f"Slip zone at the {edge}-hand edge ({law} law, mu = {mu:g})"]
    for key, value in result.to_dict().items():
        if key in ("validity", "warnings", "left"):
            continue
        lines.append(f"  {key:<20} {_format_number(value)}")
    lines.append("  validity measures (each must be << 1):")
    for key, value in result.validity.items():
        lines.append(f"    {key}  {value:<10.4g} {VALIDITY_MEANING[key]}")
    lines.append("  warnings: " + ("none" if not result.warnings else ""))
    lines.extend(f"    - {warning}" for warning in result.warnings)
    return "\n".join(lines)


def _run_slip_zone(args: argparse.Namespace) -> int:
    law = build_law(args)
    result = slip_zone(law, build_cycle(args), args.mu, edge=args.edge)
    if args.json:
        print(json.dumps(result.to_dict(), indent=2))
        return 0
    if args.edge == "both":
        assert result.left is not None
        print(format_table(result, "right", law.name, args.mu))
        print(format_table(result.left, "left", law.name, args.mu))
    else:
        print(format_table(result, args.edge, law.name, args.mu))
    return 0


def _run_traction(args: argparse.Namespace) -> int:
    result = traction_difference(build_law(args), build_cycle(args), args.mu, args.x,
                                 stick_boundary=args.b)  # fmt: skip
    if args.json:
        print(json.dumps(result.to_dict(), indent=2))
        return 0
    print(f"q_diff = q2 - q1 at the right-hand edge (b = {result.b:.12g}, {args.b} choice)")
    print(f"  {'x':>20} {'q_diff (49)':>20} {'q_diff_exact (47)':>20}")
    exact = result.q_diff_exact or [None] * len(result.x)
    for x, q, q_exact in zip(result.x, result.q_diff, exact, strict=True):
        print(f"  {x:>20.12g} {q:>20.12g} {_format_number(q_exact):>20}")
    return 0


def _run_figure(args: argparse.Namespace) -> int:
    from .figures import write_fig5

    for path in write_fig5(args.out):
        print(path)
    return 0


def main(argv: Sequence[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        return int(args.run(args))
    except InputError as error:
        option = OPTION_OF.get(error.parameter, error.parameter)
        message = str(error).removeprefix(f"{error.parameter}: ")
        print(f"asymslip: error: {option}: {message}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
