"""The formula records as data: ``generated/asymslip_gen/formulas.json``, written and read back.

``make generate`` writes every emitted formula -- name, module, derivation, equations, summary,
documentation, each argument (its symbol with its assumptions, and its meaning) and the
expression as ``sympy.srepr`` -- into the generated package, where it ships as package data.
Code that needs a derived expression at run time (``asymslip derive`` needs the calibration
(19)) reads it from there with :func:`packaged_formulas`, never by importing ``derivations/``.

Reading is safe: the ``srepr`` text is parsed with :mod:`ast` and only calls of SymPy
expression classes with literal arguments are evaluated (no ``eval``, no names beyond SymPy's
expression classes), so a tampered file cannot run code.
"""

from __future__ import annotations

import ast
import json
from collections.abc import Sequence
from typing import Any

import sympy
import sympy.codegen.cfunctions
import sympy.core.numbers
from sympy.core.assumptions import _assume_defined

from .formula import Argument, Formula

FILE = "formulas.json"
FORMAT = 1


def _expression_classes() -> dict[str, type]:
    classes: dict[str, type] = {}
    for namespace in (sympy, sympy.core.numbers, sympy.codegen.cfunctions):
        for name, value in vars(namespace).items():
            if isinstance(value, type) and issubclass(value, sympy.Basic):
                classes.setdefault(name, value)
    return classes


_CLASSES = _expression_classes()
#: Singletons srepr prints as bare names.
_NAMES = {
    "pi": sympy.pi,
    "E": sympy.E,
    "oo": sympy.oo,
    "zoo": sympy.zoo,
    "nan": sympy.nan,
    "I": sympy.I,
    "EulerGamma": sympy.EulerGamma,
    "Catalan": sympy.Catalan,
}
_KEYWORDS = set(_assume_defined) | {"precision"}


class RecordError(ValueError):
    """A formula record that cannot be read (malformed, or not plain SymPy data)."""


def _build(node: ast.AST) -> Any:
    if isinstance(node, ast.Constant) and isinstance(node.value, (str, int, float, bool)):
        return node.value
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
        value = _build(node.operand)
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            return -value
    if isinstance(node, ast.Name) and node.id in _NAMES:
        return _NAMES[node.id]
    if isinstance(node, (ast.Tuple, ast.List)):
        return tuple(_build(element) for element in node.elts)
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Name):
        cls = _CLASSES.get(node.func.id)
        if cls is None:
            raise RecordError(f"{node.func.id} is not a SymPy expression class")
        keywords: dict[str, object] = {}
        for keyword in node.keywords:
            if keyword.arg is None or keyword.arg not in _KEYWORDS:
                raise RecordError(f"keyword {keyword.arg!r} is not an assumption")
            keywords[keyword.arg] = _build(keyword.value)
        return cls(*(_build(arg) for arg in node.args), **keywords)
    raise RecordError(f"{ast.dump(node)[:60]} is not plain SymPy data")


def expression_from_srepr(text: str) -> sympy.Expr:
    """The expression ``sympy.srepr`` printed as ``text``, rebuilt without ``eval``."""
    try:
        tree = ast.parse(text, mode="eval")
    except SyntaxError as error:
        raise RecordError(f"not an srepr expression: {error.msg}") from None
    return _build(tree.body)


def formula_to_record(formula: Formula) -> dict[str, Any]:
    """One formula as JSON-ready data (a fixed key order: stable bytes)."""
    return {
        "name": formula.name,
        "module": formula.module,
        "source": formula.source,
        "equations": list(formula.equations),
        "summary": formula.summary,
        "doc": formula.doc,
        "returns": formula.returns,
        "args": [
            {"name": arg.name, "symbol": sympy.srepr(arg.symbol), "meaning": arg.meaning}
            for arg in formula.args
        ],
        "expr": sympy.srepr(formula.expr),
    }


def formula_from_record(record: dict[str, Any]) -> Formula:
    """The :class:`Formula` a record describes (its checks run again on construction)."""
    try:
        args = []
        for arg in record["args"]:
            symbol = expression_from_srepr(arg["symbol"])
            if not isinstance(symbol, sympy.Symbol) or symbol.name != arg["name"]:
                raise RecordError(f"argument {arg['name']!r} is not that symbol")
            args.append(Argument(symbol, arg["meaning"]))
        return Formula(
            name=record["name"],
            args=tuple(args),
            expr=expression_from_srepr(record["expr"]),
            equations=tuple(record["equations"]),
            summary=record["summary"],
            doc=record["doc"],
            module=record["module"],
            source=record["source"],
            returns=record["returns"],
        )
    except (KeyError, TypeError) as error:
        raise RecordError(f"malformed formula record: {error!r}") from None


def render_records(
    formulas: Sequence[Formula], languages: dict[str, Sequence[str]] | None = None
) -> str:
    """The text of ``formulas.json``: every formula, in the run's order."""
    records = []
    for formula in formulas:
        record = formula_to_record(formula)
        if languages is not None:
            record["languages"] = list(languages.get(formula.name, ()))
        records.append(record)
    document = {
        "format": FORMAT,
        "about": "Formula records of asymslip_gen, written by `make generate`; do not edit. "
        "expr and each symbol are sympy.srepr text (read with asymslip.codegen.records).",
        "formulas": records,
    }
    return json.dumps(document, indent=1, ensure_ascii=False) + "\n"


def read_records(text: str) -> dict[str, Formula]:
    """Name -> :class:`Formula` from the text of a ``formulas.json``."""
    try:
        document = json.loads(text)
    except json.JSONDecodeError as error:
        raise RecordError(f"not JSON: {error}") from None
    if not isinstance(document, dict) or document.get("format") != FORMAT:
        raise RecordError(f"not a format-{FORMAT} formula record file")
    return {record["name"]: formula_from_record(record) for record in document["formulas"]}


def packaged_formulas() -> dict[str, Formula]:
    """The records shipped with the generated package ``asymslip_gen``."""
    from importlib.resources import files

    return read_records(files("asymslip_gen").joinpath(FILE).read_text(encoding="utf-8"))
