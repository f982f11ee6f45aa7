"""argparse as the commands need it: one-line errors, and every number a person types.

argparse takes ``-1e2`` for an option (its negative-number pattern knows no exponent) and so
refuses ``--Q1 -1e2``; the parser here recognises every decimal number, with or without an
exponent, and ``-inf``/``-nan`` (which the API then refuses as non-finite, for the right
reason).
"""

from __future__ import annotations

import argparse
import re
from typing import NoReturn

#: A negative number as people type it: -3, -3., -.5, -1e2, -1.5E-3, -inf, -nan.
NEGATIVE_NUMBER = re.compile(r"^-(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$|^-(inf|infinity|nan)$", re.I)


class Parser(argparse.ArgumentParser):
    """argparse with one-line errors (no usage dump), exit status 2, negative numbers."""

    def __init__(self, *args, **kwargs) -> None:
        super().__init__(*args, **kwargs)
        # argparse's own pattern (private, stable since Python 3.2) knows no exponent.
        self._negative_number_matcher = NEGATIVE_NUMBER

    def error(self, message: str) -> NoReturn:
        self.exit(2, f"{self.prog}: error: {message}\n")


def number(text: str) -> float:
    """An option's number: any decimal a person types; non-finite ones are the API's to refuse."""
    try:
        return float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None


def whole_number(text: str) -> int:
    try:
        return int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a whole number") from None
