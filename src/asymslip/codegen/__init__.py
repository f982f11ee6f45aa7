"""Code generation engine: derivation ledger, configured NumPy printer, module emitter.

Needs SymPy (the ``derive`` extra); the runtime packages never import it.
"""

from .derivation import Derivation, DerivationError, EquationStep
from .formula import Argument, EquationCheck, Formula, Status

__all__ = [
    "Argument",
    "Derivation",
    "DerivationError",
    "EquationCheck",
    "EquationStep",
    "Formula",
    "Status",
]
