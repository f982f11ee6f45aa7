"""Code generation engine: derivation ledger, formula records, printers for every language.

Needs SymPy (the ``derive`` extra); the runtime packages never import it.  The names below are
loaded on first use (PEP 562), so that ``asymslip.codegen.law_module`` -- the ``derive``
command -- can be imported without SymPy and say, in one line, which extra to install.
"""

from __future__ import annotations

from ..lazy import lazy_exports

_EXPORTS = {
    "Argument": ".formula",
    "Derivation": ".derivation",
    "DerivationError": ".derivation",
    "EquationCheck": ".formula",
    "EquationStep": ".derivation",
    "Formula": ".formula",
    "Output": ".program",
    "Program": ".program",
    "Status": ".formula",
    "Step": ".program",
}

__all__ = sorted(_EXPORTS)


__getattr__, __dir__ = lazy_exports(globals(), _EXPORTS)
