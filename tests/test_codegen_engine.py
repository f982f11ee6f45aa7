"""The code generator: refuses what the design forbids, emits deterministic, runnable code."""

from __future__ import annotations

import numpy as np
import pytest
import sympy

from asymslip.codegen import Argument, Formula
from asymslip.codegen.emit import format_source, render_module
from asymslip.codegen.printer import GeneratedCodePrinter

x, a, b = sympy.symbols("x a b", positive=True)
ARGS = (Argument(x, "position"), Argument(a, "half-width"))


def _formula(expr, args=ARGS, name="kernel"):
    return Formula(name=name, args=args, expr=expr, equations=("15",), summary="A kernel.",
                   doc="For the tests.", module="demo", source="derivations/demo.py")  # fmt: skip


def test_piecewise_is_refused_because_numpy_evaluates_every_branch():
    with pytest.raises(ValueError, match="branch-free"):
        _formula(sympy.Piecewise((sympy.sqrt(a - x), x < a), (0, True)))


def test_heaviside_is_refused():
    with pytest.raises(ValueError, match="branch-free"):
        _formula(sympy.Heaviside(a - x) * sympy.sqrt(a - x))


def test_a_free_symbol_that_is_not_an_argument_is_refused():
    with pytest.raises(ValueError, match=r"free symbols \['b'\]"):
        _formula(a + b)


def test_an_unevaluated_integral_is_refused():
    with pytest.raises(ValueError, match="unevaluated"):
        _formula(sympy.Integral(x, (x, 0, a)))


def test_max_prints_as_elementwise_numpy_maximum():
    printed = GeneratedCodePrinter().doprint(sympy.sqrt(sympy.Max(0, a - x)))
    assert printed == "numpy.sqrt(numpy.maximum(0, a - x))"


def test_clamped_kernel_runs_without_warnings_on_both_sides_of_the_edge():
    source = format_source(
        render_module("demo", "Demo.", [_formula(sympy.sqrt(sympy.Max(0, a - x)))])
    )
    namespace: dict = {}
    exec(compile(source, "demo.py", "exec"), namespace)
    values = namespace["kernel"](np.array([0.0, 0.5, 1.0, 2.0]), 1.0)  # -W error: no warnings
    np.testing.assert_array_equal(values, [1.0, np.sqrt(0.5), 0.0, 0.0])


def test_common_subexpressions_become_numbered_temporaries():
    expr = sympy.sqrt(a - x) * sympy.log(sympy.sqrt(a - x) + 1) + sympy.sqrt(a - x) ** 3
    source = render_module("demo", "Demo.", [_formula(expr)])
    assert "tmp0 = a - x\n    tmp1 = numpy.sqrt(tmp0)\n" in source
    assert source.count("a - x") == 1


def test_rendering_is_byte_identical_on_repetition():
    expr = sympy.sqrt(sympy.Max(0, a - x)) / (a + x) + sympy.pi * a**2
    first = format_source(render_module("demo", "Demo.", [_formula(expr)]))
    second = format_source(render_module("demo", "Demo.", [_formula(expr)]))
    assert first == second
