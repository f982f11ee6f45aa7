"""What every language backend provides, and how a function is found unprintable."""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field

import sympy
from sympy.printing.codeprinter import CodePrinter

from ..cse import Reduced

#: Why a special function is missing, by SymPy function name and language (for the notes).
SPECIAL_FUNCTION_NOTES: dict[str, str] = {
    "hyper": "a hypergeometric function",
    "meijerg": "a Meijer G-function",
    "zeta": "the Riemann zeta function",
    "polylog": "a polylogarithm",
    "lerchphi": "the Lerch transcendent",
    "besselj": "a Bessel function",
    "bessely": "a Bessel function",
    "elliptic_k": "a complete elliptic integral",
    "elliptic_e": "a complete elliptic integral",
    "gamma": "the gamma function",
    "loggamma": "the log-gamma function",
    "erf": "the error function",
}


@dataclass(frozen=True)
class Rendered:
    """The files of one language: name -> text, and what went in and what was left out."""

    files: dict[str, str]
    functions: tuple[str, ...]
    left_out: dict[str, str] = field(default_factory=dict)


@dataclass(frozen=True)
class Language:
    """A target language: its name, its folder under ``generated/`` and its renderer."""

    name: str
    folder: str
    render: Callable[[Sequence[Reduced], Mapping[str, str]], Rendered]
    #: File extensions the renderer writes; stale files with these are removed on writing.
    extensions: tuple[str, ...]


def unprintable_functions(printer: CodePrinter, reduced: Reduced) -> list[str]:
    """Names of the functions in ``reduced`` that ``printer`` (strict) cannot print, sorted."""
    expressions = [value for _, value in reduced.temporaries] + [reduced.result]
    failing = set()
    for expr in expressions:
        for function in expr.atoms(sympy.Function):
            try:
                printer.doprint(function)
            except NotImplementedError:
                failing.add(function)
    # log(hyper(...)) fails because of hyper: name only the innermost culprits.
    innermost = {f for f in failing if not any(g != f and f.has(g) for g in failing)}
    return sorted({type(function).__name__ for function in innermost})


def left_out_reason(missing: Sequence[str], language: str) -> str:
    """One sentence: which functions the target lacks (and what they are)."""
    described = [
        f"{name} ({SPECIAL_FUNCTION_NOTES[name]})" if name in SPECIAL_FUNCTION_NOTES else name
        for name in missing
    ]
    return f"needs {', '.join(described)}, which {language} does not provide"
