"""The ``asymslip`` command line: a thin layer over the Python API.

Every command prints what the corresponding API call returns, so a notebook user and a shell
user get the same numbers.  Bad input gives one line naming the option and the rule, and exit
status 2; a missing optional dependency gives one line naming the extra to install.

One module per command (``register`` adds its parser, ``run`` executes it); one registry of
contact laws (:mod:`.laws`).
"""

from __future__ import annotations

import logging
import os
import sys
from collections.abc import Sequence

from .. import __version__
from ..errors import InputError
from ..files.signals import Terminated
from . import (
    calibrate,
    derive,
    fe_model,
    figure,
    match,
    nucleation,
    slip_zone,
    solve,
    solve_batch,
    stress,
    sweep,
    traction,
)
from .laws import OPTION_OF
from .parser import Parser

COMMANDS = (
    slip_zone,
    traction,
    solve,
    calibrate,
    fe_model,
    figure,
    derive,
    sweep,
    match,
    stress,
    nucleation,
    solve_batch,
)


def build_parser() -> Parser:
    parser = Parser(
        prog="asymslip",
        description="Steady-state partial slip at contact edges: slip-zone size, tractions, "
        "slip and figures from the asymptotic corrective-slip solution (TAFM 2022, 103457).  "
        "Loads are per unit length of contact; lengths and moduli in any consistent units.",
    )
    parser.add_argument(
        "--version", action="version", version=f"%(prog)s {__version__}", help="print the version"
    )
    commands = parser.add_subparsers(dest="command", required=True, parser_class=Parser)
    for command in COMMANDS:
        command.register(commands)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    # What the file layer has to say (an old partial file found, removed or kept) is printed
    # on stderr as a note, one line each.
    notes = logging.StreamHandler(sys.stderr)
    notes.setFormatter(logging.Formatter("asymslip: note: %(message)s"))
    logger = logging.getLogger("asymslip")
    logger.addHandler(notes)
    try:
        return int(args.run(args))
    except InputError as error:
        option = OPTION_OF.get(error.parameter, error.parameter)
        message = str(error).removeprefix(f"{error.parameter}: ")
        print(f"asymslip: error: {option}: {message}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("asymslip: interrupted; nothing partial was written", file=sys.stderr)
        return 130
    except Terminated as signal:
        print(f"asymslip: {signal}; nothing partial was written", file=sys.stderr)
        return 128 + signal.signum
    except BrokenPipeError:
        # The reader went away (`asymslip ... | head`): stop quietly, as Unix tools do.
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 141
    finally:
        logger.removeHandler(notes)
