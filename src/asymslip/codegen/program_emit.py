"""Print :class:`~asymslip.codegen.program.Program` records as NumPy and ``math`` functions.

``asymslip_gen/programs.py`` holds every program on NumPy arrays, ``asymslip_gen/
scalar_programs.py`` the same programs on Python floats.  A formula step is printed as the lines
of that formula's generated function -- its CSE temporaries and its result, by the same printer
-- with the step's name in place of ``return``; where the formula's argument is another
program variable, the argument is bound to it first (``a = a2``), so that the lines read
exactly as in the formula's own function and give the same bits.  Temporaries (``tmp0``, ...)
are reused from step to step: each step's are read only within it.
"""

from __future__ import annotations

import textwrap
from collections.abc import Mapping, Sequence

from sympy.printing.codeprinter import CodePrinter

from .cse import Reduced
from .documentation import PAPER, equation_refs, wrap
from .emit import banner
from .printer import GeneratedCodePrinter
from .program import Program
from .scalar import ScalarCodePrinter

MODULE = "programs"
SCALAR_MODULE = "scalar_programs"


def _equations(program: Program, formulas: Mapping[str, Reduced]) -> list[str]:
    """The paper's equations of the formulas a program evaluates, in the order of its steps."""
    found: list[str] = []
    for step in program.steps:
        if step.formula is not None:
            for number in formulas[step.formula].formula.equations:
                if number not in found:
                    found.append(number)
    return found


def _docstring(program: Program, formulas: Mapping[str, Reduced], scalar: bool) -> str:
    kind, returned = ("float", "float") if scalar else ("array_like", "ndarray or float64")
    equations = _equations(program, formulas)
    label = "Eq." if len(equations) == 1 else "Eqs."
    steps = []
    for step in program.steps:
        if step.formula is not None:
            formula = formulas[step.formula].formula
            where = f" {equation_refs(formula.equations)}" if formula.equations else ""
            steps.append(
                f"{step.name} = {step.formula}({', '.join(step.inputs)}){where}: {formula.summary}"
            )
        else:
            steps.append(f"{step.name} = {step.expr}")
    parameters = "\n".join(
        f"{arg.name} : {kind}\n{textwrap.indent(textwrap.fill(arg.meaning, 88), '    ')}"
        for arg in program.args
    )
    returns = "\n".join(
        f"{output.name} : {returned}\n{textwrap.indent(textwrap.fill(output.meaning, 88), '    ')}"
        for output in program.outputs
    )
    provenance = "\n".join(
        wrap(
            f"Implements {label} {equation_refs(equations)} of the paper through the formulas it "
            f"evaluates; registered in ``{program.source}``.",
            92,
        )
    )
    listed = "\n".join(
        f"{index}. {textwrap.indent(textwrap.fill(text, 84), '   ')[3:]}"
        for index, text in enumerate(steps, start=1)
    )
    body = (
        f"{program.summary}\n\n{textwrap.fill(program.doc, 92)}\n\n{provenance}\n\n"
        f"Parameters\n----------\n{parameters}\n\n"
        f"Returns\n-------\n{returns}\n\n"
        f"Notes\n-----\nThe steps, each a formula's own generated lines or a glue expression:\n\n"
        f"{listed}\n"
    )
    return '"""' + body + '"""'


def _body(program: Program, formulas: Mapping[str, Reduced], printer: CodePrinter) -> list[str]:
    """The lines of a program's function body (without the docstring)."""
    variables = program.variables
    lines: list[str] = []
    for step in program.steps:
        if step.expr is not None:
            lines.append(f"{step.name} = {printer.doprint(step.expr)}")
            continue
        assert step.formula is not None
        try:
            reduced = formulas[step.formula]
        except KeyError:
            raise ValueError(
                f"program {program.name}: step {step.name} calls {step.formula!r}, which no "
                "derivation emits"
            ) from None
        formula = reduced.formula
        if len(step.inputs) != len(formula.args):
            raise ValueError(
                f"program {program.name}: step {step.name} gives {len(step.inputs)} inputs to "
                f"{formula.name}, which takes {len(formula.args)}"
            )
        used = {symbol.name for symbol in reduced.result.free_symbols}
        for _, value in reduced.temporaries:
            used.update(symbol.name for symbol in value.free_symbols)
        for arg, value in zip(formula.args, step.inputs, strict=True):
            if arg.name == value or arg.name not in used:
                continue
            if arg.name in variables:
                raise ValueError(
                    f"program {program.name}: step {step.name} would bind {formula.name}'s "
                    f"argument {arg.name} to {value}, but {arg.name} is a program variable"
                )
            lines.append(f"{arg.name} = {value}")
        for temporary, value in reduced.temporaries:
            lines.append(f"{temporary} = {printer.doprint(value)}")
        lines.append(f"{step.name} = {printer.doprint(reduced.result)}")
    lines.append(f"return ({', '.join(output.name for output in program.outputs)},)")
    return lines


def render_program(
    program: Program, formulas: Mapping[str, Reduced], printer: CodePrinter, scalar: bool
) -> str:
    """One ``def`` for ``program``; ``scalar`` for Python floats (``math``), else NumPy."""
    kind, returned = ("float", "float") if scalar else ("ArrayLike", "FloatArray")
    signature = ", ".join(f"{arg.name}: {kind}" for arg in program.args)
    head = f"def {program.name}({signature}) -> tuple[{returned}, ...]:"
    body = [_docstring(program, formulas, scalar), *_body(program, formulas, printer)]
    return head + "\n" + textwrap.indent("\n".join(body), "    ") + "\n"


def _sources(programs: Sequence[Program], formulas: Mapping[str, Reduced]) -> list[str]:
    sources = {program.source for program in programs}
    for program in programs:
        sources.update(
            formulas[step.formula].formula.source
            for step in program.steps
            if step.formula is not None and step.formula in formulas
        )
    return sorted(sources)


_DOC_TEXT = (
    "Each program is a record of steps over the formulas of the other modules (one contact "
    "edge's estimates, a contact law's quantities at both states of a cycle); a formula "
    "step is that formula's own generated lines, so a program gives the bits of its "
    "formulas called one by one, without the cost of the calls.  {twin}"
)


def render_programs_module(
    programs: Sequence[Program], formulas: Mapping[str, Reduced], scalar: bool
) -> str:
    """Source of ``asymslip_gen/programs.py`` (NumPy) or ``scalar_programs.py`` (``math``)."""
    printer: CodePrinter = ScalarCodePrinter() if scalar else GeneratedCodePrinter()
    functions = "\n\n".join(render_program(p, formulas, printer, scalar) for p in programs)
    names = [program.name for program in programs]
    if len(set(names)) != len(names):
        raise ValueError(f"programs registered twice: {names}")
    exported = "\n".join(f'    "{name}",' for name in names)
    if scalar:
        what = "Python floats (``math``)"
        twin = "The NumPy twins are in ``asymslip_gen.programs``."
        imports = "import math\n\n" if "math." in functions else ""
    else:
        what = "NumPy arrays"
        twin = "The ``math`` twins, for one value at a time, are in ``scalar_programs``."
        imports = (
            "import numpy\nfrom numpy.typing import ArrayLike, NDArray\n\n"
            "FloatArray = NDArray[numpy.float64] | numpy.float64\n\n"
        )
    # Filled after the twin's sentence is in, so that no line passes the line length.
    doc = (
        f"Programs: several generated formulas evaluated in one function, on {what}.\n\n"
        + textwrap.fill(_DOC_TEXT.format(twin=twin), width=92)
        + f"\n\nSee {PAPER}.\n"
    )
    return (
        banner(_sources(programs, formulas)) + f'"""{doc}"""\n\n'
        "from __future__ import annotations\n\n"
        f"{imports}"
        f"__all__ = [\n{exported}\n]\n\n\n" + functions
    )
