"""Names a package loads on first use (PEP 562), written once for every package that needs it.

``asymslip`` must import without the generated kernels (``python -m asymslip.codegen`` rewrites
them), ``asymslip.laws`` without the table law's file reader, ``asymslip.codegen`` without
SymPy: each lists its exports and the module that defines each, and this module gives it the
module-level ``__getattr__`` and ``__dir__`` that load one on first use.

Examples
--------
>>> import types
>>> package = types.ModuleType("demo")
>>> package.__getattr__, package.__dir__ = lazy_exports(package.__dict__, {"sqrt": "math"})
>>> package.sqrt(4.0), "sqrt" in dir(package)
(2.0, True)
"""

from __future__ import annotations

import importlib
from collections.abc import Callable, Mapping, MutableMapping
from typing import Any


def lazy_exports(
    namespace: MutableMapping[str, Any], exports: Mapping[str, str]
) -> tuple[Callable[[str], Any], Callable[[], list[str]]]:
    """``__getattr__`` and ``__dir__`` for a package whose ``exports`` map each name to the
    module defining it (relative to the package, as ``".laws"``, or absolute).

    A name is imported when first asked for and kept in ``namespace`` (the package's
    ``globals()``), so later look-ups cost nothing.
    """
    package = str(namespace["__name__"])

    def __getattr__(name: str) -> Any:
        if name not in exports:
            raise AttributeError(f"module {package!r} has no attribute {name!r}")
        value = getattr(importlib.import_module(exports[name], package), name)
        namespace[name] = value
        return value

    def __dir__() -> list[str]:
        return sorted({*namespace, *exports})

    return __getattr__, __dir__
