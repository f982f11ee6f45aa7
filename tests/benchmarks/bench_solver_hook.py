"""The reference solver's cost against N, from ``tests/benchmarks/bench_solver.py`` if it exists.

That module belongs to the solver (issue 11); it provides ``solver_rows(counts, repeat)``
returning ``(N, seconds, load steps, periods)`` per N, and optionally ``COUNTS``,
``TARGET_COUNT`` and ``TARGET_SECONDS``.  Without it (the solver not merged yet) this section
says so in one row and the rest of ``make bench`` runs as usual.
"""

from __future__ import annotations

import importlib
import math
from types import ModuleType

from .timing import Row, duration, verdict

MODULE = "tests.benchmarks.bench_solver"


def solver_module() -> ModuleType | None:
    """The solver's benchmark module, or None when its file does not exist."""
    try:
        return importlib.import_module(MODULE)
    except ModuleNotFoundError as error:
        if error.name in (MODULE, "asymslip.solver"):
            return None
        raise


def growth_exponent(counts: list[int], seconds: list[float]) -> float:
    """p of seconds ~ N^p, least squares in log-log."""
    x = [math.log(count) for count in counts]
    y = [math.log(value) for value in seconds]
    mean_x, mean_y = sum(x) / len(x), sum(y) / len(y)
    return sum((a - mean_x) * (b - mean_y) for a, b in zip(x, y, strict=True)) / sum(
        (a - mean_x) ** 2 for a in x
    )


def bench_solver(quick: bool, repeat: int) -> list[Row]:
    module = solver_module()
    if module is None or not hasattr(module, "solver_rows"):
        return [
            Row(
                "reference solver, cost against N",
                "skipped: `tests/benchmarks/"
                "bench_solver.py` (with `solver_rows`) is not on this branch yet",
            )
        ]
    counts = list(getattr(module, "COUNTS", (500, 1000, 2000, 4000)))
    if quick:
        counts = counts[:1]
    target_count = getattr(module, "TARGET_COUNT", None)
    target_seconds = getattr(module, "TARGET_SECONDS", None)
    measured = module.solver_rows(counts, repeat)
    rows = []
    for count, seconds, steps, periods in measured:
        target, met = "(information)", "-"
        if count == target_count and target_seconds is not None:
            target, met = f"<= {target_seconds:g} s", verdict(seconds <= target_seconds)
        rows.append(
            Row(
                f"reference solver, Fig. 5 cycle to its steady state, N = {count:,} elements",
                duration(seconds),
                "",
                "",
                target,
                met,
                f"wall clock, best of {repeat} (`bench_solver.solver_rows`); {steps} "
                f"load steps, {periods} periods",
            )
        )
    if len(measured) >= 2:
        exponent = growth_exponent([row[0] for row in measured], [row[1] for row in measured])
        rows.append(
            Row(
                "same: growth of the cost with N",
                f"N^{exponent:.2f}",
                "",
                "",
                "(information)",
                "-",
                "least-squares slope of log time on log N",
            )
        )
    return rows
