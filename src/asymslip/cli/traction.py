"""``asymslip traction`` and ``asymslip slip``: q2 - q1 and the slip displacement near an edge."""

from __future__ import annotations

import argparse
import json

from ..tractions import (
    NEAR_EDGE_FRACTION,
    SLIP_CONVENTION,
    slip_displacement,
    traction_difference,
)
from .cycle_options import add_cycle_options, build_cycle
from .laws import add_law_options, build_law
from .parser import number


def _common(parser: argparse.ArgumentParser) -> None:
    add_law_options(parser)
    add_cycle_options(parser)
    parser.add_argument(
        "--x",
        type=number,
        nargs="+",
        required=True,
        metavar="X",
        help="positions measured from the contact centre, inside the contact",
    )
    parser.add_argument(
        "--edge",
        choices=["right", "left"],
        default="right",
        help="which edge (default right, the paper's)",
    )
    parser.add_argument(
        "--b",
        choices=["headline", "consistent", "exact"],
        default="headline",
        help="stick boundary: headline = slip-zone's b (b2, default), consistent = (17)/(22), "
        "for which (15) solves (12), exact = a(P_K), the paper's choice for Fig. 5",
    )
    parser.add_argument("--json", action="store_true", help="print one JSON object")


def register(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    traction = commands.add_parser(
        "traction",
        help="shear-traction difference q2 - q1 near a contact edge",
        description="Asymptotic q_diff of (49), in closed form, and the exact (47) where the "
        "law has a pressure distribution and eta = 0, at positions x measured from the contact "
        "centre; q_diff is the traction component along +x.  Each value says whether x lies "
        f"near the edge (within {NEAR_EDGE_FRACTION:g} a2 of the state-2 edge), where the edge "
        "asymptote (49) is meant to hold; the cycle's warnings follow.",
    )
    _common(traction)
    traction.set_defaults(run=run_traction)
    slip = commands.add_parser(
        "slip",
        help="slip displacement on loading near a contact edge",
        description="Slip displacement accumulated on loading from state 1 to state 2, the "
        f"integral of the dislocation density (15): {SLIP_CONVENTION}.  It is 0 in the stick "
        "zone; |delta| is the slip amplitude (peak to peak) of the steady cycle.  The slip "
        "starts at the headline b by default (second-order accurate, as b itself); --b "
        "consistent takes (17)'s.  The slip scales as 1/E*: a table or module law needs "
        "--E-star.",
    )
    _common(slip)
    slip.set_defaults(run=run_slip)


def _rows(header: list[str], rows: list[list[str]]) -> str:
    widths = [max(len(h), *(len(r[i]) for r in rows)) for i, h in enumerate(header)]
    lines = ["  " + "  ".join(h.rjust(w) for h, w in zip(header, widths, strict=True))]
    lines += ["  " + "  ".join(c.rjust(w) for c, w in zip(r, widths, strict=True)) for r in rows]
    return "\n".join(lines)


def _warnings(warnings: list[str]) -> str:
    return "warnings: " + (
        "none" if not warnings else "\n" + "\n".join(f"  - {warning}" for warning in warnings)
    )


def run_traction(args: argparse.Namespace) -> int:
    result = traction_difference(
        build_law(args), build_cycle(args), args.mu, args.x, stick_boundary=args.b, edge=args.edge
    )
    if args.json:
        print(json.dumps(result.to_dict(), indent=2))
        return 0
    region = (
        f"x >= {result.near_edge_from:.12g}"
        if args.edge == "right"
        else f"x <= {-result.near_edge_from:.12g}"
    )
    print(
        f"q_diff = q2 - q1 near the {args.edge}-hand edge (b = {result.b:.12g}, {args.b} "
        f"choice); near the edge: {region}"
    )
    exact = result.q_diff_exact or [None] * len(result.x)
    rows = [
        [f"{x:.12g}", f"{q:.12g}", "null" if e is None else f"{e:.12g}", "yes" if near else "no"]
        for x, q, e, near in zip(result.x, result.q_diff, exact, result.near_edge, strict=True)
    ]
    print(_rows(["x", "q_diff (49)", "q_diff_exact (47)", "near edge"], rows))
    print(_warnings(result.warnings))
    return 0


def run_slip(args: argparse.Namespace) -> int:
    law = build_law(args)
    result = slip_displacement(
        law,
        build_cycle(args),
        args.mu,
        args.x,
        E_star=args.E_star,
        stick_boundary=args.b,
        edge=args.edge,
    )
    if args.json:
        print(json.dumps(result.to_dict(), indent=2))
        return 0
    print(
        f"slip displacement on loading near the {args.edge}-hand edge (b = {result.b:.12g}, "
        f"{args.b} choice)"
    )
    rows = [[f"{x:.12g}", f"{h:.12g}"] for x, h in zip(result.x, result.slip, strict=True)]
    print(_rows(["x", "slip delta"], rows))
    print(_warnings(result.warnings))
    return 0
