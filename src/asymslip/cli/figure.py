"""``asymslip figure``: the paper's figures, and the freshness check of their committed data."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from ..errors import InputError


def register(commands: argparse._SubParsersAction) -> None:
    figure = commands.add_parser(
        "figure", help="draw one of the paper's figures",
        description="Write the paper's Fig. 5 (exact solid, asymptotic dashed) as PNG and CSV "
        "into a folder, or check that the folder's fig5.csv is what would be written now.",
    )  # fmt: skip
    figure.add_argument("name", choices=["fig5"], metavar="FIGURE",
                        help="which figure: fig5")  # an error names FIGURE, as usage shows it
    where = figure.add_mutually_exclusive_group(required=True)
    where.add_argument("--out", type=Path, metavar="DIR", help="output folder")
    where.add_argument("--check", type=Path, metavar="DIR",
                       help="compare DIR/fig5.csv with a fresh evaluation; exit 1 if stale")
    figure.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from ..figures import stale_fig5_lines, write_fig5

    if args.check is not None:
        committed = args.check / "fig5.csv"
        if not committed.is_file():  # nothing to compare: not "stale", a wrong folder
            raise InputError("check", f"{committed} does not exist: give the folder that holds "
                             "the fig5.csv to check (write one with --out)")  # fmt: skip
        diff = stale_fig5_lines(args.check)
        if diff:
            sys.stdout.writelines(diff)
            print(f"{args.check / 'fig5.csv'} is stale: run `make figures`", file=sys.stderr)
            return 1
        print(f"{args.check / 'fig5.csv'}: fresh")
        return 0
    for path in write_fig5(args.out):
        print(f"wrote {path}", file=sys.stderr)
    return 0
