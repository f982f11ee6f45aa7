"""Is a file a law module?  Decided by reading it, before any of its code runs.

``--law module --module FILE`` imports FILE, and importing runs its top level.  So the file is
parsed first (:mod:`ast`, nothing executed) and refused unless its top level is what
``asymslip derive`` writes, or the same by hand: a docstring, imports of NumPy and ``math``
(and their typing helpers), literal assignments (``__asymslip_law__``, ``__all__``), type
aliases built from those imports, and function definitions without decorators whose defaults
are literals and whose annotations are type expressions -- none of which runs code of the file
when imported.  It must describe itself (``__asymslip_law__ = {...}`` with a ``params`` list of
names) and define the law's functions.  Only then is it imported
(:func:`asymslip.laws.module_law.import_law_module`); the functions' bodies run when the law is
used, which is what a law module is for.

Examples
--------
>>> from asymslip.laws.module_check import check_law_source
>>> check_law_source('''
... import numpy
... __asymslip_law__ = {"name": "cylinder", "params": ["k"]}
... def load(a, k): return k * a**2
... def load_slope(a, k): return 2 * k * a
... def normal_edge_multiplier(a, k): return numpy.sqrt(2 / a) / numpy.pi * 2 * k * a
... ''', "cylinder.py")
>>> check_law_source("import os\\nos.system('echo hello')\\n", "evil.py")  # doctest: +ELLIPSIS
Traceback (most recent call last):
    ...
asymslip.errors.InputError: module: is not an asymslip law module: line 1 imports os ...
"""

from __future__ import annotations

import ast

from ..errors import InputError

#: The functions every law module defines.
REQUIRED_FUNCTIONS = ("load", "load_slope", "normal_edge_multiplier")
#: What a law module may import (importing runs the imported module's code: only these).
ALLOWED_IMPORTS = frozenset(
    {"numpy", "numpy.typing", "math", "typing", "collections.abc", "__future__"}
)
_WHAT_IT_HOLDS = (
    "a law module holds only its description __asymslip_law__, imports of numpy and math, "
    "literal constants and function definitions; write one with `asymslip derive`"
)


#: What the statements a law module may not hold do when the module is imported.
_STATEMENTS: dict[type, str] = {
    ast.Expr: "evaluates an expression (a call runs code)",
    ast.ClassDef: "defines a class (its body runs)",
    ast.AsyncFunctionDef: "defines an async function",
    ast.If: "runs an if statement",
    ast.For: "runs a loop",
    ast.While: "runs a loop",
    ast.With: "runs a with statement",
    ast.Try: "runs a try statement",
    ast.Delete: "deletes a name",
    ast.AugAssign: "computes a value when imported",
}


def _refuse(path: str, line: int, what: str) -> InputError:
    return InputError(
        "module",
        f"is not an asymslip law module: line {line} {what} ({_WHAT_IT_HOLDS}); nothing of it "
        "was run",
        path,
    )


def _is_literal(node: ast.expr) -> bool:
    try:
        ast.literal_eval(node)
    except (ValueError, TypeError, SyntaxError, MemoryError, RecursionError):
        return False
    return True


def _is_type_expression(node: ast.expr | None, names: set[str]) -> bool:
    """A type written with names the module imported: ``NDArray[numpy.float64] | float``."""
    if node is None or isinstance(node, ast.Constant):
        return True
    if isinstance(node, ast.Name):
        return node.id in names or node.id in {"float", "int", "bool", "None", "tuple", "list"}
    if isinstance(node, ast.Attribute):
        return _is_type_expression(node.value, names)
    if isinstance(node, ast.Subscript):
        return _is_type_expression(node.value, names) and _is_type_expression(node.slice, names)
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.BitOr):
        return _is_type_expression(node.left, names) and _is_type_expression(node.right, names)
    if isinstance(node, ast.Tuple | ast.List):
        return all(_is_type_expression(item, names) for item in node.elts)
    return False


def _check_function(node: ast.FunctionDef, path: str, names: set[str], lazy: bool) -> None:
    if node.decorator_list:
        raise _refuse(path, node.lineno, f"decorates the function {node.name}")
    arguments = node.args
    for default in [*arguments.defaults, *(d for d in arguments.kw_defaults if d is not None)]:
        if not _is_literal(default):
            raise _refuse(path, default.lineno, f"computes a default of {node.name}")
    if lazy:  # `from __future__ import annotations`: annotations are never evaluated
        return
    annotated = [
        item.annotation
        for item in [*arguments.posonlyargs, *arguments.args, *arguments.kwonlyargs]
        if item.annotation is not None
    ] + [node.returns]
    if not all(_is_type_expression(annotation, names) for annotation in annotated):
        raise _refuse(path, node.lineno, f"computes an annotation of {node.name}")


def check_law_source(source: str | bytes, path: str) -> None:
    """Refuse ``source`` unless it is a law module whose import runs none of its own code.

    Raises
    ------
    InputError
        (``module``) not Python, a top-level statement that would run code of the file, or no
        ``__asymslip_law__`` description or law function.
    """
    try:
        tree = ast.parse(source, filename=path)
    except (SyntaxError, ValueError) as error:  # ValueError: a NUL byte; bad encoding too
        raise InputError(
            "module", f"could not be imported ({type(error).__name__}: {error})", path
        ) from None
    names: set[str] = set()
    functions: set[str] = set()
    described = False
    lazy = False
    for node in tree.body:
        if isinstance(node, ast.Expr) and isinstance(node.value, ast.Constant):
            continue  # a docstring or a stray literal
        if isinstance(node, ast.Import | ast.ImportFrom):
            modules = (
                [alias.name for alias in node.names]
                if isinstance(node, ast.Import)
                else [node.module or ""]
            )
            for module in modules:
                if node.__class__ is ast.ImportFrom and node.level:
                    raise _refuse(path, node.lineno, "imports from its own package")
                if module not in ALLOWED_IMPORTS:
                    raise _refuse(path, node.lineno, f"imports {module}")
            if isinstance(node, ast.ImportFrom) and node.module == "__future__":
                lazy = lazy or any(alias.name == "annotations" for alias in node.names)
            names.update((alias.asname or alias.name).split(".")[0] for alias in node.names)
            continue
        if isinstance(node, ast.Assign | ast.AnnAssign):
            targets = node.targets if isinstance(node, ast.Assign) else [node.target]
            if not all(isinstance(target, ast.Name) for target in targets):
                raise _refuse(path, node.lineno, "assigns to something other than a name")
            value = node.value
            if value is None or not (_is_literal(value) or _is_type_expression(value, names)):
                raise _refuse(path, node.lineno, "computes a value when imported")
            for target in targets:
                assert isinstance(target, ast.Name)
                names.add(target.id)
                if target.id == "__asymslip_law__":
                    described = _describes_a_law(value)
            continue
        if isinstance(node, ast.FunctionDef):
            _check_function(node, path, names, lazy)
            functions.add(node.name)
            names.add(node.name)
            continue
        raise _refuse(path, node.lineno, _STATEMENTS.get(type(node), "runs a statement"))
    if not described:
        raise InputError(
            "module",
            "is not an asymslip law module (it has no __asymslip_law__ "
            "description with its params; write one with `asymslip derive`)",
            path,
        )
    missing = [name for name in REQUIRED_FUNCTIONS if name not in functions]
    if missing:
        raise InputError(
            "module", f"is not an asymslip law module: it lacks {', '.join(missing)}", path
        )


def _describes_a_law(value: ast.expr) -> bool:
    """``{"params": ["R", ...], ...}``: a literal dict whose params are names."""
    try:
        described = ast.literal_eval(value)
    except (ValueError, TypeError, SyntaxError, MemoryError, RecursionError):
        return False
    params = described.get("params") if isinstance(described, dict) else None
    return isinstance(params, list) and all(isinstance(name, str) for name in params)
