"""``asymslip slip-zone``: the slip zone at the contact edges for one load cycle."""

from __future__ import annotations

import argparse
import json

from ..edge_flags import VALIDITY_MEANING
from ..slip_zones import SlipZoneResult, slip_zone
from .cycle_options import add_cycle_options, build_cycle
from .laws import add_law_options, build_law


def register(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = commands.add_parser(
        "slip-zone",
        help="slip-zone size at the contact edges for one load cycle",
        description="The headline stick boundary b (second order in dP with both edges and "
        "bulk tension, b2; README 'How far to trust b') and its stated accuracy, the slip-zone "
        "width a1 - b, the paper's (22) as b_paper, first-order b (28), corrective-stick b "
        "(40), exact b = a(P_K) when eta = 0, the slip direction and the validity measures "
        "(24)-(27).  A cycle that is not a steady partial-slip state (gross "
        "sliding, no stick boundary, slip zones covering the contact) is refused.",
    )
    add_law_options(parser)
    add_cycle_options(parser)
    parser.add_argument(
        "--edge",
        choices=["right", "left", "both"],
        default="both",
        help="which edge (default both: the right edge's keys at the top level "
        "and the left edge's under 'left')",
    )
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    parser.set_defaults(run=run)


def _number(value: float | int | None) -> str:
    return "null" if value is None else f"{value:.12g}"


def format_table(result: SlipZoneResult, edge: str, law: str, mu: float) -> str:
    """The human-readable report of one edge."""
    lines = [f"Slip zone at the {edge}-hand edge ({law} law, mu = {mu:g})"]
    for key, value in result.to_dict().items():
        if key in ("validity", "warnings", "left"):
            continue
        lines.append(f"  {key:<20} {_number(value)}")  # type: ignore[arg-type]
    lines.append("  validity measures (each must be << 1):")
    for key, value in result.validity.items():
        lines.append(f"    {key}  {value:<10.4g} {VALIDITY_MEANING[key]}")
    lines.append("  warnings: " + ("none" if not result.warnings else ""))
    lines.extend(f"    - {warning}" for warning in result.warnings)
    return "\n".join(lines)


def run(args: argparse.Namespace) -> int:
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
