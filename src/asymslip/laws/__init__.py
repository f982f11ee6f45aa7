"""Contact laws a(P): the only geometry the paper's method needs."""

from ..lazy import lazy_exports

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


__getattr__, __dir__ = lazy_exports(globals(), _EXPORTS)
