"""Common-subexpression elimination shared by every language the code generator writes.

Each formula is reduced once; the NumPy, C, Fortran and MATLAB/Octave functions all print the
same temporaries (``tmp0, tmp1, ...``) in the same order, so a reader can follow one function
across languages line by line.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy

from .formula import Formula
from .operations import Reduction, cheapest_reduction

#: Names of common-subexpression temporaries; argument names must not collide with them.
TEMPORARY_PREFIX = "tmp"


@dataclass(frozen=True)
class Reduced:
    """A formula after CSE: ``temporaries`` assigned in order, then ``result`` returned."""

    formula: Formula
    temporaries: tuple[tuple[sympy.Symbol, sympy.Expr], ...]
    result: sympy.Expr


def _cse(expr: sympy.Expr) -> Reduction:
    temporaries = sympy.numbered_symbols(TEMPORARY_PREFIX)
    replacements, (reduced,) = sympy.cse(
        [expr], symbols=temporaries, optimizations=None, order="canonical"
    )
    return replacements, reduced


def reduce_formula(formula: Formula) -> Reduced:
    """CSE of ``formula.expr`` with temporaries named ``tmp0, tmp1, ...`` in a fixed order.

    Before CSE, rational coefficients move into the sums they scale where that saves array
    operations (:mod:`asymslip.codegen.operations`); the record keeps the derivation's form.
    """
    for arg in formula.args:
        if arg.name.startswith(TEMPORARY_PREFIX):
            raise ValueError(f"{formula.name}: argument {arg.name!r} collides with temporaries")
    replacements, reduced = cheapest_reduction(formula.expr, _cse)
    return Reduced(formula, tuple(replacements), reduced)
