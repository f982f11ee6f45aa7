"""Fortran 2008: one module ``asymslip_gen``, an elemental ``asymslip_<name>`` per formula.

Each function takes ``real(c_double)`` arguments (the NumPy function's, in the same order) and
works on scalars or conforming arrays alike.  A standard elemental procedure cannot have the
``BIND(C)`` attribute, so each also has a scalar twin ``asymslip_<name>_c`` with
``bind(C, name="asymslip_<name>")`` and arguments by value: C calls it through the same
prototype as the C library (``generated/c/asymslip_gen.h``).

Fortran names are case-insensitive: where two arguments differ only in case (the power law's
``a`` and ``A``), SymPy's name mangling renames the later one (``A_``); the documentation uses
the printed names.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import sympy
from sympy.codegen.cfunctions import expm1, log1p
from sympy.printing.fortran import FCodePrinter

from ..cse import Reduced
from ..documentation import PAPER, banner_lines, commented, function_lines, wrap
from ..printer import BranchFree
from .base import Language, Rendered, left_out_reason, unprintable_functions

MODULE = "asymslip_gen"
FILE = "asymslip_gen.f90"
RESULT = "asymslip_result"
PI_NAME = "asymslip_pi"
PI_VALUE = f"{sympy.N(sympy.pi, 21)}_c_double"
#: Fortran 2008 limits names to 63 characters.
MAX_NAME = 63
#: C's log1p and expm1 (accurate near 0; Fortran has no intrinsic), bound as pure functions.
C_MATH = {
    "log1p": "Natural logarithm of 1 + x, accurate for small x (C99 log1p).",
    "expm1": "exp(x) - 1, accurate for small x (C99 expm1).",
}
C_FUNCTIONS = {"log1p": log1p, "expm1": expm1}
INDENT = "    "


class FortranGeneratedPrinter(BranchFree, FCodePrinter):
    """Free-form Fortran 2008 printer for elemental ``real(c_double)`` functions.

    Configured, not post-processed: ``max``/``min`` get real literals (the intrinsics need
    arguments of one type and kind); ``sign(x)`` is NumPy's sign (0 at 0), not the complex
    ``x/abs(x)`` SymPy writes; ``log1p``/``expm1`` call C's through the module's interface;
    pi is the module's named constant.
    """

    def __init__(self) -> None:
        super().__init__(
            {"standard": 2008, "source_format": "free", "strict": True, "name_mangling": True}
        )

    def _real_literal(self, arg: sympy.Expr) -> str:
        if arg.is_Integer:
            return self._print(sympy.Float(arg))
        return self._print(arg)

    def _print_Max(self, expr: sympy.Max) -> str:
        return f"max({', '.join(self._real_literal(arg) for arg in expr.args)})"

    def _print_Min(self, expr: sympy.Min) -> str:
        return f"min({', '.join(self._real_literal(arg) for arg in expr.args)})"

    def _print_sign(self, expr: sympy.sign) -> str:
        (arg,) = expr.args
        printed = self._print(arg)
        return f"merge(0.0d0, sign(1.0d0, {printed}), {printed} == 0)"

    def _print_log1p(self, expr: log1p) -> str:
        return f"log1p({self._print(expr.args[0])})"

    def _print_expm1(self, expr: expm1) -> str:
        return f"expm1({self._print(expr.args[0])})"

    def _print_Pi(self, expr: sympy.Expr) -> str:
        return PI_NAME


def _continued(head: str, items: Sequence[str], tail: str, indent: str) -> list[str]:
    """``head(items)tail`` on as many ``&``-continued lines as 100 columns need."""
    lines: list[str] = []
    current = f"{indent}{head}("
    for index, item in enumerate(items):
        piece = item + (", " if index < len(items) - 1 else "")
        if len(current) + len(piece) > 96:
            lines.append(current.rstrip() + " &")
            current = indent + INDENT * 2
        current += piece
    if tail.strip() and len(current) + 1 + len(tail) > 100:
        # The result clause goes on a continuation line of its own.
        lines.append(current + ") &")
        current, tail = indent + INDENT * 2 + tail.strip(), ""
        return [*lines, current]
    lines.append(current + ")" + tail)
    return lines


def _declarations(kind: str, names: Sequence[str], indent: str) -> list[str]:
    lines = []
    for start in range(0, len(names), 8):
        lines.append(f"{indent}{kind} :: {', '.join(names[start : start + 8])}")
    return lines


def _function(item: Reduced) -> tuple[str, list[str]]:
    """The elemental function and its C twin; also the C functions it calls."""
    formula = item.formula
    name = f"asymslip_{formula.name}"
    if len(name) + 2 > MAX_NAME:
        raise ValueError(f"{name}_c is longer than Fortran's {MAX_NAME} characters")
    printer = FortranGeneratedPrinter()
    # Arguments must not take the names of the module's constant and C functions.
    printer.used_name.extend([PI_NAME, *C_MATH])
    names = {arg.name: printer.doprint(arg.symbol) for arg in formula.args}
    args = [names[arg.name] for arg in formula.args]
    body: list[str] = []
    for temporary, value in item.temporaries:
        body.extend(printer.doprint(value, assign_to=temporary).splitlines())
    body.extend(printer.doprint(item.result, assign_to=sympy.Symbol(RESULT)).splitlines())
    expressions = [item.result, *(value for _, value in item.temporaries)]
    used_c = sorted(
        name for name, function in C_FUNCTIONS.items() if any(e.has(function) for e in expressions)
    )
    inner = INDENT * 2
    doc = function_lines(formula, names)
    lines = [INDENT + "!> " + doc[0], *commented(doc[1:], "!!", INDENT).splitlines()]
    lines += _continued(f"elemental function {name}", args, f" result({RESULT})", INDENT)
    lines += _declarations("real(c_double), intent(in)", args, inner)
    lines.append(f"{inner}real(c_double) :: {RESULT}")
    lines += _declarations("real(c_double)", [str(t) for t, _ in item.temporaries], inner)
    lines += [inner + line for line in body]
    lines.append(f"{INDENT}end function {name}")
    lines.append("")
    binding_doc = wrap(f"C binding of {name} (scalar arguments by value).")
    lines.append(f"{INDENT}!> {binding_doc[0]}")
    lines += commented(binding_doc[1:], "!!", INDENT).splitlines()
    lines += _continued(f"function {name}_c", args, f" result({RESULT}) &", INDENT)
    lines.append(f'{INDENT * 3}bind(C, name="{name}")')
    lines += _declarations("real(c_double), value, intent(in)", args, inner)
    lines.append(f"{inner}real(c_double) :: {RESULT}")
    lines += _continued(f"{RESULT} = {name}", args, "", inner)
    lines.append(f"{INDENT}end function {name}_c")
    return "\n".join(lines) + "\n", used_c


def render_fortran(reduced: Sequence[Reduced], module_docs: Mapping[str, str]) -> Rendered:
    """``asymslip_gen.f90``: the module with every formula Fortran can express."""
    kept: list[Reduced] = []
    left_out: dict[str, str] = {}
    for item in reduced:
        missing = unprintable_functions(FortranGeneratedPrinter(), item)
        if missing:
            left_out[item.formula.name] = left_out_reason(missing, "Fortran 2008")
        else:
            kept.append(item)
    functions: list[str] = []
    used_c: set[str] = set()
    module = None
    uses_pi = False
    for item in kept:
        if item.formula.module != module:
            module = item.formula.module
            heading = f"{module}: {module_docs.get(module, '').splitlines()[0]}"
            functions.append(
                commented(["-" * 92, *wrap(heading), "-" * 92], "!", INDENT).rstrip("\n")
            )
        text, calls = _function(item)
        functions.append(text)
        used_c.update(calls)
        uses_pi = uses_pi or any(
            expr.has(sympy.pi) for expr in [item.result, *(v for _, v in item.temporaries)]
        )
    sources = [item.formula.source for item in reduced]
    intro = wrap(
        f"The formulas of the paper ({PAPER}), derived by SymPy and emitted as elemental "
        "Fortran 2008 functions of real(c_double), from the same records as the NumPy "
        "package asymslip_gen.  Call asymslip_<name> on scalars or conforming arrays; the "
        "arguments are those of the NumPy function of the same name, in the same order.  "
        "Outside the documented domain the result is whatever IEEE arithmetic gives (NaN, "
        "inf): check inputs first.  From C, call the bind(C) twins through "
        "generated/c/asymslip_gen.h."
    )
    public = [f"asymslip_{item.formula.name}" for item in kept]
    public += [f"asymslip_{item.formula.name}_c" for item in kept]
    lines = [commented(banner_lines(sources), "!").rstrip("\n"), ""]
    lines += [commented(intro, "!").rstrip("\n"), ""]
    if left_out:
        note = ["Left out of this module (the NumPy package has them):"]
        for name, reason in sorted(left_out.items()):
            note += wrap(f"- asymslip_{name}: {reason}.")
        lines += [commented(note, "!").rstrip("\n"), ""]
    lines += [
        f"module {MODULE}",
        f"{INDENT}use, intrinsic :: iso_c_binding, only: c_double",
        f"{INDENT}implicit none",
        f"{INDENT}private",
        "",
    ]
    for name in public:
        lines.append(f"{INDENT}public :: {name}")
    lines.append("")
    if uses_pi:
        lines += [f"{INDENT}real(c_double), parameter :: {PI_NAME} = {PI_VALUE}", ""]
    if used_c:
        lines.append(f"{INDENT}interface")
        for function in sorted(used_c):
            lines += [
                f"{INDENT * 2}!> {C_MATH[function]}",
                f'{INDENT * 2}pure function {function}(x) bind(C, name="{function}")',
                f"{INDENT * 3}import :: c_double",
                f"{INDENT * 3}real(c_double), value, intent(in) :: x",
                f"{INDENT * 3}real(c_double) :: {function}",
                f"{INDENT * 2}end function {function}",
            ]
        lines += [f"{INDENT}end interface", ""]
    lines += ["contains", ""]
    lines += ["\n".join(functions).rstrip("\n"), "", f"end module {MODULE}", ""]
    return Rendered(
        files={FILE: "\n".join(lines)},
        functions=tuple(item.formula.name for item in kept),
        left_out=left_out,
    )


FORTRAN_LANGUAGE = Language(
    name="Fortran", folder="fortran", render=render_fortran, extensions=(".f90",)
)
