"""The ledger a derivation script fills in: formulas to emit and equations it established.

Usage inside ``derivations/<part>.py``::

    d = Derivation(__file__)
    with d.equation("17", "Stick boundary from the consistency condition") as eq:
        b = solve(...)
        eq.matches_paper(b, printed_b)          # asserts simplify(b - printed_b) == 0
    d.emit(name="stick_boundary", expr=b, ...)
"""

from __future__ import annotations

import time
from collections.abc import Callable, Iterator, Mapping, Sequence
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path

import sympy

from .formula import Argument, EquationCheck, Formula, Status
from .program import Output, Program, Step


class DerivationError(AssertionError):
    """A derived result disagrees with what it was checked against."""


def is_zero(expr: sympy.Expr) -> bool:
    """True when SymPy can prove ``expr == 0`` (simplify first, then the slower ``equals``)."""
    if expr == 0:
        return True
    simplified = sympy.simplify(expr)
    if simplified == 0:
        return True
    return bool(simplified.equals(0))


@dataclass
class EquationStep:
    """One numbered equation being established; concluded by exactly one of its methods."""

    equation: str
    title: str
    source: str
    status: Status | None = None
    how: str = ""
    derived: sympy.Basic | None = None
    printed: str | None = None
    details: list[str] = field(default_factory=list)

    def _conclude(self, status: Status, how: str, derived: sympy.Basic | None) -> None:
        if self.status is not None:
            # The first conclusion names the status; later ones add evidence.
            self.details.append(how)
            return
        self.status, self.how, self.derived = status, how, derived

    def matches_paper(
        self, derived: sympy.Expr, paper: sympy.Expr, *, how: str = "", printed: str | None = None
    ) -> None:
        """Assert the derived expression equals the paper's printed form symbolically."""
        if not is_zero(derived - paper):
            raise DerivationError(
                f"Eq. ({self.equation}): derived form differs from the paper's\n"
                f"  derived: {derived}\n  paper:   {paper}"
            )
        self.printed = printed if printed is not None else self.printed
        self._conclude(Status.DERIVED, how or "derived; simplify(derived - paper) == 0", derived)

    def holds(self, identity: sympy.Expr, *, how: str, derived: sympy.Basic | None = None) -> None:
        """Assert that ``identity`` simplifies to zero (a derived property, not a paper form)."""
        if not is_zero(identity):
            raise DerivationError(f"Eq. ({self.equation}): {how}: residual {identity}")
        self._conclude(Status.DERIVED, how, derived)

    def matches_numerically(
        self,
        derived: Callable[..., object],
        reference: Callable[..., object],
        points: Sequence[Mapping[str, object]],
        *,
        how: str,
        digits: int = 30,
        derived_expr: sympy.Basic | None = None,
        symbolic: bool = False,
    ) -> float:
        """Compare two mpmath-evaluated callables at ``points`` to ``digits - 5`` digits.

        Used where SymPy cannot decide equality, and as an independent check of a symbolic
        result.  With ``symbolic=True`` the status stays "derived" (the numeric check is extra
        evidence); otherwise the equation is recorded as verified numerically.
        Returns the largest relative difference seen.
        """
        import mpmath

        worst = mpmath.mpf(0)
        # Twice the digits asked for: quadrature near endpoint and principal-value
        # singularities cancels about half of the working precision.
        with mpmath.workdps(2 * digits + 10):
            for point in points:
                a = mpmath.mpmathify(derived(**point))
                b = mpmath.mpmathify(reference(**point))
                scale = max(abs(b), mpmath.mpf(10) ** (-digits))
                worst = max(worst, abs(a - b) / scale)
        tolerance = mpmath.mpf(10) ** (-(digits - 5))
        if not worst < tolerance:
            raise DerivationError(
                f"Eq. ({self.equation}): {how}: relative difference {mpmath.nstr(worst, 5)}"
            )
        detail = f"{how} ({len(points)} points, {digits} digits, max rel. diff {float(worst):.1e})"
        if symbolic:
            self.details.append(detail)
        else:
            self._conclude(Status.NUMERIC, detail, derived_expr)
        return float(worst)

    def given(self, how: str, *, derived: sympy.Basic | None = None) -> None:
        """Record an equation the derivations start from (a definition or model assumption)."""
        self._conclude(Status.GIVEN, how, derived)

    def erratum(self, how: str, *, derived: sympy.Basic | None = None) -> None:
        """Record that the paper's printed equation is wrong and what is right instead."""
        self.status, self.how, self.derived = Status.ERRATUM, how, derived

    def beyond_paper(self, how: str, *, derived: sympy.Basic | None = None) -> None:
        """Record a result the paper does not state (a derived extension)."""
        self._conclude(Status.BEYOND, how, derived)


class Derivation:
    """Collects the formulas and equation checks of one derivation script."""

    def __init__(self, script: str) -> None:
        self.source = f"derivations/{Path(script).name}"
        self.formulas: list[Formula] = []
        self.programs: list[Program] = []
        self.checks: list[EquationCheck] = []
        self.module_docs: dict[str, str] = {}

    @contextmanager
    def equation(self, number: str, title: str) -> Iterator[EquationStep]:
        """Time the establishment of one equation; fail if the block concludes nothing."""
        step = EquationStep(number, title, self.source)
        start = time.perf_counter()
        yield step
        seconds = time.perf_counter() - start
        if step.status is None:
            raise DerivationError(f"Eq. ({number}) in {self.source}: the step concluded nothing")
        self.checks.append(
            EquationCheck(
                equation=number,
                title=title,
                status=step.status,
                how=step.how,
                seconds=seconds,
                source=self.source,
                derived=step.derived,
                printed=step.printed,
                details=tuple(step.details),
            )
        )

    def describe_module(self, module: str, doc: str) -> None:
        """Give the module docstring of a generated module this script writes into."""
        self.module_docs[module] = doc

    def emit(
        self,
        *,
        name: str,
        args: Sequence[Argument],
        expr: sympy.Expr,
        equations: Sequence[str],
        summary: str,
        doc: str,
        module: str,
        returns: str = "Broadcast over the arguments.",
    ) -> Formula:
        """Register a derived expression for code generation."""
        formula = Formula(
            name=name,
            args=tuple(args),
            expr=expr,
            equations=tuple(equations),
            summary=summary,
            doc=doc,
            module=module,
            source=self.source,
            returns=returns,
        )
        self.formulas.append(formula)
        return formula

    def emit_program(
        self,
        *,
        name: str,
        args: Sequence[Argument],
        steps: Sequence[Step],
        outputs: Sequence[Output],
        summary: str,
        doc: str,
    ) -> Program:
        """Register a program: formulas (of any script) evaluated in one generated function
        (:mod:`asymslip.codegen.program`)."""
        program = Program(
            name=name,
            args=tuple(args),
            steps=tuple(steps),
            outputs=tuple(outputs),
            summary=summary,
            doc=doc,
            source=self.source,
        )
        self.programs.append(program)
        return program
