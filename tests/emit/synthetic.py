"""Formulas that exercise every construct the printers must carry over, beyond today's records.

Max/Min (with integer literals, which Fortran's intrinsics refuse unless printed as reals),
x**-1, negative and rational powers, sqrt, integer powers, rational constants, pi, sign,
atan2, log1p/expm1 (which Fortran lacks: bound to C's), exp/log, Abs -- each in a branch-free,
warning-free form on the documented domain below.  Plus one formula with a special function no
target has (``zeta``), which every language must leave out with a note.
"""

from __future__ import annotations

import numpy as np
import sympy
from sympy.codegen.cfunctions import expm1, log1p

from asymslip.codegen import Argument, Formula

x = sympy.Symbol("x", real=True)
a = sympy.Symbol("a", positive=True)
A = sympy.Symbol("A", positive=True)  # differs from a only in case (Fortran!)
n = sympy.Symbol("n", positive=True)
ARGS = (
    Argument(x, "Any real x."),
    Argument(a, "Half-width a > 0."),
    Argument(A, "Coefficient A > 0."),
    Argument(n, "Exponent n >= 1."),
)
SOURCE = "derivations/synthetic.py"


def _formula(name: str, expr: sympy.Expr, args=ARGS, module: str = "synthetic") -> Formula:
    return Formula(
        name=name,
        args=args,
        expr=expr,
        equations=("15",),
        summary=f"{name}.",
        doc="For the printer tests.",
        module=module,
        source=SOURCE,
    )


FORMULAS = (
    _formula("clamped_root", sympy.sqrt(sympy.Max(0, a - x)) + sympy.Min(0, x, a - 2 * A)),
    _formula("powers", x**2 / a + a**-3 * A ** sympy.Rational(3, 4) + 1 / (a + A) + a ** (1 / n)),
    _formula("constants", sympy.pi * x / 4 + sympy.Rational(2, 3) * a - sympy.sqrt(2) * A),
    _formula("signs", sympy.sign(x) * sympy.Abs(x) ** sympy.Rational(3, 2) + sympy.atan2(x, a)),
    _formula("accurate_logs", log1p(sympy.Abs(x) / a) + expm1(-A / (a + A)) * n),
    _formula("exp_log", sympy.exp(-(x**2) / a) * sympy.log(a + A) + a ** (n - 2) * A**n),
    _formula("case_clash", a * A + a / A),
)
#: A formula none of the targets can express: left out of C, Fortran and MATLAB/Octave.
SPECIAL = _formula("needs_zeta", sympy.zeta(a + 2) * x)


def sample(count: int, seed: int = 5) -> dict[str, np.ndarray]:
    rng = np.random.default_rng(seed)
    a_values = np.exp(rng.uniform(np.log(0.01), np.log(100.0), count))
    return {
        "x": a_values * rng.uniform(-2.0, 2.0, count),
        "a": a_values,
        "A": np.exp(rng.uniform(np.log(0.01), np.log(100.0), count)),
        "n": rng.uniform(1.0, 4.0, count),
    }
