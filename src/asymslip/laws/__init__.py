"""Contact laws a(P): the only geometry the paper's method needs."""

import importlib
from typing import Any

# Each law loads on first use (PEP 562): `from asymslip import HertzLaw` should not pay for the
# table law's file reader or the user-module loader (measured in the import benchmark).
_EXPORTS = {
    "ContactLaw": ".base",
    "FlatRoundedLaw": ".flat_rounded",
    "HertzLaw": ".hertz",
    "ModuleLaw": ".module_law",
    "PowerLaw": ".power",
    "TableLaw": ".table",
}

__all__ = sorted(_EXPORTS)


def __getattr__(name: str) -> Any:
    if name not in _EXPORTS:
        raise AttributeError(f"module 'asymslip.laws' has no attribute {name!r}")
    value = getattr(importlib.import_module(_EXPORTS[name], __name__), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted([*globals(), *_EXPORTS])
