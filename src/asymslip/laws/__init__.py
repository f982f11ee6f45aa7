"""Contact laws a(P): the only geometry the paper's method needs."""

from .base import ContactLaw
from .flat_rounded import FlatRoundedLaw
from .hertz import HertzLaw
from .module_law import ModuleLaw
from .power import PowerLaw
from .table import TableLaw

__all__ = ["ContactLaw", "FlatRoundedLaw", "HertzLaw", "ModuleLaw", "PowerLaw", "TableLaw"]
