"""The code generator: refuses what the design forbids, emits deterministic, runnable code."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest
import sympy

from asymslip.codegen import Argument, Formula
from asymslip.codegen.emit import format_source, render_module
from asymslip.codegen.loader import DERIVATIONS_PACKAGE, import_derivation
from asymslip.codegen.printer import GeneratedCodePrinter
from asymslip.codegen.records import RecordError, expression_from_srepr, packaged_formulas
from asymslip.codegen.runner import run_derivations

ROOT = Path(__file__).resolve().parents[1]

x, a, b = sympy.symbols("x a b", positive=True)
ARGS = (Argument(x, "position"), Argument(a, "half-width"))


def _formula(expr, args=ARGS, name="kernel"):
    return Formula(
        name=name,
        args=args,
        expr=expr,
        equations=("15",),
        summary="A kernel.",
        doc="For the tests.",
        module="demo",
        source="derivations/demo.py",
    )


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


RENDER_EVERYTHING = """
import hashlib
from asymslip.codegen.cse import reduce_formula
from asymslip.codegen.emit import format_source, render_module
from asymslip.codegen.languages import LANGUAGES
from asymslip.codegen.records import render_records
from tests.emit.synthetic import FORMULAS, SPECIAL

docs = {"synthetic": "Synthetic."}
texts = [format_source(render_module("synthetic", docs["synthetic"], FORMULAS)),
         render_records([*FORMULAS, SPECIAL])]
reduced = [reduce_formula(formula) for formula in (*FORMULAS, SPECIAL)]
for language in LANGUAGES:
    files = language.render(reduced, docs).files
    texts += [name + "\\n" + files[name] for name in sorted(files)]
print(hashlib.sha256("\\0".join(texts).encode()).hexdigest())
"""


def test_every_language_renders_the_same_bytes_under_different_hash_seeds():
    # Separate interpreters: string hashing (set and dict order of symbols) is fixed per
    # process, so only fresh processes with different PYTHONHASHSEED can expose a dependence.
    # The three interpreters run at once (they share nothing), so two cores halve the wait.
    processes = [
        subprocess.Popen(
            [sys.executable, "-c", RENDER_EVERYTHING],
            cwd=ROOT,
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
            env={**os.environ, "PYTHONHASHSEED": seed},
        )
        for seed in ("0", "1", "4242")
    ]
    digests = set()
    for process in processes:
        out, err = process.communicate(timeout=300)
        assert process.returncode == 0, err
        digests.add(out.strip())
    assert len(digests) == 1 and len(next(iter(digests))) == 64


def _write_tiny_derivations(folder):
    """Two scripts, the second importing a building block of the first relatively."""
    folder.mkdir()
    (folder / "_symbols.py").write_text("import sympy\n\nx = sympy.Symbol('x', positive=True)\n")
    (folder / "first.py").write_text(
        textwrap.dedent("""
        from asymslip.codegen import Derivation

        from ._symbols import x


        def square():
            return x**2


        def derive():
            return Derivation(__file__)
    """)
    )
    (folder / "second.py").write_text(
        textwrap.dedent("""
        from asymslip.codegen import Argument, Derivation

        from ._symbols import x
        from .first import square


        def derive():
            d = Derivation(__file__)
            d.describe_module("tiny", "Tiny.")
            d.emit(name="square", args=(Argument(x, "x > 0."),), expr=square(),
                   equations=("1",), summary="x^2.", doc="Square.", module="tiny")
            return d
    """)
    )


def test_derivations_load_as_a_package_with_relative_imports_and_no_sys_path_entry(tmp_path):
    folder = tmp_path / "derivations"
    _write_tiny_derivations(folder)
    path_before = list(sys.path)
    run = run_derivations(folder, progress=False)
    assert sys.path == path_before
    assert [formula.name for formula in run.formulas] == ["square"]
    assert run.formulas[0].source == "derivations/second.py"
    assert sys.modules[DERIVATIONS_PACKAGE].__path__ == [str(folder.resolve())]


def test_a_script_importing_a_neighbour_by_plain_name_fails(tmp_path):
    folder = tmp_path / "derivations"
    _write_tiny_derivations(folder)
    (folder / "third.py").write_text("from _symbols import x\n\n\ndef derive():\n    pass\n")
    with pytest.raises(ModuleNotFoundError, match="_symbols"):
        run_derivations(folder, progress=False)


def test_the_repository_derivations_import_each_other_relatively():
    glossary = import_derivation(ROOT / "derivations", "_glossary")
    assert glossary.__name__ == f"{DERIVATIONS_PACKAGE}._glossary"
    assert str(ROOT / "derivations") not in sys.path


def test_every_packaged_formula_record_reads_back_to_the_same_expression():
    records = json.loads((ROOT / "generated" / "asymslip_gen" / "formulas.json").read_text())
    formulas = packaged_formulas()
    assert len(formulas) == len(records["formulas"]) > 0
    for record in records["formulas"]:
        formula = formulas[record["name"]]
        assert sympy.srepr(formula.expr) == record["expr"]
        assert [arg.name for arg in formula.args] == [arg["name"] for arg in record["args"]]


@pytest.mark.parametrize(
    "text",
    [
        "__import__('os').system('true')",
        "sympify('x')",
        "Symbol('x').__class__",
        "Symbol('x', evaluate=exec)",
        "Symbol('x', foo=True)",
        "lambda: 0",
        "[Symbol('x') for _ in ()]",
    ],
)
def test_a_record_holding_anything_but_sympy_expression_data_is_refused(text):
    with pytest.raises(RecordError):
        expression_from_srepr(text)


def test_records_rebuild_assumptions_and_singletons():
    expr = expression_from_srepr(sympy.srepr(sympy.pi * sympy.sqrt(a) / x + sympy.Rational(1, 3)))
    assert expr == sympy.pi * sympy.sqrt(a) / x + sympy.Rational(1, 3)
    assert next(s for s in expr.free_symbols if s.name == "a").is_positive
