"""Formulas typed by a user (a contact law P(a), a profile h(x)), read safely into SymPy.

SymPy's parser evaluates Python, so the text is screened token by token first: only numbers,
the declared names, a whitelist of functions and constants, arithmetic and parentheses reach
it, with no builtins in its namespace.  The size is bounded before anything is parsed (a
100 kB formula would otherwise exhaust the recursion limit deep inside SymPy).

Used by ``asymslip derive`` (a law P(a)) and by the reference solver (a profile h(x)).  SymPy
is imported only when a formula is parsed (the ``derive`` extra), never at import time.

Examples
--------
>>> from asymslip.expressions import screen_formula
>>> screen_formula("pi*E_star*a**2/(4*R)", "a", ["R", "E_star"], "P_of_a")  # passes
>>> screen_formula("a.__class__", "a", [], "P_of_a")  # doctest: +ELLIPSIS
Traceback (most recent call last):
    ...
asymslip.errors.InputError: P_of_a: '.' is not allowed: ...
"""

from __future__ import annotations

import io
import keyword
import re
import sys
import tokenize
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from typing import Any

from .errors import InputError

#: Functions a formula may use (SymPy names); each has a NumPy counterpart, as do the
#: derivatives a derivation takes.
ALLOWED_FUNCTIONS = (
    "sqrt",
    "cbrt",
    "exp",
    "log",
    "sin",
    "cos",
    "tan",
    "asin",
    "acos",
    "atan",
    "atan2",
    "sinh",
    "cosh",
    "tanh",
    "asinh",
    "acosh",
    "atanh",
    "Abs",
)
#: Constants a formula may use.
ALLOWED_CONSTANTS = ("pi", "E")
#: Functions refused with a reason (they would need SciPy at run time, or are not smooth).
REFUSED_FUNCTIONS = {
    "gamma": "NumPy has no gamma function (the law would need SciPy at run time)",
    "erf": "NumPy has no vectorised erf (the law would need SciPy at run time)",
    "Max": "its derivative is a step function, which generated code does not allow",
    "Min": "its derivative is a step function, which generated code does not allow",
}
#: Longest formula accepted, in characters.  A contact law or a profile is a line or two; the
#: bound keeps SymPy's recursive parser and simplifier far from Python's recursion limit.
MAX_CHARACTERS = 2000
#: Deepest nesting of parentheses accepted (each level is a recursion in the parser).
MAX_NESTING = 30

_OPERATORS = {"+", "-", "*", "/", "**", "^", "(", ")", ","}
_NUMBER = re.compile(r"^(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$")
IDENTIFIER = re.compile(r"^[A-Za-z][A-Za-z0-9_]*$")
# Names generated modules use themselves; a parameter must not shadow them.
_RESERVED = {"numpy", "ArrayLike", "NDArray", "FloatArray", "annotations"}


#: How a formula's parameters are given, by the option the formula came in.
_PARAMETER_HINT = {
    "P_of_a": "declare parameters with --params; ",
    "profile": "give each parameter's value with --param NAME=VALUE; ",
}


def allowed_names(variable: str, params: Sequence[str]) -> list[str]:
    """Every name a formula in ``variable`` with these parameters may use."""
    return [variable, *params, *ALLOWED_FUNCTIONS, *ALLOWED_CONSTANTS]


def check_params(params: Sequence[str], variable: str, option: str = "params") -> list[str]:
    """Validate parameter names: identifiers, distinct, not the variable, no function/keyword."""
    params = list(params)
    for name in params:
        if not IDENTIFIER.match(name):
            raise InputError(
                option,
                "each parameter must be a name of letters, digits and _ starting with a letter",
                name,
            )
        if (
            keyword.iskeyword(name)
            or name in _RESERVED
            or name == variable
            or name.startswith("tmp")
        ):
            raise InputError(
                option,
                f"this name is reserved ({variable} is the variable; "
                "tmp*, numpy and Python keywords are taken)",
                name,
            )
        if name in ALLOWED_FUNCTIONS or name in ALLOWED_CONSTANTS or name in REFUSED_FUNCTIONS:
            raise InputError(option, "this name is a function or constant of formulas", name)
    if len(set(params)) != len(params):
        raise InputError(option, "parameter names must be distinct", " ".join(params))
    return params


def _shown(text: str) -> str:
    """The formula as quoted in a message: whole when short, else its start and its length."""
    return text if len(text) <= 80 else f"{text[:60]}... ({len(text)} characters)"


def screen_formula(text: str, variable: str, params: Sequence[str], option: str) -> None:
    """Refuse anything but numbers, allowed names and arithmetic, before SymPy sees the text.

    Screening the tokens first means that attribute access, strings, subscripts, keywords
    (``lambda``, ``import``) and unknown names never reach SymPy's parser.
    """
    if not text.strip():
        raise InputError(option, f"is empty: give the formula in {variable}")
    if len(text) > MAX_CHARACTERS:
        raise InputError(
            option,
            f"is {len(text)} characters long; at most {MAX_CHARACTERS} "
            "are accepted (write the formula more compactly)",
        )
    allowed = set(allowed_names(variable, params))
    try:
        tokens = list(tokenize.generate_tokens(io.StringIO(text).readline))
    except (tokenize.TokenError, SyntaxError) as error:
        raise InputError(
            option, f"is not a complete formula ({error.args[0]})", _shown(text)
        ) from None
    unknown: list[str] = []
    depth = 0
    for token in tokens:
        kind, string = token.type, token.string
        if kind == tokenize.ENDMARKER or (kind == tokenize.NEWLINE and string == ""):
            continue
        if kind in (tokenize.NEWLINE, tokenize.NL):
            raise InputError(option, "must be a single line", _shown(text))
        if kind == tokenize.NAME:
            if string in REFUSED_FUNCTIONS:
                raise InputError(
                    option, f"{string} is not available: {REFUSED_FUNCTIONS[string]}", _shown(text)
                )
            if string not in allowed and string not in unknown:
                unknown.append(string)
        elif kind == tokenize.NUMBER:
            if not _NUMBER.match(string):
                raise InputError(option, f"{string!r} is not a plain decimal number", _shown(text))
        elif kind == tokenize.OP:
            if string not in _OPERATORS:
                raise InputError(
                    option,
                    f"{string!r} is not allowed: only numbers, names, "
                    "+ - * / ** ^, parentheses and commas",
                    _shown(text),
                )
            depth += {"(": 1, ")": -1}.get(string, 0)
            if depth > MAX_NESTING:
                raise InputError(
                    option, f"nests parentheses more than {MAX_NESTING} deep", _shown(text)
                )
        else:
            raise InputError(
                option,
                f"{string.strip()!r} is not allowed: only numbers, "
                "names, + - * / ** ^, parentheses and commas",
                _shown(text),
            )
    if unknown:
        plural = "s" if len(unknown) > 1 else ""
        raise InputError(
            option,
            f"unknown name{plural} {', '.join(unknown)}: {_PARAMETER_HINT.get(option, '')}"
            f"the names allowed are {', '.join(allowed_names(variable, params))}",
            _shown(text),
        )


def sympy_module() -> Any:
    """SymPy, or an :class:`InputError` naming the extra that provides it."""
    try:
        import sympy
    except ImportError:
        raise InputError(
            "derive",
            "needs SymPy: install asymslip with the derive extra (pip install 'asymslip[derive]')",
        ) from None
    return sympy


def check_numbers(expr: Any, option: str, text: str) -> None:
    """Refuse a formula whose constant parts are not finite real numbers within double range.

    ``expr`` is the unevaluated parse.  Each constant part is evaluated in floating point
    (15 digits, from its parts' values: cheap however large), innermost first, so that a
    tower such as ``9**9**9`` stops at the first level beyond double range and ``1/0``,
    ``log(0)`` or ``sqrt(-1)`` are refused for what they are.  The generated code computes in
    doubles: a constant beyond about 1.8e308 would be inf there, one below 5e-324 zero.
    """
    sympy = sympy_module()
    values: dict[Any, Any] = {}
    stack: list[tuple[Any, bool]] = [(expr, False)]
    while stack:  # children before parents, without recursion (a long sum is a deep tree)
        node, children_done = stack.pop()
        if node in values:
            continue
        if not children_done:
            stack.append((node, True))
            stack.extend((arg, False) for arg in node.args)
            continue
        if not isinstance(node, sympy.Expr) or node.free_symbols:
            continue  # not a constant: its constant parts are checked
        parts = [values.get(arg, arg) for arg in node.args]
        value = (node.func(*parts) if parts else node).evalf(15)
        values[node] = value
        shown = sympy.sstr(node)
        if value.has(sympy.zoo, sympy.nan, sympy.oo, -sympy.oo) or value.is_real is not True:
            raise InputError(
                option,
                f"{_shown(shown)} is not a finite real number (a division "
                "by zero, a logarithm of 0, a root of a negative number?)",
                _shown(text),
            )
        if abs(value) > sys.float_info.max or (value != 0 and float(value) == 0):
            if len(shown) > 40:
                shown = sympy.sstr(sympy.Float(value, 3))
            raise InputError(
                option,
                f"the number {shown} is outside double precision (about "
                "5e-324 to 1.8e308 in magnitude), in which the law is computed",
                _shown(text),
            )


@contextmanager
def _recursion_limit(limit: int) -> Iterator[None]:
    """Python's recursion limit raised to ``limit`` for a while: SymPy's unevaluated parse
    visits the syntax tree recursively, one level per operator of a long sum."""
    old = sys.getrecursionlimit()
    sys.setrecursionlimit(max(old, limit))
    try:
        yield
    finally:
        sys.setrecursionlimit(old)


def parse_formula(
    text: str,
    variable: Any,
    params: Sequence[str],
    *,
    option: str,
) -> tuple[Any, list[Any]]:
    """Parse screened text into a SymPy expression in ``variable`` and the parameters.

    Parameters
    ----------
    text
        The formula, e.g. ``"pi*E_star*a**2/(4*R)"``.
    variable
        The SymPy symbol the formula is a function of (with the assumptions the caller's
        derivation needs, e.g. a positive half-width ``a``).
    params
        Parameter names; each becomes a real symbol.
    option
        The option or parameter named in error messages (``P_of_a``, ``profile``).

    Returns
    -------
    (expression, parameter symbols)

    Raises
    ------
    InputError
        Anything the screen refuses, text SymPy cannot read, or symbols other than the
        variable and the parameters.
    """
    name = variable.name
    params = check_params(params, name)
    text = text.strip()
    screen_formula(text, name, params, option)
    sympy = sympy_module()
    from sympy.parsing.sympy_parser import auto_number, convert_xor, parse_expr, rationalize

    symbols = [sympy.Symbol(param, real=True) for param in params]
    namespace: dict[str, Any] = {name: variable, **dict(zip(params, symbols, strict=True))}
    namespace.update({function: getattr(sympy, function) for function in ALLOWED_FUNCTIONS})
    namespace.update({"pi": sympy.pi, "E": sympy.E})
    # Only the number constructors auto_number writes; no builtins, no SymPy namespace.
    globals_ = {
        "__builtins__": {},
        "Integer": sympy.Integer,
        "Float": sympy.Float,
        "Rational": sympy.Rational,
    }
    transformations = (auto_number, rationalize, convert_xor)
    try:
        # First unevaluated, to check its numbers before SymPy computes them exactly: "9**9**9"
        # would otherwise take minutes (369 million digits).
        # (evaluate=False writes the operators as calls to SymPy's Add, Mul and Pow.)
        operators = {"Add": sympy.Add, "Mul": sympy.Mul, "Pow": sympy.Pow}
        with _recursion_limit(10 * MAX_CHARACTERS):
            unevaluated = parse_expr(
                text,
                local_dict=namespace,
                global_dict=globals_ | operators,
                transformations=transformations,
                evaluate=False,
            )
        if isinstance(unevaluated, sympy.Expr):  # else refused below as not one expression
            check_numbers(unevaluated, option, text)
        expr = parse_expr(
            text, local_dict=namespace, global_dict=globals_, transformations=transformations
        )
    except InputError:
        raise
    except (SyntaxError, TypeError, ValueError, AttributeError, NameError, RecursionError) as error:
        reason = "too deeply nested" if isinstance(error, RecursionError) else str(error)
        raise InputError(
            option, f"is not a formula SymPy can read ({reason})", _shown(text)
        ) from None
    if not isinstance(expr, sympy.Expr):
        raise InputError(option, f"must be one expression in {name}", _shown(text))
    extra = sorted(s.name for s in expr.free_symbols - {variable, *symbols})
    if extra:
        raise InputError(
            option, f"has symbols other than {name} and the parameters: {extra}", _shown(text)
        )
    return expr, symbols
