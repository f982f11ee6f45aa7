"""The NumPy printer used for generated code, configured through ``_print_*`` methods."""

from __future__ import annotations

from typing import Any

import sympy
from sympy.printing.numpy import NumPyPrinter
from sympy.printing.precedence import PRECEDENCE


class BranchFree:
    """What every generated language's printer refuses, written once.

    Piecewise and Heaviside evaluate every branch in NumPy (``numpy.select``), so an unused
    branch's sqrt of a negative number raises a warning or leaks NaN; in the compiled
    languages they would print branches that the NumPy kernels, the reference, do not have.
    A formula must use a branch-free clamped form such as ``sqrt(Max(0, a1 - x))``.
    """

    def _print_Piecewise(self, expr: sympy.Piecewise) -> str:
        raise TypeError("Piecewise is not allowed in generated code; use a branch-free form")

    def _print_Heaviside(self, expr: sympy.Heaviside) -> str:
        raise TypeError("Heaviside is not allowed in generated code; use a clamped form")


class ReciprocalAsDivision:
    """Python printers: ``1/x`` for ``x**-1``.

    NumPyPrinter writes x**(-1.0) so that integer arrays do not fail; a division says the
    same thing plainly and is just as safe (the math kernels share it, so both print alike).
    """

    def _print_Pow(self, expr: sympy.Pow, rational: bool = False) -> str:
        if expr.exp == -1:
            printer: Any = self
            return f"1/{printer.parenthesize(expr.base, PRECEDENCE['Pow'])}"
        return super()._print_Pow(expr, rational=rational)  # type: ignore[misc]


class GeneratedCodePrinter(BranchFree, ReciprocalAsDivision, NumPyPrinter):
    """NumPy printer with element-wise Max/Min and no Piecewise.

    SymPy's default prints ``Max(a, b)`` as ``numpy.amax((a, b), axis=0)``, which stacks the
    arguments into a new array before reducing; ``numpy.maximum`` is element-wise, allocation
    light and works unchanged on dask arrays.  Piecewise is refused: ``numpy.select`` evaluates
    every branch, so an unused branch's sqrt of a negative number raises a warning or leaks NaN.
    """

    def __init__(self) -> None:
        super().__init__({"fully_qualified_modules": True, "allow_unknown_functions": False})

    def _print_elementwise_fold(self, function: str, args: tuple[sympy.Expr, ...]) -> str:
        printed = [self._print(arg) for arg in args]
        result = printed[0]
        for arg in printed[1:]:
            result = f"{self._module_format(function)}({result}, {arg})"
        return result

    def _print_Max(self, expr: sympy.Max) -> str:
        return self._print_elementwise_fold("numpy.maximum", expr.args)

    def _print_Min(self, expr: sympy.Min) -> str:
        return self._print_elementwise_fold("numpy.minimum", expr.args)
