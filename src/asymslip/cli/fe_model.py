"""``asymslip fe-model``: the CalculiX model of a cylinder on a block, for a cycle as slip-zone's.

Writes the plane-strain deck (:mod:`asymslip.fe`), runs ``ccx`` on it where it is installed,
and prints each edge's steady FE stick boundary beside slip-zone's headline b, the difference
in FE elements.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path
from typing import TYPE_CHECKING

from .cycle_options import add_cycle_options
from .parser import number, whole_number

if TYPE_CHECKING:
    from ..fe import CylinderOnBlock


def register(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    command = commands.add_parser(
        "fe-model",
        help="write (and run, with CalculiX) a finite-element model of a cylinder on a block",
        description="Write the CalculiX deck of a plane-strain cylinder (--R, --E-star: the "
        "Hertz law of slip-zone) on a block of the same material, loaded by the steady cycle "
        "(normal load and shear force on the cylinder, bulk tension in the block), with a "
        "graded mesh and penalty contact with Coulomb friction; run ccx on it where it is "
        "installed (Debian: calculix-ccx) and print each edge's steady stick boundary and "
        "contact edges beside slip-zone's.  The run's .frd and .dat are what calibrate reads.",
    )
    law = command.add_argument_group("the cylinder (the hertz law of slip-zone)")
    law.add_argument("--R", type=number, required=True, help="cylinder radius [length]")
    law.add_argument(
        "--E-star",
        dest="E_star",
        type=number,
        required=True,
        help="plane-strain contact modulus E* [force/length^2]",
    )
    law.add_argument(
        "--nu", type=number, default=0.3, help="Poisson's ratio of both bodies (default 0.3)"
    )
    add_cycle_options(command)
    command.add_argument(
        "--elements-per-half-width",
        dest="elements_per_half_width",
        type=whole_number,
        default=30,
        metavar="N",
        help="a(P2) over the element size at the contact (default 30, a coarse mesh; a study "
        "would use 100 or more)",
    )
    command.add_argument(
        "--out", type=Path, required=True, metavar="DIR", help="the folder for the deck and run"
    )
    command.add_argument(
        "--deck-only", action="store_true", help="write the deck without running ccx"
    )
    command.add_argument("--json", action="store_true", help="print one JSON object")
    command.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from ..errors import InputError
    from ..fe import CylinderOnBlock, find_ccx, run_model, write_model

    model = CylinderOnBlock(
        R=args.R,
        E_star=args.E_star,
        mu=args.mu,
        P1=args.P1,
        Q1=args.Q1,
        P2=args.P2,
        Q2=args.Q2,
        sigma1=args.sigma1,
        sigma2=args.sigma2,
        nu=args.nu,
        elements_per_half_width=args.elements_per_half_width,
    )
    if args.out.exists() and not args.out.is_dir():
        raise InputError("out", f"{args.out} exists and is not a folder")
    try:
        args.out.mkdir(exist_ok=True)
    except OSError as error:
        raise InputError("out", f"cannot create {args.out}: {error.strerror}") from None
    if args.deck_only or find_ccx() is None:
        deck = write_model(model, args.out)
        why = "" if args.deck_only else " (ccx is not installed: Debian's calculix-ccx)"
        print(f"wrote {deck}; not run{why}", file=sys.stderr)
        if args.json:
            print(json.dumps({"deck": str(deck), "run": False}, indent=2))
        return 0
    outcome = run_model(model, args.out)
    assert outcome.result is not None
    comparison = _comparison(model)
    if args.json:
        print(
            json.dumps(
                {
                    "deck": str(outcome.deck),
                    "run": True,
                    "seconds": outcome.seconds,
                    "cpu_seconds": outcome.cpu_seconds,
                    **outcome.result.to_dict(),
                    "slip_zone": comparison,
                },
                indent=2,
            )
        )
        return 0
    h = model.element_size
    print(
        f"deck {outcome.deck}; ccx ran in {outcome.seconds:.1f} s ({outcome.cpu_seconds:.1f} s "
        f"CPU); element size {h:.6g}"
    )
    print(
        f"{'edge':>6} {'FE b':>10} {'+-':>8} {'slip-zone b':>12} {'(FE - b)/h':>11} "
        f"{'FE a1':>10} {'Hertz a1':>10} {'FE a2':>10} {'Hertz a2':>10}"
    )
    for side in ("right", "left"):
        edge = getattr(outcome.result, side)
        row = comparison[side]
        print(
            f"{side:>6} {edge.b:10.6g} {edge.resolution:8.2g} {row['b']:12.6g} "
            f"{(edge.b - row['b']) / h:11.3g} {edge.a1:10.6g} {model.a1:10.6g} "
            f"{edge.a2:10.6g} {model.a2:10.6g}"
        )
    return 0


def _comparison(model: CylinderOnBlock) -> dict[str, dict[str, float]]:
    """slip-zone's headline b and its stated accuracy at both edges, for the same cycle."""
    from ..cycle import LoadCycle
    from ..slip_zones import slip_zone

    cycle = LoadCycle(model.P1, model.Q1, model.P2, model.Q2, model.sigma1, model.sigma2)
    found = slip_zone(model.law, cycle, model.mu, edge="both")
    assert found.left is not None  # edge="both" gives the left edge
    return {
        "right": {"b": float(found.b), "b_accuracy": float(found.b_accuracy)},
        "left": {"b": float(found.left.b), "b_accuracy": float(found.left.b_accuracy)},
    }
