"""A solve runs on one thread whatever the BLAS is set to: no BLAS call in the inner loop.

OpenBLAS runs dot products and matrix-vector products longer than 10,000 elements on every
core; on a shared machine those threads wait for each other at every call (issue 17: 4-8
times slower at N >= 16,000 with other work on the cores).  The solver's iterations therefore
take their inner products from :mod:`asymslip.solver.inner_products` (``numpy.einsum``, NumPy's
own loops) and FFTs (NumPy's pocketfft, single-threaded).  This test reads the source of every
module the load steps run through and fails on any BLAS entry point: the ``@`` operator,
``dot``, ``vdot``, ``inner``, ``matmul``, ``tensordot`` and ``linalg.norm`` / ``linalg.solve``
(the latter allowed only in ``solve_small``, for systems larger than 2 x 2 that the solver never
forms).  The effect is measured by ``tests/benchmarks/bench_solver.py`` (loaded rows).
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

SOLVER = Path(__file__).resolve().parents[2] / "src" / "asymslip" / "solver"
INNER_LOOP = (
    "toeplitz",
    "crt_layout",
    "halved_product",
    "qp",
    "tangential",
    "normal",
    "period",
    "run",
    "inner_products",
    "grid",
)
BLAS_NAMES = {"dot", "vdot", "inner", "matmul", "tensordot"}
LINALG = {"norm", "solve", "lstsq", "inv"}


def blas_calls(source: str) -> list[str]:
    """Every BLAS entry point in a module's source, as 'line: what'."""
    found = []
    tree = ast.parse(source)
    for function in ast.walk(tree):
        if not isinstance(function, ast.FunctionDef):
            continue
        for node in ast.walk(function):
            if isinstance(node, ast.BinOp) and isinstance(node.op, ast.MatMult):
                found.append(f"{node.lineno}: @ in {function.name}")
            elif isinstance(node, ast.Attribute) and node.attr in BLAS_NAMES:
                base = node.value
                numpy = isinstance(base, ast.Name) and base.id in ("np", "numpy")
                if numpy or node.attr == "dot":
                    found.append(f"{node.lineno}: {node.attr} in {function.name}")
            elif isinstance(node, ast.Attribute) and node.attr in LINALG:
                base = node.value
                if isinstance(base, ast.Attribute) and base.attr == "linalg":
                    if not (node.attr == "solve" and function.name == "solve_small"):
                        found.append(f"{node.lineno}: linalg.{node.attr} in {function.name}")
    return sorted(set(found))


@pytest.mark.parametrize("module", INNER_LOOP)
def test_the_inner_loop_calls_no_blas(module):
    assert blas_calls((SOLVER / f"{module}.py").read_text(encoding="utf-8")) == []


def test_the_check_finds_each_kind_of_blas_call():
    source = (
        "import numpy as np\n"
        "def f(a, b, m):\n"
        "    x = a @ b\n"
        "    y = np.dot(a, b) + a.dot(b) + np.linalg.norm(a)\n"
        "    return np.linalg.solve(m, a)\n"
    )
    assert blas_calls(source) == [
        "3: @ in f",
        "4: dot in f",  # np.dot and a.dot, both on line 4
        "4: linalg.norm in f",
        "5: linalg.solve in f",
    ]
