"""One chunk of cases through the core: result columns, per-row errors, encoded warnings.

Rows are checked by exactly the rules the API checks (:mod:`asymslip.rules`, through
:func:`asymslip.slip_zones.evaluate`), so a bad row gets the message ``slip_zone`` would raise
for it.  Warnings are bit flags per row; each distinct combination is put into words once
(dictionary encoding), so a million rows cost a handful of strings.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..cycle import LoadCycle
from ..edge_flags import MEASURE_KEYS, NUMBER_KEYS, warning_texts
from ..laws.base import ContactLaw
from ..slip_zones import evaluate
from .columns import CYCLE_COLUMNS, PREFIX, WARNING_SEPARATOR, Edges, edges_of

FloatArray = NDArray[np.float64]


@dataclass
class Encoded:
    """A text column as codes into a list of distinct texts."""

    codes: NDArray[np.intp]
    categories: list[str]

    def texts(self) -> list[str]:
        return [self.categories[code] if code >= 0 else "" for code in self.codes.tolist()]


@dataclass
class ChunkResult:
    """The result columns of one chunk (NaN where a row is invalid) and each row's error."""

    numbers: dict[str, FloatArray]
    warnings: dict[str, Encoded]
    errors: list[str | None]


def _warnings_column(
    flags: NDArray[np.int64], valid: NDArray[np.bool_], law: ContactLaw
) -> Encoded:
    """Code -1 (an empty field, a Parquet null) for no warnings and for invalid rows (which
    have only their error); each distinct set of warnings in words once."""
    flags = np.where(valid, flags, 0)
    distinct, codes = np.unique(flags, return_inverse=True)
    categories = [
        WARNING_SEPARATOR.join(warning_texts(int(value), law)) for value in distinct.tolist()
    ]
    codes = codes.reshape(-1)
    if distinct.size and distinct[0] == 0:  # no warnings: no value
        codes = codes - 1
        categories = categories[1:]
    return Encoded(codes, categories)


def evaluate_chunk(
    law: ContactLaw,
    values: dict[str, FloatArray],
    mu: FloatArray,
    edge: Edges,
    errors: list[str | None],
) -> ChunkResult:
    """Evaluate the rows whose parsing gave no error; mark the others with the API's rules.

    ``values`` holds the cycle columns (:data:`CYCLE_COLUMNS`) as float arrays; ``errors`` the
    parsing errors so far (None for a row that parsed).
    """
    rows = len(errors)
    parsed = np.array([error is None for error in errors], dtype=bool)
    # Rows that did not parse are evaluated on a valid stand-in and keep their parse error.
    stand_in = {"P1": 1.0, "Q1": 0.0, "P2": 2.0, "Q2": 0.0, "sigma1": 0.0, "sigma2": 0.0}
    loads = [np.where(parsed, values[name], stand_in[name]) for name in CYCLE_COLUMNS]
    friction = np.where(parsed, mu, 1.0)
    evaluation = evaluate(law, LoadCycle.unchecked(*loads), friction)
    messages = evaluation.verdict.messages()
    errors = [
        error if error is not None else message
        for error, message in zip(errors, messages, strict=True)
    ]
    valid = np.array([error is None for error in errors], dtype=bool)
    numbers: dict[str, FloatArray] = {}
    warnings: dict[str, Encoded] = {}
    for side in edges_of(edge):
        edge_values = evaluation.edges[side]
        for key in (*NUMBER_KEYS, *MEASURE_KEYS):
            column = np.broadcast_to(
                np.asarray(getattr(edge_values, key), dtype=np.float64), (rows,)
            )
            numbers[PREFIX[side] + key] = np.where(valid, column, np.nan)
        flags = np.broadcast_to(np.asarray(edge_values.flags, dtype=np.int64), (rows,))
        warnings[PREFIX[side] + "warnings"] = _warnings_column(flags, valid, law.for_edge(side))
    return ChunkResult(numbers, warnings, errors)
