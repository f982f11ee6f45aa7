"""Programs: several formulas evaluated in one generated function, step by step.

A :class:`Program` is the record of a straight-line computation over registered formulas --
one contact edge's estimates, a law's quantities at both states of a cycle -- that the code
generator prints once for NumPy arrays and once for Python floats (``math``), as it prints each
formula.  Each :class:`Step` binds a name either to a registered formula, called with program
variables, or to a small expression of program variables (a ratio, a maximum).  A formula step
is printed as that formula's own CSE'd body, the very lines of its generated function, so a
program gives the bits its formulas give called one by one; only the calls are saved (a Python
call costs more than most formulas' arithmetic on one float).

The records are written by a derivation script (``Derivation.emit_program``); which formulas
exist is known only after every script ran, so a program names its formulas and the code
generator resolves them (:mod:`asymslip.codegen.program_emit`).
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy

from .cse import TEMPORARY_PREFIX
from .formula import Argument


@dataclass(frozen=True)
class Step:
    """One line of a program: ``name`` bound to a formula or to an expression.

    Attributes
    ----------
    name
        The program variable the step defines.
    formula
        The name of a registered formula, called with ``inputs`` (program variables, one per
        argument of the formula, in its order).
    inputs
        See ``formula``.
    expr
        Instead of a formula: an expression of program variables (symbols named like them).
    """

    name: str
    formula: str | None = None
    inputs: tuple[str, ...] = ()
    expr: sympy.Expr | None = None

    def __post_init__(self) -> None:
        if (self.formula is None) == (self.expr is None):
            raise ValueError(f"step {self.name}: give either a formula or an expression")
        if self.expr is not None and self.inputs:
            raise ValueError(f"step {self.name}: an expression step takes no inputs")

    @property
    def reads(self) -> tuple[str, ...]:
        """The program variables the step reads."""
        if self.expr is not None:
            return tuple(sorted(symbol.name for symbol in self.expr.free_symbols))
        return self.inputs


@dataclass(frozen=True)
class Output:
    """One value a program returns: a program variable and what it means (with units)."""

    name: str
    meaning: str


@dataclass(frozen=True)
class Program:
    """A generated function evaluating several formulas in order; see the module docstring.

    Attributes
    ----------
    name
        Python name of the generated function.
    args
        Its parameters, in order.
    steps
        The steps, in the order they run; each reads only arguments and earlier steps.
    outputs
        What it returns, as a tuple in this order.
    summary, doc
        One line on what it returns; a paragraph on its meaning and domain.
    source
        The derivation script that registered it.
    """

    name: str
    args: tuple[Argument, ...]
    steps: tuple[Step, ...]
    outputs: tuple[Output, ...]
    summary: str
    doc: str
    source: str

    def __post_init__(self) -> None:
        known = [arg.name for arg in self.args]
        if len(set(known)) != len(known):
            raise ValueError(f"program {self.name}: repeated argument names {known}")
        for step in self.steps:
            if step.name in known:
                raise ValueError(f"program {self.name}: {step.name} is defined twice")
            unknown = [name for name in step.reads if name not in known]
            if unknown:
                raise ValueError(
                    f"program {self.name}: step {step.name} reads {unknown} before they exist"
                )
            if step.expr is not None and step.expr.has(sympy.Piecewise, sympy.Heaviside):
                raise ValueError(f"program {self.name}: step {step.name} is not branch-free")
            known.append(step.name)
        for name in known:
            if name.startswith(TEMPORARY_PREFIX):
                raise ValueError(f"program {self.name}: {name} collides with CSE temporaries")
        missing = [output.name for output in self.outputs if output.name not in known]
        if missing:
            raise ValueError(f"program {self.name}: outputs {missing} are never computed")

    @property
    def variables(self) -> frozenset[str]:
        """Every name the program defines: its arguments and its steps."""
        return frozenset([*(arg.name for arg in self.args), *(step.name for step in self.steps)])
