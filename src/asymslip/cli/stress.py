"""``asymslip stress``: the stress field near a contact edge, from the solver or the asymptote.

The points are the grid of every ``--x`` with every ``--depth``.  ``--source solver`` (the
default) solves the cycle numerically and gives both states and their difference;
``--source asymptote`` gives the amplitude (state 2 minus state 1) near one edge from the edge
asymptotes (4), (49), each value with its stated accuracy, without a solver.  Conventions:
``asymslip.stress``.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from ..errors import InputError
from .cycle_options import add_cycle_options, build_cycle
from .laws import add_law_options, build_law
from .parser import number, whole_number

if TYPE_CHECKING:  # the command's own imports are lazy, for a fast start
    from ..stress.field import CycleStress

SOURCES = ("solver", "asymptote")


def register(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    from ..solver import DEFAULT_ELEMENTS

    stress = commands.add_parser(
        "stress",
        help="the stress field near a contact edge (solver or edge asymptote)",
        description="Plane-strain stresses sxx, syy (normal to the surface), sxy in the lower "
        "body (depth into it; tension positive; the bulk tension in sxx) at every --x with "
        "every --depth.  --source solver: both extremes of the steady cycle and their "
        "difference, from the reference solver's tractions; --source asymptote: the "
        "amplitude (state 2 minus state 1) near one --edge from the edge asymptotes (4) and "
        "(49), each value with its stated accuracy and whether the point is near enough to "
        "the edge.  --out FILE.csv|.parquet writes the table in pyLife's column names "
        "(S11, S22, S33, S12, S13, S23); --out DIR draws the field and writes stress.csv.",
    )
    add_law_options(stress)
    add_cycle_options(stress)
    points = stress.add_argument_group("the points (every x with every depth)")
    points.add_argument(
        "--x",
        type=number,
        nargs="+",
        required=True,
        metavar="X",
        help="positions along the surface from the contact centre",
    )
    points.add_argument(
        "--depth",
        type=number,
        nargs="+",
        required=True,
        metavar="Y",
        help="depths below the surface (>= 0; 0 is the surface)",
    )
    stress.add_argument(
        "--source", choices=SOURCES, default="solver", help="solver (default) or asymptote"
    )
    stress.add_argument(
        "--edge",
        choices=["right", "left"],
        default="right",
        help="the edge of the asymptote (and of the picture); default right",
    )
    stress.add_argument(
        "--elements",
        type=whole_number,
        default=None,
        help=f"solver elements (default {DEFAULT_ELEMENTS}; --source solver only)",
    )
    stress.add_argument(
        "--nu",
        type=number,
        default=None,
        help="Poisson's ratio, for the out-of-plane S33 = nu (S11 + S22) of the table",
    )
    stress.add_argument("--json", action="store_true", help="print one JSON object")
    stress.add_argument(
        "--out",
        type=Path,
        metavar="FILE|DIR",
        help="a table (.csv or .parquet), or a folder for stress.png and stress.csv",
    )
    stress.set_defaults(run=run)


def _field(args: argparse.Namespace) -> CycleStress:
    law, cycle = build_law(args), build_cycle(args)
    x = np.asarray(args.x, dtype=float)
    depth = np.asarray(args.depth, dtype=float)
    X, Y = np.meshgrid(x, depth, indexing="ij")
    if args.nu is not None and not (0 < args.nu < 0.5):
        raise InputError("nu", "must be a Poisson's ratio with 0 < nu < 0.5", args.nu)
    if args.source == "asymptote":
        from ..stress.asymptote import edge_amplitude

        if args.elements is not None:
            raise InputError("elements", "applies to --source solver only")
        return edge_amplitude(law, cycle, args.mu, X.ravel(), Y.ravel(), edge=args.edge)
    from ..rules import Verdict, check_friction, check_partial_slip
    from ..solver import DEFAULT_ELEMENTS, SolverError, solve
    from ..stress.solver_source import solver_stress

    if not hasattr(law, "profile"):
        raise InputError(
            "law",
            f"the {law.name} law has no profile for the solver: use hertz, flat-rounded or "
            "power, or --source asymptote",
        )
    verdict = Verdict(())
    check_friction(verdict, args.mu)
    check_partial_slip(verdict, args.mu, cycle.values())
    verdict.raise_first()
    if np.any(Y < 0):
        raise InputError("depth", "must be >= 0 (depth into the lower body)")
    try:
        result = solve(law, cycle, args.mu, elements=args.elements or DEFAULT_ELEMENTS)
    except SolverError as error:
        raise InputError("cycle", f"the reference solver did not converge: {error}") from None
    return solver_stress(result, X.ravel(), Y.ravel())


def run(args: argparse.Namespace) -> int:
    field = _field(args)
    if args.out is not None:
        _write(field, args)
    if args.json:
        print(json.dumps(field.to_dict(), indent=2))
        return 0
    print(_summary(field))
    return 0


def _write(field: CycleStress, args: argparse.Namespace) -> None:
    from ..stress.output import draw, write_table

    target = Path(args.out)
    if target.suffix.lower() in (".csv", ".parquet"):
        written = [write_table(field, target, nu=args.nu)]
    elif target.suffix:
        raise InputError(
            "out",
            f"{target}: a table must end in .csv or .parquet (got {target.suffix!r}); "
            "a folder gets stress.png and stress.csv",
        )
    else:
        if target.exists() and not target.is_dir():
            raise InputError("out", f"{target} exists and is not a folder")
        target.mkdir(parents=True, exist_ok=True)
        title = f"{field.source}: {args.edge} edge" if field.source == "asymptote" else "solver"
        written = [
            draw(field, target / "stress.png", title=title),
            write_table(field, target / "stress.csv", nu=args.nu),
        ]
    for path in written:
        print(f"wrote {path}", file=sys.stderr)


def _summary(field: CycleStress) -> str:
    """One line per point: the amplitude (and the accuracy) or the states."""
    shown = field.amplitude if field.amplitude is not None else field.states[-1]
    what = "amplitude (state 2 - state 1)" if field.amplitude is not None else "last state"
    header = ["x", "depth", "sxx", "syy", "sxy"]
    if field.accuracy is not None:
        header += ["accuracy", "near edge"]
    lines = [f"stress from the {field.source}: {what}, tension positive"]
    lines.append("  " + "  ".join(f"{h:>14}" for h in header))
    for i in range(field.count):
        row = [field.x[i], field.depth[i], shown.sxx[i], shown.syy[i], shown.sxy[i]]
        cells = [f"{value:14.7g}" for value in row]
        if field.accuracy is not None:
            near = field.near_edge is not None and bool(field.near_edge[i])
            cells += [f"{field.accuracy[i]:14.3g}", f"{'yes' if near else 'no':>14}"]
        lines.append("  " + "  ".join(cells))
    lines.append(
        "warnings: "
        + ("none" if not field.warnings else "\n" + "\n".join(f"  - {w}" for w in field.warnings))
    )
    return "\n".join(lines)
