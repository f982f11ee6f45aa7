"""Contact laws a(P): the only geometry the paper's method needs."""

from .base import ContactLaw
from .hertz import HertzLaw

__all__ = ["ContactLaw", "HertzLaw"]
