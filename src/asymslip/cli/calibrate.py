"""``asymslip calibrate``: each edge's law a(P) and multiplier L_I from nodal pressure traces."""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from .parser import number


def register(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    calibrate = commands.add_parser(
        "calibrate",
        help="calibrate each contact edge from pressure traces (e.g. from a finite-element run)",
        description="Read nodal contact pressures in long format (columns P, x, p; optional "
        "side; one row per node per load, two or more loads), an FE path report (x or arc "
        "length and CPRESS, with --loads), CalculiX results (.frd with CONTACT output, or the "
        ".dat of *CONTACT PRINT beside its .frd or .inp: each step's load from the reaction "
        "force of a node set where the file has one, else --loads) or a mesh file meshio "
        "reads (.vtu, .vtk, .xdmf, ...; the pressure field named by --field), fit each "
        "edge's position a and multiplier L_I of (4) near the edge with the next term of "
        "the expansion, and build each edge's law a(P), L_I(P) with error estimates.  Use the "
        "saved calibration with --law calibrated --calibration FILE.json in slip-zone, "
        "traction and sweep.",
    )
    calibrate.add_argument("traces", type=Path, metavar="TRACES", help="the pressure traces")
    calibrate.add_argument(
        "--loads",
        type=number,
        nargs="+",
        metavar="P",
        help="the load of each trace of an FE report, or of each step of an FE result that "
        "does not give it (in file order)",
    )
    calibrate.add_argument(
        "--field",
        metavar="NAME",
        help="a mesh file's nodal pressure field (default CPRESS; fields NAME_1, NAME-2, ... "
        "are one load each)",
    )
    calibrate.add_argument(
        "--origin",
        type=number,
        metavar="X",
        help="the point b and a are measured from (default: the contact "
        "centre at the smallest load)",
    )
    calibrate.add_argument(
        "--noise",
        type=number,
        metavar="S",
        help="the pressure noise, if known (default: estimated from the data)",
    )
    calibrate.add_argument("--json", action="store_true", help="print one JSON object")
    calibrate.add_argument(
        "--out",
        type=Path,
        metavar="FILE.json",
        help="save the calibration (for --law calibrated --calibration)",
    )
    calibrate.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from ..calibration import calibrate, read_traces
    from ..calibration.report import checks, format_calibration
    from ..files.collisions import Input, Output, refuse_overwriting_inputs

    if args.out is not None:  # before anything is read: the traces must survive a typo
        # A CalculiX .dat takes its coordinates from the job's .frd or .inp beside it.
        beside = (
            [args.traces.with_suffix(".frd"), args.traces.with_suffix(".inp")]
            if args.traces.suffix.lower() == ".dat"
            else []
        )
        refuse_overwriting_inputs(
            [Input(args.traces, "traces", "the traces")]
            + [Input(path, "traces", "the job's coordinates") for path in beside],
            [Output(args.out, "out")],
        )
    traces = read_traces(args.traces, loads=args.loads, field=args.field)
    calibration = calibrate(traces, noise=args.noise, origin=args.origin)
    if args.out is not None:
        calibration.save(args.out)
        print(f"wrote {args.out}", file=sys.stderr)
    if args.json:
        print(
            json.dumps(calibration.to_dict() | {"checks": checks(calibration).to_dict()}, indent=2)
        )
    else:
        print(format_calibration(calibration))
    return 0
