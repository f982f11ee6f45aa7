"""Records that a derivation hands to the code generator and to the report.

A derivation script never writes Python source.  It produces :class:`Formula` records (a SymPy
expression plus the metadata the generated function's signature and docstring need) and
:class:`EquationCheck` records (what was established about one of the paper's numbered
equations, how, and how long it took).
"""

from __future__ import annotations

import enum
from dataclasses import dataclass, field

import sympy


class Status(enum.Enum):
    """How a paper equation was established; the strings are what `make verify` prints."""

    GIVEN = "starting point"
    DERIVED = "derived and verified"
    NUMERIC = "verified numerically"
    ERRATUM = "erratum found"
    BEYOND = "beyond the paper"


@dataclass(frozen=True)
class Argument:
    """One parameter of a generated function: its symbol and what it means (with units)."""

    symbol: sympy.Symbol
    meaning: str

    @property
    def name(self) -> str:
        return self.symbol.name


@dataclass(frozen=True)
class Formula:
    """A derived expression to be emitted as one NumPy function.

    Attributes
    ----------
    name
        Python name of the generated function: what the quantity is (``stick_boundary``), never
        its equation number.
    args
        Parameters of the generated function, in order.  Every free symbol of ``expr`` must be
        one of them.
    expr
        The expression exactly as the derivation produced it (never retyped by hand).
    equations
        The paper's equation numbers this formula implements, for docstrings and the report.
    summary
        One line: what the function returns.
    doc
        A paragraph on meaning, units and the domain of validity.
    module
        Generated module name: ``corrective_slip`` -> ``asymslip_gen/corrective_slip.py``.
    source
        The derivation script, named in the module banner.
    returns
        Description of the return value.
    """

    name: str
    args: tuple[Argument, ...]
    expr: sympy.Expr
    equations: tuple[str, ...]
    summary: str
    doc: str
    module: str
    source: str
    returns: str = "Broadcast over the arguments."

    def __post_init__(self) -> None:
        names = [a.name for a in self.args]
        if len(set(names)) != len(names):
            raise ValueError(f"{self.name}: repeated argument names {names}")
        free = {s.name for s in self.expr.free_symbols}
        missing = free - set(names)
        if missing:
            raise ValueError(f"{self.name}: free symbols {sorted(missing)} are not arguments")
        if self.expr.has(sympy.Piecewise, sympy.Heaviside):
            raise ValueError(
                f"{self.name}: Piecewise/Heaviside evaluate every branch in NumPy; "
                "write a branch-free clamped form such as sqrt(Max(0, a1 - x))"
            )
        if self.expr.has(sympy.Derivative, sympy.Integral, sympy.Limit, sympy.Order):
            raise ValueError(f"{self.name}: expression still holds an unevaluated operation")


@dataclass(frozen=True)
class EquationCheck:
    """What was established about one numbered equation of the paper.

    ``printed`` is the paper's form in LaTeX (typed from the paper, used only for display and
    comparison); ``derived`` is the SymPy result the derivation produced.
    """

    equation: str
    title: str
    status: Status
    how: str
    seconds: float
    source: str
    derived: sympy.Basic | None = None
    printed: str | None = None
    details: tuple[str, ...] = field(default_factory=tuple)
