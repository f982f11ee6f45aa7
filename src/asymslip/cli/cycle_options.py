"""The load-cycle options shared by the commands that evaluate one cycle."""

from __future__ import annotations

import argparse

from ..cycle import LoadCycle
from .parser import number


def add_cycle_options(parser: argparse.ArgumentParser) -> None:
    group = parser.add_argument_group(
        "load cycle (loads per unit length; state 2 has the larger normal load)"
    )
    for name, required, text in [
        ("P1", True, "normal load at state 1"),
        ("Q1", True, "shear force at state 1"),
        ("P2", True, "normal load at state 2 (> P1)"),
        ("Q2", True, "shear force at state 2"),
        ("sigma1", False, "differential bulk tension at state 1 (default 0)"),
        ("sigma2", False, "differential bulk tension at state 2 (default 0)"),
    ]:
        group.add_argument(
            f"--{name}",
            type=number,
            required=required,
            default=None if required else 0.0,
            help=text,
        )
    parser.add_argument("--mu", type=number, required=True, help="coefficient of friction (> 0)")


def build_cycle(args: argparse.Namespace) -> LoadCycle:
    return LoadCycle(args.P1, args.Q1, args.P2, args.Q2, args.sigma1, args.sigma2)
