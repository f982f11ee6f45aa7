"""The Hertzian (cylinder) contact law (29), from the generated kernels."""

from __future__ import annotations

from dataclasses import dataclass

from numpy.typing import ArrayLike

from asymslip_gen.hertz import (
    hertz_half_width,
    hertz_half_width_growth,
    hertz_load,
    hertz_load_slope,
    hertz_normal_edge_multiplier,
    hertz_normal_edge_multiplier_slope,
)
from asymslip_gen.tractions import hertz_pressure

from ..errors import positive
from .base import ContactLaw, FloatArray


@dataclass(frozen=True)
class HertzLaw(ContactLaw):
    """Cylinder of radius R on a half-plane, plane-strain modulus E*: a^2 = 4 P R / (pi E*).

    Examples
    --------
    >>> law = HertzLaw(R=1.0, E_star=1.0)
    >>> round(float(law.half_width(100.0)), 6)
    11.283792
    """

    R: float
    E_star: float
    name = "hertz"

    def __post_init__(self) -> None:
        object.__setattr__(self, "R", float(positive("R", self.R)))
        object.__setattr__(self, "E_star", float(positive("E_star", self.E_star)))

    def load(self, a: ArrayLike) -> FloatArray:
        return hertz_load(a, self.R, self.E_star)

    def load_slope(self, a: ArrayLike) -> FloatArray:
        return hertz_load_slope(a, self.R, self.E_star)

    def half_width(self, P: ArrayLike) -> FloatArray:
        return hertz_half_width(P, self.R, self.E_star)

    def half_width_growth(self, P1: ArrayLike, dP: ArrayLike) -> FloatArray:
        return hertz_half_width_growth(P1, dP, self.R, self.E_star)

    def normal_multiplier(self, P: ArrayLike) -> FloatArray:
        return hertz_normal_edge_multiplier(P, self.R, self.E_star)

    def pressure(self, x: ArrayLike, P: ArrayLike) -> FloatArray:
        """Hertz pressure (48), zero outside the contact."""
        return hertz_pressure(x, P, self.R, self.E_star)

    def normal_multiplier_slope(self, P: ArrayLike) -> FloatArray:
        return hertz_normal_edge_multiplier_slope(P, self.R, self.E_star)
