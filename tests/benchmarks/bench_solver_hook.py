"""The reference solver's section of ``make bench``, from ``tests/benchmarks/bench_solver.py``.

That module belongs to the solver (issues 11, 17, 22); it measures the new solver against
today's (the package at main before issue 22, unpacked from git) and turns the runs into rows.
Without it (a checkout that lacks the solver) this section says so in one row and the rest of
``make bench`` runs as usual.
"""

from __future__ import annotations

import importlib
from types import ModuleType

from .timing import Row

MODULE = "tests.benchmarks.bench_solver"


def solver_module() -> ModuleType | None:
    """The solver's benchmark module, or None when its file does not exist."""
    try:
        return importlib.import_module(MODULE)
    except ModuleNotFoundError as error:
        if error.name in (MODULE, "asymslip.solver"):
            return None
        raise


def bench_solver(quick: bool, repeat: int) -> list[Row]:
    module = solver_module()
    if module is None or not hasattr(module, "solver_rows"):
        return [
            Row(
                "reference solver, cost against N",
                "skipped: `tests/benchmarks/bench_solver.py` (with `solver_rows`) is not on "
                "this branch yet",
            )
        ]
    rows: list[Row] = module.solver_rows(quick, repeat)
    return rows
