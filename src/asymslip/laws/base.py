"""The contact-law interface: everything the paper's method needs from a contact.

Section 2 needs only the law a(P) and the edge multiplier L_I of (19).  A law supplies P(a)
and dP/da; the rest has sensible defaults that a law overrides where it knows better (a closed
form inverse, a cancellation-free growth a(P1 + dP) - a(P1), a pressure distribution).
"""

from __future__ import annotations

import abc

import numpy as np
from numpy.typing import ArrayLike, NDArray

from asymslip_gen.edge_multipliers import normal_edge_multiplier

from ..errors import InputError

FloatArray = NDArray[np.float64]


class ContactLaw(abc.ABC):
    """A symmetric incomplete contact: its law P(a) and what follows from it."""

    #: Short name used by the command line (``--law NAME``) and in results.
    name: str = "contact law"

    @abc.abstractmethod
    def load(self, a: ArrayLike) -> FloatArray:
        """Normal load P(a) that gives contact half-width a."""

    @abc.abstractmethod
    def load_slope(self, a: ArrayLike) -> FloatArray:
        """dP/da of the law at half-width a; > 0 for an incomplete contact."""

    def half_width(self, P: ArrayLike) -> FloatArray:
        """Contact half-width a(P), the inverse of :meth:`load`."""
        from .roots import invert_increasing

        return invert_increasing(self.load, np.asarray(P, dtype=np.float64), self.load_slope)

    def half_width_growth(self, P1: ArrayLike, dP: ArrayLike) -> FloatArray:
        """a(P1 + dP) - a(P1), as the integral of da/dP over (P1, P1 + dP).

        A sum of positive terms, so it keeps full relative precision however small dP/P1 is;
        laws with a closed form override it.
        """
        from .roots import inverse_growth

        return inverse_growth(self.half_width, self.load_slope, P1, dP)

    def half_width_slope(self, P: ArrayLike) -> FloatArray:
        """a'(P) = 1 / (dP/da)."""
        return 1.0 / self.load_slope(self.half_width(P))

    def normal_multiplier(self, P: ArrayLike) -> FloatArray:
        """Edge multiplier L_I of the contact pressure at load P, from (19)."""
        a = self.half_width(P)
        return normal_edge_multiplier(a, self.load_slope(a))

    def normal_multiplier_slope(self, P: ArrayLike) -> FloatArray:
        """dL_I/dP, for the validity measure (26); central differences unless overridden."""
        P = np.asarray(P, dtype=np.float64)
        step = 1e-5 * P
        return (self.normal_multiplier(P + step) - self.normal_multiplier(P - step)) / (2 * step)

    def pressure(self, x: ArrayLike, P: ArrayLike) -> FloatArray:
        """Contact pressure p(x, P) over the whole contact (zero outside it)."""
        raise NotImplementedError(f"the {self.name} law has no pressure distribution")

    def load_warnings(self, P1: float, P2: float) -> list[str]:
        """Messages for load states where the law is extrapolated (default: none)."""
        return []

    def check_increasing(self, *half_widths: FloatArray) -> None:
        """Refuse a law that is not increasing where it is used (dP/da <= 0)."""
        for a in half_widths:
            slope = self.load_slope(a)
            if not np.all(slope > 0):
                raise InputError(
                    "law",
                    f"the {self.name} contact law must be increasing (dP/da > 0) over the cycle",
                    float(np.min(slope)),
                )
