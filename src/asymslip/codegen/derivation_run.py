"""What one run of every derivation script produced: the records the code generator reads."""

from __future__ import annotations

from dataclasses import dataclass, field

from .formula import EquationCheck, Formula
from .program import Program


@dataclass
class DerivationRun:
    """Everything the derivation scripts produced, in a fixed order."""

    formulas: list[Formula] = field(default_factory=list)
    #: Formulas evaluated together in one generated function (asymslip.codegen.program).
    programs: list[Program] = field(default_factory=list)
    checks: list[EquationCheck] = field(default_factory=list)
    module_docs: dict[str, str] = field(default_factory=dict)
    seconds: dict[str, float] = field(default_factory=dict)
    #: The paper's printed equations (number -> LaTeX), display only: the derivations
    #: package's ``PAPER_EQUATIONS``, shown by the report where a check recorded none.
    paper_equations: dict[str, str] = field(default_factory=dict)
