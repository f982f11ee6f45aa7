"""``asymslip derive``: a contact law P(a) typed as a formula, derived into a law module."""

from __future__ import annotations

import argparse
from pathlib import Path

from .laws import parse_assignments
from .parser import number


def register(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    derive = commands.add_parser(
        "derive",
        help="derive a contact law P(a) given as a formula into a law module",
        description="Parse P(a), differentiate it, apply the calibration (19) and write a "
        "NumPy module (use it with --law module --module FILE --param NAME=VALUE).  The "
        "half-width a and every parameter are taken to be positive real numbers (moduli, "
        "radii, coefficients): write a negative coefficient with its minus sign.  A law that "
        "provably decreases, or is nowhere positive where it increases, is refused; otherwise "
        "the range of a and of the load where it is positive and increasing is established "
        "symbolically where SymPy can and recorded in the module.  Needs SymPy (the derive "
        "extra).",
    )
    derive.add_argument(
        "--P-of-a",
        dest="P_of_a",
        required=True,
        metavar="EXPR",
        help='the normal load as a formula in a, e.g. "pi*E_star*a**2/(4*R)"',
    )
    derive.add_argument(
        "--params",
        default="",
        metavar='"NAME ..."',
        help="the formula's parameters, space- or comma-separated, in order",
    )
    derive.add_argument("--name", required=True, help="name of the law (a Python identifier)")
    derive.add_argument(
        "--out", required=True, type=Path, metavar="FILE.py", help="module file to write"
    )
    derive.add_argument(
        "--check",
        action="append",
        metavar="NAME=VALUE",
        help="parameter value for checking dP/da > 0 now (repeat)",
    )
    derive.add_argument(
        "--check-a",
        dest="check_a",
        type=number,
        nargs="+",
        default=[],
        metavar="A",
        help="half-widths at which dP/da > 0 is checked",
    )
    derive.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from ..codegen.law_module import write_law_module

    params = [name for name in args.params.replace(",", " ").split() if name]
    written = write_law_module(
        args.P_of_a,
        params,
        args.name,
        args.out,
        check=parse_assignments("check", args.check),
        check_half_widths=args.check_a,
    )
    out = written.path
    settings = " ".join(f"--param {name}=VALUE" for name in params)
    print(f"wrote {out}: load, load_slope, normal_edge_multiplier, normal_edge_multiplier_slope")
    print(written.range_summary)
    print(f"use it with: --law module --module {out} {settings}".rstrip())
    return 0
