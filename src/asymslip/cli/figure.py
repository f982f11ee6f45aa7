"""``asymslip figure``: the paper's figures and the error map, and the freshness check of their
committed data."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from ..errors import InputError
from ..files.collisions import Input, Output, refuse_overwriting_inputs

FIGURES = ("fig5", "error-map")


def register(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    figure = commands.add_parser(
        "figure",
        help="draw one of the paper's figures, or the error map",
        description="fig5: write the paper's Fig. 5 (exact solid, asymptotic dashed) as PNG and "
        "CSV into a folder, or check that the folder's fig5.csv is what would be written now.  "
        "error-map: run the reference solver over the error map (about two minutes) and write "
        "error_map.csv (into --data) and error_map.png (into --out); or redraw the PNG from the "
        "CSV (--redraw); or recompute a few rows (--check DIR, every row with --every-row) and "
        "compare them with DIR/error_map.csv at its printed precision.",
    )
    figure.add_argument(
        "name", choices=FIGURES, metavar="FIGURE", help="which figure: fig5 or error-map"
    )  # an error names FIGURE
    where = figure.add_mutually_exclusive_group(required=True)
    where.add_argument("--out", type=Path, metavar="DIR", help="output folder")
    where.add_argument(
        "--check",
        type=Path,
        metavar="DIR",
        help="compare DIR's committed data with a fresh evaluation; exit 1 if stale",
    )
    figure.add_argument(
        "--data",
        type=Path,
        metavar="DIR",
        help="error-map: folder of error_map.csv (default: --out)",
    )
    figure.add_argument(
        "--redraw",
        action="store_true",
        help="error-map: draw the PNG from the CSV in --data, without the solver",
    )
    figure.add_argument(
        "--every-row",
        action="store_true",
        help="error-map with --check: recompute every row, not only a few",
    )
    figure.set_defaults(run=run)


def _refuse(option: str, rule: str) -> int:
    print(f"asymslip: error: {option}: {rule}", file=sys.stderr)
    return 2


def run(args: argparse.Namespace) -> int:
    if args.name == "fig5":
        for option, given in (
            ("--data", args.data),
            ("--redraw", args.redraw),
            ("--every-row", args.every_row),
        ):
            if given:
                return _refuse(option, "applies to the error map only")
        return _fig5(args)
    if args.check is not None and (args.data is not None or args.redraw):
        return _refuse(
            "--data" if args.data is not None else "--redraw",
            "is for writing the map; --check reads DIR/error_map.csv",
        )
    if args.out is not None and args.every_row:
        return _refuse("--every-row", "applies to --check only")
    return _error_map(args)


def _fig5(args: argparse.Namespace) -> int:
    from ..figures import stale_fig5_lines, write_fig5

    if args.check is not None:
        committed = args.check / "fig5.csv"
        if not committed.is_file():  # nothing to compare: not "stale", a wrong folder
            raise InputError(
                "check",
                f"{committed} does not exist: give the folder that holds "
                "the fig5.csv to check (write one with --out)",
            )
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


def _error_map(args: argparse.Namespace) -> int:
    from ..figures import ERROR_MAP_CSV, ERROR_MAP_PNG, stale_error_map_lines, write_error_map
    from ..files.progress import Progress
    from ..solver.error_map import map_cases

    if args.check is not None:
        path = args.check / ERROR_MAP_CSV
        if not path.is_file():  # nothing to compare: not "stale", a wrong folder
            raise InputError(
                "check",
                f"{path} does not exist: give the folder that holds the "
                "error_map.csv to check (write one with --out)",
            )
        problems = stale_error_map_lines(args.check, every_row=args.every_row)
        if problems:
            print("\n".join(problems))
            print(f"{path} is stale: run `make error-map`", file=sys.stderr)
            return 1
        rows = "every row" if args.every_row else "the check rows"
        print(f"{path}: fresh ({rows} recomputed)")
        return 0
    if args.redraw:
        data = args.data if args.data is not None else args.out
        refuse_overwriting_inputs(
            [Input(data / ERROR_MAP_CSV, "data", "the error map's data")],
            [Output(args.out, "out", (ERROR_MAP_PNG,))],
        )
        paths = write_error_map(args.out, args.data, redraw=True)
    else:
        with Progress(len(map_cases()), label="error map (cycles)") as bar:
            paths = write_error_map(
                args.out, args.data, progress=lambda done, _total: bar.update(done)
            )
    for path in paths:
        print(f"wrote {path}", file=sys.stderr)
    return 0
