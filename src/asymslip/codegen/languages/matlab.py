"""MATLAB/Octave: one vectorised function file ``asymslip_<name>.m`` per formula.

Element-wise operators throughout (SymPy's Octave printer writes ``.*``, ``./``, ``.^``), so
each function takes scalars or arrays of one size (or scalars mixed with arrays) and runs
unchanged in MATLAB and Octave.  The help block (what ``help asymslip_<name>`` prints) comes
right after the function line, as both require, and ends with the banner.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import sympy
from sympy.printing.octave import OctaveCodePrinter

from ..cse import Reduced
from ..documentation import banner_lines, commented, function_lines
from ..printer import BranchFree
from .base import Language, Rendered, left_out_reason, unprintable_functions

RESULT = "result"
NOTE_FILE = "LEFT_OUT.md"
#: SymPy functions whose Octave names exist in base MATLAB and base Octave alike.  SymPy's
#: printer also maps zeta, polylog, harmonic, lambertw, chebyshevT, ... which need MATLAB's
#: Symbolic Math Toolbox or Octave's symbolic package: a generated file must run without them.
BASE_FUNCTIONS = frozenset(
    {
        "sin",
        "cos",
        "tan",
        "cot",
        "sec",
        "csc",
        "asin",
        "acos",
        "acot",
        "atan",
        "atan2",
        "asec",
        "acsc",
        "sinh",
        "cosh",
        "tanh",
        "coth",
        "csch",
        "sech",
        "asinh",
        "acosh",
        "atanh",
        "acoth",
        "asech",
        "acsch",
        "erf",
        "erfc",
        "erfinv",
        "erfcinv",
        "besseli",
        "besselj",
        "besselk",
        "bessely",
        "beta",
        "exp",
        "gamma",
        "log",
        "sign",
        "floor",
        "ceiling",
        "Abs",
        "Max",
        "Min",
        "Mod",
        "loggamma",
        "log1p",
        "expm1",
    }
)


class MatlabGeneratedPrinter(BranchFree, OctaveCodePrinter):
    """Octave/MATLAB printer: strict, base functions only, with ``log1p`` and ``expm1``."""

    def __init__(self) -> None:
        super().__init__({"strict": True, "user_functions": {"log1p": "log1p", "expm1": "expm1"}})
        self.known_functions: dict[str, str] = {
            name: printed
            for name, printed in self.known_functions.items()
            if name in BASE_FUNCTIONS
        }

    # Printed by SymPy as toolbox functions (or, for the deltas, as branches): refused, so
    # that a formula using them is left out with a note.
    def _print_zeta(self, expr: sympy.Expr) -> str:
        return self._print_not_supported(expr)

    def _print_LambertW(self, expr: sympy.Expr) -> str:
        return self._print_not_supported(expr)

    def _print_DiracDelta(self, expr: sympy.Expr) -> str:
        return self._print_not_supported(expr)

    def _print_KroneckerDelta(self, expr: sympy.Expr) -> str:
        return self._print_not_supported(expr)

    def _print_sinc(self, expr: sympy.Expr) -> str:
        return self._print_not_supported(expr)


def _function_file(item: Reduced) -> str:
    formula = item.formula
    name = f"asymslip_{formula.name}"
    printer = MatlabGeneratedPrinter()
    names = {arg.name: printer.doprint(arg.symbol) for arg in formula.args}
    if RESULT in names.values():
        raise ValueError(f"{formula.name}: an argument is named {RESULT!r}")
    args = ", ".join(names[arg.name] for arg in formula.args)
    doc = function_lines(formula, names, arguments_heading="Arguments (scalars or arrays):")
    # MATLAB's help convention: the first line is NAME in capitals, then the summary.
    help_lines = [f"{name.upper()}  {doc[0]}", *doc[1:], "", *banner_lines([formula.source])]
    body = [printer.doprint(value, assign_to=temporary) for temporary, value in item.temporaries]
    body.append(printer.doprint(item.result, assign_to=sympy.Symbol(RESULT)))
    return (
        f"function {RESULT} = {name}({args})\n"
        + commented(help_lines, "%")
        + "\n"
        + "".join(f"  {line}\n" for statement in body for line in statement.splitlines())
        + "end\n"
    )


def render_matlab(reduced: Sequence[Reduced], module_docs: Mapping[str, str]) -> Rendered:
    """One ``asymslip_<name>.m`` per formula Octave can express (and a note of the others)."""
    files: dict[str, str] = {}
    left_out: dict[str, str] = {}
    kept: list[str] = []
    for item in reduced:
        missing = unprintable_functions(MatlabGeneratedPrinter(), item)
        if missing:
            left_out[item.formula.name] = left_out_reason(missing, "MATLAB/Octave")
            continue
        files[f"asymslip_{item.formula.name}.m"] = _function_file(item)
        kept.append(item.formula.name)
    if left_out:
        # One function per file leaves no file to hold the note: it gets its own.
        lines = [
            *(f"<!-- {line} -->" for line in banner_lines([i.formula.source for i in reduced])),
            "",
            "# Left out of the MATLAB/Octave functions",
            "",
            *(f"- `asymslip_{name}`: {reason}." for name, reason in sorted(left_out.items())),
        ]
        files[NOTE_FILE] = "\n".join(lines) + "\n"
    return Rendered(files=files, functions=tuple(kept), left_out=left_out)


MATLAB_LANGUAGE = Language(
    name="MATLAB/Octave", folder="matlab", render=render_matlab, extensions=(".m", ".md")
)
