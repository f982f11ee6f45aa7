"""C99: one header and one source, ``double asymslip_<name>(double ...)`` per formula.

The functions take the NumPy function's arguments in the same order and compute the same CSE
temporaries (as ``const double``).  They need ``<math.h>`` only (link with ``-lm``).  The
Fortran module exports the same symbols through ``bind(C)``, so this header declares either
library's functions (link one of them).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import sympy
from sympy.printing.c import C99CodePrinter

from ..cse import Reduced
from ..documentation import PAPER, banner_lines, commented, function_lines, wrap
from ..printer import BranchFree
from .base import Language, Rendered, left_out_reason, unprintable_functions

HEADER = "asymslip_gen.h"
SOURCE = "asymslip_gen.c"
#: pi to 21 significant digits: the nearest double is numpy.pi, whatever the compiler rounds.
PI_NAME = "asymslip_pi"
PI_VALUE = sympy.N(sympy.pi, 21)


class CGeneratedPrinter(BranchFree, C99CodePrinter):
    """C99 printer for generated code: strict, no POSIX-only macros, pi as a named constant.

    ``M_PI`` is not ISO C, so SymPy's math macros are switched off and pi prints as the
    source's ``asymslip_pi`` constant (rather than a declaration SymPy would prepend to every
    expression).  Unknown functions raise instead of printing a comment (``strict``), so that
    a formula C cannot express is left out, never emitted half-printed.
    """

    def __init__(self) -> None:
        super().__init__({"math_macros": {}, "strict": True})

    def _print_Pi(self, expr: sympy.Expr) -> str:
        return PI_NAME

    def _print_sign(self, expr: sympy.Expr) -> str:
        # SymPy's C sign is an int expression; fabs of an int is an error under -Werror.
        argument = self._print(expr.args[0])
        return f"((double)(((({argument}) > 0)) - ((({argument}) < 0))))"


def _comment_safe(text: str) -> str:
    """Prose inside a C comment: "E*/2" would end the comment, so "*/" gets a space."""
    return text.replace("*/", "* /")


def _block_comment(lines: Sequence[str], opening: str = "/*") -> str:
    return opening + "\n" + commented([_comment_safe(line) for line in lines], " *") + " */\n"


def _c_name(formula_name: str) -> str:
    return f"asymslip_{formula_name}"


def _signature(reduced: Reduced, printer: CGeneratedPrinter) -> tuple[str, dict[str, str]]:
    names = {arg.name: printer.doprint(arg.symbol) for arg in reduced.formula.args}
    params = [f"double {names[arg.name]}" for arg in reduced.formula.args] or ["void"]
    head = f"double {_c_name(reduced.formula.name)}("
    if len(head) + len(", ".join(params)) + 2 <= 100:
        return head + ", ".join(params) + ")", names
    # One parameter per line when the prototype would not fit in 100 columns.
    return head + "\n" + ",\n".join(f"    {param}" for param in params) + ")", names


def _definition(reduced: Reduced, printer: CGeneratedPrinter) -> str:
    signature, _ = _signature(reduced, printer)
    formula = reduced.formula
    lines = [f"/* {_comment_safe(formula.summary)} See {HEADER}. */", signature, "{"]
    used = {symbol.name for symbol in formula.expr.free_symbols}
    for arg in formula.args:
        if arg.name not in used:
            # Same arguments as the NumPy function, even where this formula ignores one.
            lines.append(f"    (void){printer.doprint(arg.symbol)};")
    for temporary, value in reduced.temporaries:
        lines.append(f"    const double {printer.doprint(temporary)} = {printer.doprint(value)};")
    lines.append(f"    return {printer.doprint(reduced.result)};")
    lines.append("}")
    return "\n".join(lines) + "\n"


def _left_out_note(left_out: Mapping[str, str]) -> str:
    if not left_out:
        return ""
    lines = ["Left out of the C files (the NumPy package has them):"]
    for name, reason in sorted(left_out.items()):
        lines += wrap(f"- {_c_name(name)}: {reason}.")
    return _block_comment(lines) + "\n"


def render_c(reduced: Sequence[Reduced], module_docs: Mapping[str, str]) -> Rendered:
    """``asymslip_gen.h`` and ``asymslip_gen.c`` for every formula C can express."""
    kept: list[Reduced] = []
    left_out: dict[str, str] = {}
    for item in reduced:
        missing = unprintable_functions(CGeneratedPrinter(), item)
        if missing:
            left_out[item.formula.name] = left_out_reason(missing, "C99's <math.h>")
        else:
            kept.append(item)
    sources = [item.formula.source for item in reduced]
    banner = _block_comment(banner_lines(sources))
    intro = [
        "The formulas of the paper (" + PAPER + "), derived by SymPy and emitted as C99 "
        "functions of doubles, from the same records as the NumPy package asymslip_gen.",
        "",
        "Each function evaluates one formula at one point; the arguments are those of the "
        "NumPy function of the same name, in the same order.  Outside the documented domain "
        "the result is whatever IEEE arithmetic gives (NaN, inf): check inputs first.  Needs "
        "<math.h> only (link with -lm).  The Fortran module in generated/fortran exports the "
        "same symbols through bind(C); link one of the two.",
    ]
    declarations: list[str] = []
    definitions: list[str] = []
    module = None
    for item in kept:
        formula = item.formula
        if formula.module != module:
            module = formula.module
            heading = [f"{module}: {module_docs.get(module, '').splitlines()[0]}"]
            declarations.append(_block_comment(wrap(heading[0]), "/* " + "-" * 92))
        printer = CGeneratedPrinter()
        signature, names = _signature(item, printer)
        doc = function_lines(formula, names)
        declarations.append(_block_comment(doc, "/**") + signature + ";\n")
        definitions.append(_definition(item, printer))
    note = _left_out_note(left_out)
    uses_pi = any(item.formula.expr.has(sympy.pi) for item in kept)
    header = (
        banner
        + "\n"
        + _block_comment([HEADER, "", *wrap(intro[0]), "", *wrap(intro[2])])
        + "\n"
        + "#ifndef ASYMSLIP_GEN_H\n#define ASYMSLIP_GEN_H\n\n"
        + '#ifdef __cplusplus\nextern "C" {\n#endif\n\n'
        + note
        + "\n".join(declarations)
        + "\n#ifdef __cplusplus\n}\n#endif\n\n#endif /* ASYMSLIP_GEN_H */\n"
    )
    source = (
        banner
        + f"\n/* Definitions of the functions declared and documented in {HEADER}. */\n\n"
        + f'#include <math.h>\n\n#include "{HEADER}"\n\n'
        + (f"static const double {PI_NAME} = {PI_VALUE};\n\n" if uses_pi else "")
        + note
        + "\n".join(definitions)
    )
    return Rendered(
        files={HEADER: header, SOURCE: source},
        functions=tuple(item.formula.name for item in kept),
        left_out=left_out,
    )


C_LANGUAGE = Language(name="C", folder="c", render=render_c, extensions=(".c", ".h"))
