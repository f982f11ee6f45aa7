"""Contact laws a(P): the only geometry the paper's method needs."""

from .base import ContactLaw
from .hertz import HertzLaw
from .module_law import ModuleLaw
from .table import TableLaw

__all__ = ["ContactLaw", "HertzLaw", "ModuleLaw", "TableLaw"]
