"""The same formulas for one value at a time: ``asymslip_gen/scalar.py``, printed with ``math``.

NumPy's ufuncs cost 0.3-2 us per call on a single float (dispatch, type resolution), so a
kernel of a few square roots costs microseconds for one cycle; ``math.sqrt`` costs 40 ns.  The
single-cycle path of the API evaluates these functions on Python floats: the same records, the
same CSE'd bodies and temporaries as the NumPy kernels, printed by SymPy's Python printer
configured for ``math`` (``Max``/``Min`` as the builtins, ``x**-1`` as ``1/x``).

Python floats raise where NumPy returns inf or NaN (``ZeroDivisionError``, ``OverflowError``,
``ValueError`` for ``math.sqrt(-1)``); the caller catches these and evaluates the value again
with the NumPy kernels, whose infinities and NaNs its rules then report.  A function that needs
something ``math`` lacks is left out, with a note in the module.
"""

from __future__ import annotations

import math
import textwrap
from collections.abc import Mapping, Sequence

import sympy
from sympy.printing.pycode import PythonCodePrinter

from .cse import Reduced
from .documentation import PAPER
from .printer import BranchFree, ReciprocalAsDivision

MODULE = "scalar"


class ScalarCodePrinter(BranchFree, ReciprocalAsDivision, PythonCodePrinter):
    """Python printer on ``math``: strict, element-free ``Max``/``Min``, ``1/x`` for ``x**-1``."""

    def __init__(self) -> None:
        super().__init__(
            {"fully_qualified_modules": True, "allow_unknown_functions": False, "strict": True}
        )

    def _print_Integer(self, expr: sympy.Integer) -> str:
        # 256.0 * x, not 256 * x: CPython 3.11 specialises float-float arithmetic only, so an
        # int operand takes the generic path (~15 % of an edge program's time).  The value is
        # the same double either way: Python converts the int to the nearest double before it
        # multiplies (and x**2.0 is x**2), so every result keeps its bits.
        return f"{int(expr)}.0"

    def _print_Pi(self, expr: sympy.Expr) -> str:
        # pi as the double math.pi holds (repr round-trips it): a literal, not a module
        # attribute looked up at every use, and folded with its neighbours (pi**2.0) when
        # Python compiles the module -- by the same float arithmetic, so the same bits.
        return repr(math.pi)

    def _print_Max(self, expr: sympy.Max) -> str:
        return f"max({', '.join(self._print(arg) for arg in expr.args)})"

    def _print_Min(self, expr: sympy.Min) -> str:
        return f"min({', '.join(self._print(arg) for arg in expr.args)})"

    def _print_sign(self, expr: sympy.Expr) -> str:
        # NumPy's sign (0 at 0, as the array kernels), without a branch on the argument.
        argument = self._print(expr.args[0])
        return f"((0.0 < {argument}) - ({argument} < 0.0))"

    def _print_Abs(self, expr: sympy.Expr) -> str:
        # abs(sign(x)) without the sign's own grouping parentheses doubled (ruff's UP034).
        printed = self._print(expr.args[0])
        if isinstance(expr.args[0], sympy.sign):
            printed = printed[1:-1]
        return f"abs({printed})"


def _unprintable(printer: ScalarCodePrinter, reduced: Reduced) -> list[str]:
    failing = set()
    for expr in [value for _, value in reduced.temporaries] + [reduced.result]:
        for function in expr.atoms(sympy.Function):
            try:
                printer.doprint(function)
            except (NotImplementedError, TypeError, ValueError):
                failing.add(type(function).__name__)
    return sorted(failing)


def render_scalar_module(reduced: Sequence[Reduced], module_docs: Mapping[str, str]) -> str:
    """Source of ``asymslip_gen/scalar.py``: every function, one value at a time."""
    from .emit import banner, docstring

    printer = ScalarCodePrinter()
    functions: list[str] = []
    left_out: dict[str, str] = {}
    names: list[str] = []
    for item in reduced:
        formula = item.formula
        missing = _unprintable(printer, item)
        if missing:
            left_out[formula.name] = f"needs {', '.join(missing)}, which math does not provide"
            continue
        signature = ", ".join(f"{arg.name}: float" for arg in formula.args)
        lines = [f"def {formula.name}({signature}) -> float:"]
        note = f"One value at a time, as ``asymslip_gen.{formula.module}.{formula.name}``."
        lines.append(textwrap.indent(docstring(formula, "float", "float", note), "    "))
        for temporary, value in item.temporaries:
            lines.append(f"    {temporary} = {printer.doprint(value)}")
        lines.append(f"    return {printer.doprint(item.result)}")
        functions.append("\n".join(lines) + "\n")
        names.append(formula.name)
    notes = "".join(f"\n- ``{name}``: {reason}." for name, reason in sorted(left_out.items()))
    doc = (
        "The generated formulas for one value at a time, on Python floats with ``math``.\n\n"
        + textwrap.fill(
            "Each function is its NumPy namesake in the module named in its docstring, with the "
            "same CSE'd body; ``math`` costs a fraction of NumPy's per-call overhead on one "
            "float.  Python floats raise (ZeroDivisionError, OverflowError, ValueError) where "
            "NumPy gives inf or NaN: callers fall back to the NumPy kernels then.",
            width=92,
        )
        + (f"\n\nLeft out:{notes}" if notes else "")
        + f"\n\nSee {PAPER}.\n"
    )
    exported = "\n".join(f'    "{name}",' for name in names)
    sources = sorted({item.formula.source for item in reduced})
    return (
        banner(sources) + f'"""{doc}"""\n\n'
        "from __future__ import annotations\n\n"
        "import math\n\n"
        f"__all__ = [\n{exported}\n]\n\n\n" + "\n\n".join(functions)
    )
