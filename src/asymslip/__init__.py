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

from .cycle import LoadCycle
from .edge_solution import SlipZoneResult, slip_zone
from .errors import InputError
from .laws import ContactLaw, FlatRoundedLaw, HertzLaw, ModuleLaw, PowerLaw, TableLaw

__all__ = [
    "ContactLaw",
    "FlatRoundedLaw",
    "HertzLaw",
    "InputError",
    "LoadCycle",
    "ModuleLaw",
    "PowerLaw",
    "SlipZoneResult",
    "TableLaw",
    "slip_zone",
]
__version__ = "0.1.0"
