"""Command-line pieces for ``derive``, ``sweep`` and the ``table`` / ``module`` contact laws.

``cli.py`` wires them in: :data:`LAWS` and :data:`OPTION_OF` join its registries,
:func:`add_law_options` adds the laws' options to its "contact law" group, and
:func:`register` adds the two commands.  Nothing here imports ``cli`` at import time.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable
from pathlib import Path

from .errors import InputError, positive
from .laws.base import ContactLaw

#: API parameter name -> the option that sets it, for error messages (joins cli.OPTION_OF).
OPTION_OF = {
    "table": "--table", "module": "--module", "param": "--param", "P_of_a": "--P-of-a",
    "params": "--params", "name": "--name", "out": "--out", "check": "--check",
    "cases": "CASES", "derive": "derive", "chunk_rows": "--chunk-rows", "workers": "--workers",
}  # fmt: skip


def _table(args: argparse.Namespace) -> ContactLaw:
    from .laws.table import TableLaw

    if args.table is None:
        raise InputError("table", "is required with --law table (a CSV with columns P, a)")
    return TableLaw.from_csv(args.table)


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


def _module(args: argparse.Namespace) -> ContactLaw:
    from .laws.module_law import ModuleLaw

    if args.module is None:
        raise InputError("module", "is required with --law module (a file from asymslip derive)")
    return ModuleLaw.from_file(args.module, **parse_assignments("param", args.param))


#: Law builders (join cli.LAWS).
LAWS: dict[str, Callable[[argparse.Namespace], ContactLaw]] = {
    "table": _table,
    "module": _module,
}


def add_law_options(group: argparse._ArgumentGroup) -> None:
    """The options of the table and module laws, for cli's "contact law" group."""
    group.add_argument(
        "--table",
        type=Path,
        metavar="FILE.csv",
        help="table law: CSV with a header and columns P, a (e.g. from FE)",
    )
    group.add_argument(
        "--module",
        type=Path,
        metavar="FILE.py",
        help="module law: a file written by `asymslip derive`",
    )
    group.add_argument("--param", action="append", metavar="NAME=VALUE",
                       help="module law: a parameter value (repeat for each)")  # fmt: skip


def register(commands: argparse._SubParsersAction,
             add_law_options: Callable[[argparse.ArgumentParser], None]) -> None:  # fmt: skip
    """Add ``derive`` and ``sweep`` to cli's subcommands.

    ``add_law_options`` is cli's own (so ``sweep`` takes every law ``slip-zone`` takes).
    """
    derive = commands.add_parser(
        "derive",
        help="derive a contact law P(a) given as a formula into a law module",
        description="Parse P(a), differentiate it, apply the calibration (19) and write a "
        "NumPy module (use it with --law module --module FILE --param NAME=VALUE).  Needs "
        "SymPy (the derive extra).",
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
        type=float,
        nargs="+",
        default=[],
        metavar="A",
        help="half-widths at which dP/da > 0 is checked",
    )
    derive.set_defaults(run=run_derive)  # fmt: skip

    sweep = commands.add_parser(
        "sweep",
        help="slip zone of every load cycle in a CSV file",
        description="One cycle per row (columns P1, Q1, P2, Q2; optional sigma1, sigma2, mu; "
        "other columns are copied).  Writes every slip-zone quantity per row; a row that "
        "breaks a rule gets its reason in the error column and the others go on.  Exit "
        "status 1 when some rows were invalid.",
    )
    sweep.add_argument("cases", type=Path, metavar="CASES.csv", help="the load cycles")
    add_law_options(sweep)
    sweep.add_argument("--mu", type=float, help="coefficient of friction for rows without mu")
    sweep.add_argument(
        "--edge",
        choices=["right", "left", "both"],
        default="both",
        help="which edge (default both; left-edge columns are prefixed left_)",
    )
    sweep.add_argument(
        "--out", required=True, type=Path, metavar="RESULTS.csv", help="the result CSV"
    )
    sweep.add_argument(
        "--chunk-rows",
        dest="chunk_rows",
        type=int,
        default=100_000,
        help="rows evaluated at once (default 100000)",
    )
    sweep.add_argument(
        "--workers",
        type=int,
        default=None,
        help="processes evaluating chunks at once (default: every CPU available)",
    )
    sweep.set_defaults(run=run_sweep)  # fmt: skip


def run_derive(args: argparse.Namespace) -> int:
    from .user_law import derive_law_module

    params = [name for name in args.params.replace(",", " ").split() if name]
    out = derive_law_module(args.P_of_a, params, args.name, args.out,
                            check=parse_assignments("check", args.check),
                            check_half_widths=args.check_a)  # fmt: skip
    settings = " ".join(f"--param {name}=VALUE" for name in params)
    print(f"wrote {out}: load, load_slope, normal_edge_multiplier, normal_edge_multiplier_slope")
    print(f"use it with: --law module --module {out} {settings}".rstrip())
    return 0


def run_sweep(args: argparse.Namespace) -> int:
    from .cli import build_law
    from .sweep import sweep_file

    if args.chunk_rows < 1:
        raise InputError("chunk_rows", "must be >= 1", args.chunk_rows)
    if args.mu is not None:
        positive("mu", args.mu)  # a bad default is one error, not one per row
    law = build_law(args)
    if args.workers is not None and args.workers < 1:
        raise InputError("workers", "must be >= 1", args.workers)
    summary = sweep_file(args.cases, law, args.out, mu=args.mu, edge=args.edge,
                         chunk_rows=args.chunk_rows, workers=args.workers)  # fmt: skip
    print(summary.report(), file=sys.stderr)
    return 1 if summary.invalid else 0
