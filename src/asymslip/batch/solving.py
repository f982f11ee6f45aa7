"""One partition of ``solve-batch``: every case through :func:`asymslip.solver.solve`, two
result rows per case (the right edge, then the left), as columns ready to write.

The numbers are those of ``solve --json`` for the edge (its ``b``, ``b_error``, ``b_method``,
``slip_direction``, the contact edges and stick boundaries at states 1 and 2 of the paper's
cycle), ``a_max`` (the largest contact edge over the path's points), the solver's record
(prefixed ``solver_``) and, for the paper's cycle, every ``slip-zone`` estimate set beside the
solver by :func:`asymslip.solver.compare.with_asymptotes`: ``asymptote_<name>`` with its
``_difference`` (estimate - solver), ``_elements`` (that in elements) and ``_within_error``
(1 when within the solver's bound, else 0), for ``<name>`` in ``b`` (the headline),
``b_paper`` (22), ``b_first_order`` (28), ``b_corrective_stick`` (40), ``b_exact``.  A case the
solver refuses or cannot converge keeps its two rows, with the reason in ``error``.

Examples
--------
>>> from asymslip.batch.cases import RowError
>>> from asymslip.batch.solving import result_schema, solve_one
>>> [name for name, _ in result_schema()][:6]
['edge', 'b', 'b_error', 'b_error_elements', 'slip_direction', 'b_method']
>>> solve_one(RowError("R: must be > 0 (got -1.0)")).error  # a bad row: no solve, its reason
'R: must be > 0 (got -1.0)'
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import InputError
from ..files import CaseTable, Categorical, TextColumn
from ..files.writer import Column, Kind
from ..solver import SolverError, SolverResult, solve
from ..solver.compare import ESTIMATES, with_asymptotes
from .cases import BatchSettings, Case, RowError, case_of

EDGES = ("right", "left")
#: Joins a case's warnings (as the sweep joins a row's).
WARNING_SEPARATOR = " | "
STATE_COLUMNS = (
    "a1",
    "a1_error",
    "a2",
    "a2_error",
    "b1",
    "b1_error",
    "slip_direction1",
    "b2",
    "b2_error",
    "slip_direction2",
)
EDGE_NUMBERS = ("b", "b_error", "b_error_elements", "slip_direction", *STATE_COLUMNS, "a_max")
ASYMPTOTE_PARTS = ("", "_difference", "_elements", "_within_error")
SOLVER_NUMBERS = (
    "elements",
    "element_size",
    "steps_per_segment",
    "cycles",
    "steady",
    "steady_change",
    "load_steps",
    "fallbacks",
    "seconds",
)
#: Columns that vary from run to run (timings): left out when two runs are compared.
TIMING_COLUMNS = ("solver_seconds",)

Solve = Callable[..., SolverResult]


def result_schema() -> list[tuple[str, Kind]]:
    """The result columns after the input's: name and kind."""
    schema: list[tuple[str, Kind]] = [("edge", "category")]
    schema += [(name, "float") for name in EDGE_NUMBERS[:4]]
    schema.append(("b_method", "category"))
    schema += [(name, "float") for name in EDGE_NUMBERS[4:]]
    schema += [
        (f"asymptote_{name}{part}", "float") for name in ESTIMATES for part in ASYMPTOTE_PARTS
    ]
    schema += [(f"solver_{name}", "float") for name in SOLVER_NUMBERS]
    schema += [("warnings", "category"), ("error", "category")]
    return schema


def _float(value: Any) -> float:
    if value is None:
        return np.nan
    if isinstance(value, bool):
        return 1.0 if value else 0.0
    return float(value)


def edge_values(data: dict[str, Any], is_cycle: bool) -> dict[str, float | str | None]:
    """One edge's result row (numbers and texts) from ``SolverResult.to_dict()``'s edge part."""
    row: dict[str, float | str | None] = {
        name: _float(data.get(name)) for name in EDGE_NUMBERS if name != "a_max"
    }
    if not is_cycle:  # states 1 and 2 are the paper's cycle's; a path has its own points
        row.update(dict.fromkeys(STATE_COLUMNS, np.nan))
    edges = [value for key, value in data.items() if key[:1] == "a" and key[1:].isdigit()]
    row["a_max"] = max(edges) if edges else np.nan
    row["b_method"] = data.get("b_method")
    asymptotes = data.get("asymptotes") or {}
    for name in ESTIMATES:
        entry = asymptotes.get(name) or {}
        row[f"asymptote_{name}"] = _float(entry.get("value"))
        row[f"asymptote_{name}_difference"] = _float(entry.get("difference"))
        row[f"asymptote_{name}_elements"] = _float(entry.get("elements"))
        row[f"asymptote_{name}_within_error"] = _float(entry.get("within_error"))
    return row


@dataclass(frozen=True)
class CaseOutcome:
    """The two edge rows of a case, its warnings, and its error (None when solved)."""

    edges: tuple[dict[str, float | str | None], dict[str, float | str | None]] | None
    solver: dict[str, float]
    warnings: str | None
    error: str | None


def solve_one(case: Case | RowError, solver: Solve = solve) -> CaseOutcome:
    """Solve one case; a refusal, a solver failure or asymptotes that do not exist are
    recorded, never raised."""
    if isinstance(case, RowError):
        return CaseOutcome(None, {}, None, case.message)
    try:
        result = solver(case.law, case.loading, case.mu, elements=case.elements, steps=case.steps)
    except InputError as error:
        return CaseOutcome(None, {}, None, str(error))
    except SolverError as error:
        return CaseOutcome(None, {}, None, f"the reference solver did not converge: {error}")
    warnings = list(result.warnings)
    if case.cycle is not None:
        try:
            compared = with_asymptotes(result, case.law, case.cycle, case.mu)
            assert isinstance(compared, SolverResult)
            result = compared
        except InputError as error:  # the solver's answer stands; the asymptotes do not exist
            warnings.append(f"no asymptotic estimates: {error}")
    data = result.to_dict()
    right = edge_values(data, result.is_cycle)
    left = edge_values(data["left"], result.is_cycle)
    solver_record = {f"solver_{name}": _float(data["solver"][name]) for name in SOLVER_NUMBERS}
    text = WARNING_SEPARATOR.join(warnings) if warnings else None
    return CaseOutcome((right, left), solver_record, text, None)


def solve_table(
    table: CaseTable,
    settings: BatchSettings,
    numbers: set[str],
    solver: Solve = solve,
) -> tuple[dict[str, Column], list[tuple[int, str]]]:
    """Every case of ``table``: the result columns (input columns first, two rows a case) and
    the failed cases as (line, message)."""
    outcomes = [solve_one(case_of(table, row, settings), solver) for row in range(len(table))]
    twice = np.repeat(np.arange(len(table)), 2)
    columns: dict[str, Column] = {}
    for name in table.header:
        if name in numbers:
            columns[name] = np.asarray(table.values[name], dtype=np.float64)[twice]
        else:
            columns[name] = TextColumn.take(table.text[name], twice)
    schema = result_schema()
    rows = 2 * len(outcomes)
    filled: dict[str, list[Any]] = {name: [] for name, _ in schema}
    for outcome in outcomes:
        for side, index in zip(EDGES, (0, 1), strict=True):
            filled["edge"].append(side)
            values = outcome.edges[index] if outcome.edges is not None else {}
            for name, kind in schema:
                if name in ("edge", "warnings", "error"):
                    continue
                default = None if kind == "category" else np.nan
                filled[name].append(
                    outcome.solver.get(name, default)
                    if name.startswith("solver_")
                    else values.get(name, default)
                )
            filled["warnings"].append(outcome.warnings)
            filled["error"].append(outcome.error)
    for name, kind in schema:
        if kind == "category":
            columns[name] = Categorical.from_strings(filled[name])
        else:
            columns[name] = np.asarray(filled[name], dtype=np.float64).reshape(rows)
    failed = [
        (int(table.line[row]), outcome.error)
        for row, outcome in enumerate(outcomes)
        if outcome.error is not None
    ]
    return columns, failed
