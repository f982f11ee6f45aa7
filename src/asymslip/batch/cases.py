"""The cases of ``solve-batch``: one load cycle or load path per row, with its own friction,
law parameters and grid where the row gives them.

Columns (any order; others are copied to the results):

- ``P1, Q1, P2, Q2`` and optionally ``sigma1, sigma2`` (default 0): the paper's cycle, as
  ``solve --P1 ...``;
- or ``path``: a closed load path, its points separated by ``;`` and each point's
  ``P Q [sigma [M]]`` by spaces, e.g. ``100 -5; 120 0; 100 5`` (as the rows of
  ``solve --path PATH.csv``).  A row gives either the cycle or a path, not both;
- ``mu``: the coefficient of friction (default ``--mu``);
- the law's parameters, named as in the API -- ``R, E_star`` (hertz), ``c, R, E_star``
  (flat-rounded: ``c`` is the flat's half-width), ``A, n, E_star`` (power) -- each overriding
  the command line's value for its row;
- ``elements``, ``steps``: the solver's grid and load steps (default ``--elements``,
  ``--steps``).

An empty field takes the default.  A row that breaks a rule becomes a :class:`RowError`
naming the column and the rule (``R: must be > 0 (got -1.0)``) and is reported in its result
rows; the other rows go on.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..cycle import LoadCycle
from ..errors import InputError
from ..files import CaseTable
from ..laws import ContactLaw, FlatRoundedLaw, HertzLaw, PowerLaw
from ..rules import Verdict, check_friction, check_partial_slip
from ..solver import DEFAULT_ELEMENTS, DEFAULT_STEPS, LoadPath

CYCLE_COLUMNS = ("P1", "Q1", "P2", "Q2", "sigma1", "sigma2")
#: The laws whose profile the solver takes, and their parameters (API names) in order.
LAW_PARAMETERS: dict[str, tuple[str, ...]] = {
    "hertz": ("R", "E_star"),
    "flat-rounded": ("c", "R", "E_star"),
    "power": ("A", "n", "E_star"),
}
_CONSTRUCTORS: dict[str, type[ContactLaw]] = {
    "hertz": HertzLaw,
    "flat-rounded": FlatRoundedLaw,
    "power": PowerLaw,
}
SETTING_COLUMNS = ("mu", "elements", "steps")
#: Every column read as a number where present.
NUMERIC_COLUMNS = tuple(
    dict.fromkeys(
        [*CYCLE_COLUMNS, *SETTING_COLUMNS, *(p for ps in LAW_PARAMETERS.values() for p in ps)]
    )
)
_POINT_SEPARATOR = re.compile(r"\s*;\s*")


@dataclass(frozen=True)
class BatchSettings:
    """What the command line gives for every row (a row's own columns override it).

    Attributes
    ----------
    law
        ``hertz``, ``flat-rounded`` or ``power``.
    parameters
        The law's parameters given for all rows, ``(name, value)`` pairs.
    mu, elements, steps
        Defaults of the rows' ``mu``, ``elements``, ``steps``.
    """

    law: str = "hertz"
    parameters: tuple[tuple[str, float], ...] = ()
    mu: float | None = None
    elements: int = DEFAULT_ELEMENTS
    steps: int = DEFAULT_STEPS

    def __post_init__(self) -> None:
        if self.law not in LAW_PARAMETERS:
            raise InputError(
                "law",
                "solve-batch takes a law with a profile: " + ", ".join(LAW_PARAMETERS),
                self.law,
            )


@dataclass(frozen=True)
class Case:
    """One row, ready for the solver."""

    law: ContactLaw
    loading: LoadCycle | LoadPath
    mu: float
    elements: int
    steps: int

    @property
    def cycle(self) -> LoadCycle | None:
        """The paper's cycle (the asymptotes exist for it), or None for a path."""
        return self.loading if isinstance(self.loading, LoadCycle) else None


@dataclass(frozen=True)
class RowError:
    """Why a row cannot be solved: the message names the column and the rule."""

    message: str


def check_header(header: list[str], settings: BatchSettings, option: str = "cases") -> None:
    """Refuse a table that cannot describe a case: neither the cycle's columns nor ``path``,
    or no friction coefficient anywhere."""
    cycle = [name for name in ("P1", "Q1", "P2", "Q2") if name in header]
    if "path" not in header and len(cycle) < 4:
        missing = [name for name in ("P1", "Q1", "P2", "Q2") if name not in header]
        raise InputError(
            option,
            f"the header has no column {', '.join(missing)} and no path column: each row needs "
            "a cycle (P1, Q1, P2, Q2) or a load path (path)",
        )
    if settings.mu is None and "mu" not in header:
        raise InputError("mu", "is required: give --mu or a mu column in the cases")
    for name in LAW_PARAMETERS[settings.law]:
        given = dict(settings.parameters)
        if name not in given and name not in header:
            raise InputError(name, f"is required with --law {settings.law} (or a {name} column)")


def _number(table: CaseTable, name: str, row: int) -> float | None:
    """The row's value of a numeric column, None where it is absent or empty."""
    if name not in table.values or table.empty[name][row]:
        return None
    return float(table.values[name][row])


def _whole(name: str, value: float, minimum: int) -> int:
    if not np.isfinite(value) or not float(value).is_integer() or value < minimum:
        raise InputError(name, f"must be a whole number >= {minimum}", value)
    return int(value)


def parse_path(text: str) -> LoadPath:
    """``"100 -5; 120 0; 100 5"`` -> a :class:`LoadPath` (points P Q [sigma [M]]).

    Examples
    --------
    >>> parse_path("100 -5; 120 0 0.1; 100 5").points.tolist()
    [[100.0, -5.0, 0.0, 0.0], [120.0, 0.0, 0.1, 0.0], [100.0, 5.0, 0.0, 0.0]]
    """
    points: list[list[float]] = []
    for number, point in enumerate(_POINT_SEPARATOR.split(text.strip().strip(";")), start=1):
        fields = point.split()
        if not 2 <= len(fields) <= 4:
            raise InputError(
                "path", f"point {number} must be 'P Q [sigma [M]]' separated by spaces", point
            )
        try:
            values = [float(field) for field in fields]
        except ValueError:
            raise InputError(
                "path", f"point {number} holds something not a number", point
            ) from None
        points.append(values + [0.0] * (4 - len(values)))
    if not all(np.isfinite(points).ravel()):
        raise InputError("path", "every value must be finite", text)
    return LoadPath(np.asarray(points, dtype=np.float64))


def _law(table: CaseTable, row: int, settings: BatchSettings) -> ContactLaw:
    values: dict[str, Any] = dict(settings.parameters)
    for name in LAW_PARAMETERS[settings.law]:
        own = _number(table, name, row)
        if own is not None:
            values[name] = own
    return _CONSTRUCTORS[settings.law](**values)


def _loading(table: CaseTable, row: int, mu: float) -> LoadCycle | LoadPath:
    path = table.text["path"][row].strip() if "path" in table.text else ""
    given = [name for name in ("P1", "Q1", "P2", "Q2") if _number(table, name, row) is not None]
    if path:
        if given or any(_number(table, name, row) is not None for name in ("sigma1", "sigma2")):
            raise InputError("path", "a row gives either a path or the cycle's P1 ... Q2, not both")
        loading = parse_path(path)
        loading.check_partial_slip(mu)
        return loading
    loads = []
    for name in CYCLE_COLUMNS:
        value = _number(table, name, row)
        if value is None:
            if name.startswith("sigma"):
                value = 0.0
            else:
                raise InputError(name, "missing value (or give a path)")
        loads.append(value)
    cycle = LoadCycle(*loads)
    # Gross sliding by the rules slip-zone applies, naming Q1 or Q2 (the solver's own check
    # would name the path's points).
    verdict = Verdict(())
    check_partial_slip(verdict, np.float64(mu), cycle.values())  # type: ignore[arg-type]
    verdict.raise_first()
    return cycle


def case_of(table: CaseTable, row: int, settings: BatchSettings) -> Case | RowError:
    """Row ``row`` of ``table`` as a :class:`Case`, or the first rule it breaks."""
    if row in table.errors:
        return RowError(table.errors[row])
    try:
        own_mu = _number(table, "mu", row)
        mu = own_mu if own_mu is not None else settings.mu
        if mu is None:
            raise InputError("mu", "missing (give --mu or a value in the mu column)")
        verdict = Verdict(())
        check_friction(verdict, np.float64(mu))  # type: ignore[arg-type]
        verdict.raise_first()
        elements = _number(table, "elements", row)
        steps = _number(table, "steps", row)
        return Case(
            law=_law(table, row, settings),
            loading=_loading(table, row, mu),
            mu=float(mu),
            elements=settings.elements if elements is None else _whole("elements", elements, 1),
            steps=settings.steps if steps is None else _whole("steps", steps, 1),
        )
    except InputError as error:
        return RowError(str(error))
