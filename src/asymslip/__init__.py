"""asymslip: derived, verified and generated formulas for partial-slip contact edges.

The validating Python API over the generated NumPy kernels (``asymslip_gen``).  Runtime needs
NumPy only.

Examples
--------
>>> from asymslip import HertzLaw, LoadCycle, slip_zone
>>> result = slip_zone(HertzLaw(R=1, E_star=1), LoadCycle(P1=100, Q1=0, P2=105, Q2=1), mu=0.1)
>>> round(result.b, 4)
11.1419
"""

import importlib
from typing import Any

# Exports load on first use (PEP 562): `python -m asymslip.codegen` must run without importing
# the API, which imports the generated package that the code generator is about to rewrite.
_EXPORTS = {
    "ContactLaw": ".laws",
    "FlatRoundedLaw": ".laws",
    "HertzLaw": ".laws",
    "InputError": ".errors",
    "LoadCycle": ".cycle",
    "ModuleLaw": ".laws",
    "PowerLaw": ".laws",
    "SlipZoneResult": ".slip_zones",
    "TableLaw": ".laws",
    "slip_zone": ".slip_zones",
}

__all__ = sorted(_EXPORTS)
__version__ = "0.1.0"


def __getattr__(name: str) -> Any:
    if name not in _EXPORTS:
        raise AttributeError(f"module 'asymslip' has no attribute {name!r}")
    value = getattr(importlib.import_module(_EXPORTS[name], __name__), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted([*globals(), *_EXPORTS])
