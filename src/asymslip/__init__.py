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

from .lazy import lazy_exports

# Exports load on first use (PEP 562): `python -m asymslip.codegen` must run without importing
# the API, which imports the generated package that the code generator is about to rewrite.
_EXPORTS = {
    "ContactLaw": ".laws",
    "Edge": ".edge",
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


__getattr__, __dir__ = lazy_exports(globals(), _EXPORTS)
