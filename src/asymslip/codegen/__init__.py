"""Code generation engine: derivation ledger, formula records, printers for every language.

Needs SymPy (the ``derive`` extra); the runtime packages never import it.  The names below are
loaded on first use (PEP 562), so that ``asymslip.codegen.law_module`` -- the ``derive``
command -- can be imported without SymPy and say, in one line, which extra to install.
"""

from __future__ import annotations

import importlib
from typing import Any

_EXPORTS = {
    "Argument": ".formula",
    "Derivation": ".derivation",
    "DerivationError": ".derivation",
    "EquationCheck": ".formula",
    "EquationStep": ".derivation",
    "Formula": ".formula",
    "Status": ".formula",
}

__all__ = sorted(_EXPORTS)


def __getattr__(name: str) -> Any:
    if name in _EXPORTS:
        return getattr(importlib.import_module(_EXPORTS[name], __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
