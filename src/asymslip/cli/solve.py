"""``asymslip solve``: the reference solver on a law's profile (or a typed or tabulated one).

The paper's cycle from the same options as ``slip-zone``, or any piecewise-linear path of
(P, Q, sigma, M) points from a CSV file, solved numerically to its steady state; the JSON has,
like ``slip-zone``'s, the right edge at the top level and the left edge under ``left``, each
with the solver's stick boundary ``b``, its bound ``b_error`` and every ``slip-zone`` estimate
with its difference from the solver in elements.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path
from typing import Any

from ..cycle import LoadCycle
from ..errors import InputError
from ..files.collisions import Input, Output, refuse_overwriting_inputs
from ..rules import Verdict, check_friction, check_partial_slip
from .laws import add_law_options, build_law, law_inputs, parse_assignments
from .parser import number, whole_number


def register(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    from ..solver import DEFAULT_ELEMENTS, DEFAULT_STEPS

    solve = commands.add_parser(
        "solve",
        help="the reference numerical solver: the steady partial-slip cycle of a profile",
        description="Incremental half-plane frictional contact (plane strain, Coulomb friction, "
        "history-dependent stick and slip) on a uniform grid, run period after period to the "
        "steady state.  The contact is the law's profile (hertz, flat-rounded, power), a "
        "profile typed as --profile EXPR (needs the derive extra) or tabulated in "
        "--profile-table FILE.csv (columns x, h), with --E-star.  Every stick boundary comes "
        "with an error bound of at least one element, and is set beside every asymptotic "
        "estimate of slip-zone (for a built-in law and the paper's cycle).",
    )
    add_law_options(solve)
    profile = solve.add_argument_group("a profile instead of a law")
    profile.add_argument(
        "--profile",
        metavar="EXPR",
        help='the gap h(x) as a formula in x, e.g. "x**2/(2*R) + k*x**3"; '
        "parameter values with --param NAME=VALUE",
    )
    profile.add_argument(
        "--profile-table",
        dest="profile_table",
        type=Path,
        metavar="FILE.csv",
        help="the gap h(x) tabulated: a CSV with a header naming x and h",
    )
    cycle = solve.add_argument_group(
        "load cycle (the paper's, as slip-zone; or --path for any path)"
    )
    for name, text in (
        ("P1", "normal load at state 1"),
        ("Q1", "shear force at state 1"),
        ("P2", "normal load at state 2 (> P1)"),
        ("Q2", "shear force at state 2"),
        ("sigma1", "bulk tension at state 1 (default 0)"),
        ("sigma2", "bulk tension at state 2 (default 0)"),
    ):
        cycle.add_argument(f"--{name}", type=number, help=text)
    cycle.add_argument(
        "--path",
        type=Path,
        metavar="PATH.csv",
        help="a closed load path instead: points P,Q[,sigma,M] repeated until "
        "the steady state (after P and M are applied with Q = sigma = 0)",
    )
    solve.add_argument("--mu", type=number, required=True, help="coefficient of friction (> 0)")
    grid = solve.add_argument_group("the solver")
    grid.add_argument(
        "--elements",
        type=whole_number,
        default=DEFAULT_ELEMENTS,
        help=f"elements of the grid (default {DEFAULT_ELEMENTS})",
    )
    grid.add_argument(
        "--steps",
        type=whole_number,
        default=DEFAULT_STEPS,
        help=f"load steps per segment of the path (default {DEFAULT_STEPS})",
    )
    grid.add_argument(
        "--refine",
        action="store_true",
        help="solve on N, 2N and 4N elements and extrapolate each boundary",
    )
    solve.add_argument("--json", action="store_true", help="print one JSON object")
    solve.add_argument(
        "--out",
        type=Path,
        metavar="DIR",
        help="write tractions.csv, slip.csv, energy.csv and solver.png there",
    )
    solve.add_argument(
        "--no-plot",
        dest="plot",
        action="store_false",
        help="with --out, write the CSV files only (no solver.png; matplotlib not needed)",
    )
    solve.set_defaults(run=run)


def _contact(args: argparse.Namespace) -> tuple[Any, Any | None]:
    """(the contact the solver works on: a law or a profile; the law for the asymptotes or None)."""
    from ..solver import ExpressionProfile, TableProfile

    if args.profile is not None and args.profile_table is not None:
        raise InputError("profile", "give either --profile or --profile-table, not both")
    if args.profile is not None:
        return ExpressionProfile(args.profile, parse_assignments("param", args.param)), None
    if args.profile_table is not None:
        try:
            return TableProfile.from_csv(args.profile_table), None
        except InputError as error:  # the API names its profile; here it is --profile-table
            if error.parameter != "profile":
                raise
            raise InputError("profile_table", error.rule, error.value, error.where) from None
    law = build_law(args)
    if not hasattr(law, "profile"):
        raise InputError(
            "law",
            f"the {law.name} law has no profile for the solver: use "
            "hertz, flat-rounded or power, or give --profile or --profile-table",
        )
    return law, law


def _loading(args: argparse.Namespace) -> tuple[object, LoadCycle | None]:
    """(the solver's loading, the paper's cycle or None)."""
    from ..solver import LoadPath

    given = [name for name in ("P1", "Q1", "P2", "Q2") if getattr(args, name) is not None]
    if args.path is not None:
        if given:
            raise InputError("path", "give either --path or the cycle's --P1 --Q1 --P2 --Q2")
        return LoadPath.from_csv(args.path), None
    missing = [f"--{name}" for name in ("P1", "Q1", "P2", "Q2") if getattr(args, name) is None]
    if missing:
        raise InputError("cycle", f"needs {' '.join(missing)} (or --path PATH.csv)")
    cycle = LoadCycle(args.P1, args.Q1, args.P2, args.Q2, args.sigma1 or 0.0, args.sigma2 or 0.0)
    # Gross sliding by the rules slip-zone applies, naming --Q1/--Q2 as typed (the solver's
    # own check names the points of a --path).
    verdict = Verdict(())
    check_friction(verdict, args.mu)
    check_partial_slip(verdict, args.mu, cycle.values())
    verdict.raise_first()
    return cycle, cycle


def run(args: argparse.Namespace) -> int:
    from ..solver import RefinementResult, SolverError, refine, solve, write_outputs
    from ..solver.compare import with_asymptotes
    from ..solver.outputs import FILES

    reads = [Input(args.path, "path", "the load path")] if args.path is not None else []
    if args.profile_table is not None:
        reads.append(Input(args.profile_table, "profile_table", "the profile table"))
    written = Output(args.out, "out", FILES) if args.out is not None else None
    refuse_overwriting_inputs([*reads, *law_inputs(args)], [written])
    contact, law = _contact(args)
    loading, cycle = _loading(args)
    E_star = args.E_star if law is None else None
    if law is None and E_star is None:
        raise InputError("E_star", "is required with --profile or --profile-table")
    options = {"elements": args.elements, "steps": args.steps, "E_star": E_star}
    try:
        result = (
            refine(contact, loading, args.mu, **options)
            if args.refine
            else solve(contact, loading, args.mu, **options)
        )
    except SolverError as error:  # not the input's fault: one line, and the failure status
        print(f"asymslip: error: the reference solver did not converge: {error}", file=sys.stderr)
        return 1
    if law is not None and cycle is not None:
        result = with_asymptotes(result, law, cycle, args.mu)
    if args.out is not None:
        final = result.finest if isinstance(result, RefinementResult) else result
        for path in write_outputs(final, args.out, png=args.plot):
            print(f"wrote {path}", file=sys.stderr)
    data = result.to_dict()
    if args.json:
        print(json.dumps(data, indent=2))
        return 0
    print(_summary(data))
    return 0


def _summary(data: dict[str, Any]) -> str:
    """The human-readable report: each edge's boundary, bound and the estimates beside it."""
    lines = []
    for name, edge in (("right", data), ("left", data.get("left") or {})):
        if "b" not in edge:
            continue
        b = "null" if edge["b"] is None else f"{edge['b']:.9g}"
        bound = "null" if edge.get("b_error") is None else f"{edge['b_error']:.3g}"
        lines.append(
            f"{name}-hand edge: stick boundary b = {b} +- {bound} "
            f"(slip direction {edge.get('slip_direction')})"
        )
        for key, entry in (edge.get("asymptotes") or {}).items():
            if entry is None:
                lines.append(f"  {key:<20} does not exist for this cycle")
                continue
            lines.append(
                f"  {key:<20} {entry['value']:.9g}  ({entry['elements']:+.2f} elements "
                "from the solver)"
            )
    for warning in data.get("warnings", []):
        lines.append(f"warning: {warning}")
    return "\n".join(lines)
