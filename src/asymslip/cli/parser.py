"""argparse as the commands need it: one-line errors, and every number a person types.

argparse takes ``-1e2`` for an option (its negative-number pattern knows no exponent) and so
refuses ``--Q1 -1e2``; the parser here recognises every decimal number, with or without an
exponent, and ``-inf``/``-nan`` (which the API then refuses as non-finite, for the right
reason).  Likewise a formula that starts with a minus sign (``--P-of-a "-1/a+k"``) is a value,
not an unknown option.
"""

from __future__ import annotations

import argparse
import math
import re
from typing import Any, NoReturn

#: A negative number as people type it: -3, -3., -.5, -1e2, -1.5E-3, -inf, -nan.
NEGATIVE_NUMBER = re.compile(r"^-(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$|^-(inf|infinity|nan)$", re.I)
#: A value that starts with a minus sign but holds a character no option name has (no "="):
#: a formula such as ``--P-of-a "-1/a+k"``.
NOT_AN_OPTION = re.compile(r"^-(?!-)[\w-]*[^\w=-][^=]*$")


class Parser(argparse.ArgumentParser):
    """argparse with one-line errors (no usage dump), exit status 2, negative numbers."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        # argparse's own pattern (private, stable since Python 3.2) knows no exponent.
        self._negative_number_matcher = NEGATIVE_NUMBER

    def _parse_optional(self, arg_string: str) -> Any:  # argparse's private hook
        # argparse takes anything that starts with "-" for an option unless it has a space.
        if NOT_AN_OPTION.match(arg_string):
            return None
        return super()._parse_optional(arg_string)

    def error(self, message: str) -> NoReturn:
        self.exit(2, f"{self.prog}: error: {message}\n")


def number(text: str) -> float:
    """An option's number: any decimal a person types; non-finite ones are the API's to refuse."""
    try:
        return float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None


def whole_number(text: str) -> int:
    """A count as people type it: 2000, 2e3 or 2000.0 (but not 1.5, inf or nan)."""
    try:
        return int(text)
    except ValueError:
        pass
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a whole number") from None
    if not math.isfinite(value):  # said in words: never echo inf or nan as a value
        raise argparse.ArgumentTypeError("must be a finite whole number (not inf or nan)")
    if not value.is_integer():
        raise argparse.ArgumentTypeError(f"{text!r} is not a whole number")
    return int(value)
