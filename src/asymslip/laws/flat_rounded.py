"""Flat punch with rounded corners: the law P(a), its inverse, multiplier and pressure.

The formulas are generated from ``derivations/contact_law_flat_rounded.py`` (beyond the paper);
a(P) has no closed form and is found by :func:`~asymslip.laws.roots.invert_increasing`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from asymslip_gen.flat_rounded import (
    flat_rounded_load,
    flat_rounded_load_slope,
    flat_rounded_normal_edge_multiplier,
    flat_rounded_normal_edge_multiplier_slope,
    flat_rounded_pressure,
)
from asymslip_gen.hertz import hertz_half_width

from ..errors import as_float_array, positive, require
from .base import ContactLaw, FloatArray
from .roots import inverse_growth, invert_increasing


@dataclass(frozen=True)
class FlatRoundedLaw(ContactLaw):
    """Flat face of half-width c with corners of radius R, on a half-plane of modulus E*.

    P(a) = E* (a^2 psi - c sqrt(a^2 - c^2)) / (2R), psi = arccos(c/a): any load P > 0 gives
    a > c, and c = 0 is the Hertz cylinder (29).

    Accuracy: a is a double, so for a contact barely wider than the flat the relative error of
    L_I grows like 1e-16 / (1 - c/a): measured 5e-13 at 1 - c/a = 1e-4 and 7e-12 at 1e-5.

    Parameters
    ----------
    c
        Half-width of the flat face, c >= 0 [length].
    R
        Radius of the rounded corners, R > 0 [length].
    E_star
        Plane-strain contact modulus E* > 0 [force/length^2].

    Examples
    --------
    >>> law = FlatRoundedLaw(c=1.0, R=10.0, E_star=1.0)
    >>> a = law.half_width(0.05)
    >>> round(float(law.load(a)), 12)
    0.05
    """

    c: float
    R: float
    E_star: float
    name = "flat-rounded"

    def __post_init__(self) -> None:
        flat = as_float_array("c", self.c)
        require(flat >= 0, "c", "must be >= 0 (the half-width of the flat face)", flat)
        object.__setattr__(self, "c", float(flat))
        object.__setattr__(self, "R", float(positive("R", self.R)))
        object.__setattr__(self, "E_star", float(positive("E_star", self.E_star)))

    def load(self, a: ArrayLike) -> FloatArray:
        """P(a); zero for a <= c."""
        return flat_rounded_load(a, self.c, self.R, self.E_star)

    def load_slope(self, a: ArrayLike) -> FloatArray:
        """dP/da = E* a arccos(c/a) / R."""
        return flat_rounded_load_slope(a, self.c, self.R, self.E_star)

    def half_width(self, P: ArrayLike) -> FloatArray:
        """a(P) by safeguarded Newton on P(a), to within a few units in the last place.

        The root is bracketed by max(c, a_H) <= a <= c + a_H with a_H = sqrt(4 P R/(pi E*)),
        the Hertz half-width: the rounded flat carries at most the cylinder's load at the same
        half-width, and at least the load of the cylinder of half-width a - c.
        """
        load = positive("P", P)
        hertz = hertz_half_width(load, self.R, self.E_star)
        a = invert_increasing(
            self.load, load, self.load_slope,
            lower=np.maximum(self.c, hertz), upper=self.c + hertz,
        )  # fmt: skip
        # a - c grows like P^(2/3): below P ~ 1e-23 E* c^2/R it is lost in the rounding of a.
        require(a > self.c, "P", "is too small: a(P) equals the flat half-width c in double "
                "precision (P R/(E* c^2) below about 1e-23)", load)  # fmt: skip
        return a

    def half_width_growth(self, P1: ArrayLike, dP: ArrayLike) -> FloatArray:
        """a(P1 + dP) - a(P1) as int dP/P'(a(P)): full relative precision for any dP/P1."""
        start = positive("P1", P1)
        change = as_float_array("dP", dP)
        require(change >= 0, "dP", "must be >= 0", change)
        return inverse_growth(self.half_width, self.load_slope, start, change)

    def normal_multiplier(self, P: ArrayLike) -> FloatArray:
        """L_I of (19) at load P."""
        return flat_rounded_normal_edge_multiplier(
            self.half_width(P), self.c, self.R, self.E_star
        )

    def normal_multiplier_slope(self, P: ArrayLike) -> FloatArray:
        """dL_I/dP at load P, in closed form."""
        return flat_rounded_normal_edge_multiplier_slope(
            self.half_width(P), self.c, self.R, self.E_star
        )

    def pressure(self, x: ArrayLike, P: ArrayLike) -> FloatArray:
        """Contact pressure p(x) at load P; zero for |x| >= a(P)."""
        position = as_float_array("x", x)
        return flat_rounded_pressure(position, self.half_width(P), self.c, self.R, self.E_star)
