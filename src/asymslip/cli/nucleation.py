"""``asymslip nucleation``: where and how hard each edge fatigues, for the user's material.

Solves the cycle with the reference solver (the criteria need the stress at both extremes of
the cycle, which the edge asymptote does not give) and reports, per edge and criterion, the
peak and -- with ``--L`` -- the point and line methods of the theory of critical distances,
each with its value, location and critical-plane angle.  Conventions: ``asymslip.stress``.
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
    from ..nucleation import Criterion, NucleationResult

UNITS = {
    "swt": "stress x strain",
    "fs": "strain",
    "findley": "stress",
    "frictional_work": "force/length",
    "ruiz": "force^2/length^3",
}


def register(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    from ..solver import DEFAULT_ELEMENTS

    parser = commands.add_parser(
        "nucleation",
        help="crack-nucleation parameters near each edge (Ruiz, SWT, Fatemi-Socie, Findley)",
        description="The crack-nucleation parameters near both edges of the steady cycle, "
        "from the reference solver: Ruiz's tau delta and sigma_T tau delta along the surface; "
        "Smith-Watson-Topper sigma_n,max eps_a, Fatemi-Socie gamma_a (1 + k sigma_n,max/"
        "sigma_y) and Findley tau_a + k sigma_n,max on the critical plane (searched over the "
        "planes through each point); with --L the critical distances' point (L/2) and line "
        "(over 2L) methods below the surface hot spot.  Each with value, location (x, depth) "
        "and plane angle (the normal's, from +x towards the depth, in degrees).",
    )
    add_law_options(parser)
    add_cycle_options(parser)
    material = parser.add_argument_group("the lower body's material")
    material.add_argument("--E", type=number, required=True, help="Young's modulus")
    material.add_argument("--nu", type=number, required=True, help="Poisson's ratio")
    material.add_argument("--sigma-y", dest="sigma_y", type=number, help="yield stress (fs)")
    material.add_argument(
        "--k", type=number, help="the criterion constant k of findley (and of fs)"
    )
    material.add_argument(
        "--k-fs", dest="k_fs", type=number, help="fs's own k, when it differs from findley's"
    )
    material.add_argument("--L", type=number, help="the critical distance")
    parser.add_argument(
        "--criteria",
        default=None,
        help="comma-separated, from ruiz,swt,fs,findley (default: every one whose constants "
        "are given)",
    )
    parser.add_argument(
        "--elements",
        type=whole_number,
        default=DEFAULT_ELEMENTS,
        help=f"solver elements (default {DEFAULT_ELEMENTS})",
    )
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    parser.add_argument(
        "--out", type=Path, metavar="DIR", help="write nucleation.png and nucleation.csv there"
    )
    parser.set_defaults(run=run)


def _criteria(args: argparse.Namespace) -> tuple[Criterion, ...]:
    from ..nucleation import criteria_from_names

    if args.criteria is not None:
        return criteria_from_names([name.strip() for name in args.criteria.split(",")])
    names = ["ruiz", "swt"]
    if args.sigma_y is not None and (args.k_fs or args.k) is not None:
        names.append("fs")
    if args.k is not None:
        names.append("findley")
    return criteria_from_names(names)


def run(args: argparse.Namespace) -> int:
    from ..nucleation import Material, nucleation
    from ..rules import Verdict, check_friction, check_partial_slip
    from ..solver import SolverError, solve

    law, cycle = build_law(args), build_cycle(args)
    material = Material(
        E=args.E,
        nu=args.nu,
        sigma_y=args.sigma_y,
        k_findley=args.k,
        k_fatemi_socie=args.k_fs if args.k_fs is not None else args.k,
        L=args.L,
    )
    criteria = _criteria(args)
    for criterion in criteria:
        material.require(criterion)
    if not hasattr(law, "profile"):
        raise InputError(
            "law",
            f"the {law.name} law has no profile for the solver: use hertz, flat-rounded or power",
        )
    verdict = Verdict(())
    check_friction(verdict, args.mu)
    check_partial_slip(verdict, args.mu, cycle.values())
    verdict.raise_first()
    try:
        result = solve(law, cycle, args.mu, elements=args.elements)
    except SolverError as error:
        raise InputError("cycle", f"the reference solver did not converge: {error}") from None
    found = nucleation(result, material, criteria)
    warnings = list(found.warnings)
    E_star = getattr(law, "E_star", None)
    if E_star is not None:
        implied = material.E / (2 * (1 - material.nu**2))
        if not np.isclose(E_star, implied, rtol=1e-6):
            warnings.append(
                f"--E and --nu give E* = E/(2 (1 - nu^2)) = {implied:.6g} for two similar "
                f"bodies, but the law's --E-star is {E_star:.6g}: the strains use E and nu, the "
                "contact the law's E*"
            )
    if args.out is not None:
        from ..nucleation.output import write_outputs

        for path in write_outputs(found, args.out):
            print(f"wrote {path}", file=sys.stderr)
    data = found.to_dict()
    data["warnings"] = warnings
    if args.json:
        print(json.dumps(data, indent=2))
        return 0
    print(_summary(found, warnings))
    return 0


def _summary(found: NucleationResult, warnings: list[str]) -> str:
    lines = []
    for edge in ("right", "left"):
        lines.append(f"{edge}-hand edge:")
        for finding in found.findings:
            if finding.edge != edge:
                continue
            angle = "" if finding.angle is None else f", plane {finding.angle:.2f} deg"
            label = finding.criterion if finding.criterion != "ruiz" else finding.method
            method = "" if finding.criterion == "ruiz" else f" {finding.method}"
            lines.append(
                f"  {label}{method}: {finding.value:.6g} [{UNITS.get(label, '')}] at x = "
                f"{finding.x:.6g}, depth {finding.depth:.6g}{angle}"
            )
    lines.append(
        "warnings: " + ("none" if not warnings else "\n" + "\n".join(f"  - {w}" for w in warnings))
    )
    return "\n".join(lines)
