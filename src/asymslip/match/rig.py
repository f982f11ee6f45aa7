"""The laboratory rig: its family of pads, its material and what it can apply.

Examples
--------
>>> from asymslip.match import Available, Rig
>>> rig = Rig("hertz", 1.0, radius=Available.listed("rig_R", [5, 10, 20]), max_P=100.0)
>>> rig.limits_text()
'R one of 5, 10, 20; P <= 100'
>>> rig.radius.clip(12.0)
10.0
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Literal

from ..errors import InputError, as_float_array
from ..laws.base import ContactLaw
from ..laws.flat_rounded import FlatRoundedLaw
from ..laws.hertz import HertzLaw

Family = Literal["hertz", "flat-rounded"]
FAMILIES: tuple[Family, ...] = ("hertz", "flat-rounded")


@dataclass(frozen=True)
class Available:
    """The values one dimension of a pad can take: a list, a range, or any positive value.

    Parameters
    ----------
    values
        The values on the shelf (a fixed list), or None for a continuous range.
    low, high
        The range (inclusive) when ``values`` is None.
    """

    values: tuple[float, ...] | None = None
    low: float = 0.0
    high: float = math.inf

    @classmethod
    def listed(cls, parameter: str, values: Sequence[float]) -> Available:
        """A fixed list of values, each finite and > 0."""
        numbers = as_float_array(parameter, list(values))
        if numbers.size == 0:
            raise InputError(parameter, "needs at least one value")
        if not (numbers > 0).all():
            raise InputError(parameter, "every value must be > 0", float(numbers.min()))
        return cls(values=tuple(sorted({float(value) for value in numbers})))

    @classmethod
    def between(cls, parameter: str, low: float, high: float, minimum: float = 0.0) -> Available:
        """A range low <= value <= high (high may be infinite)."""
        if not (math.isfinite(low) and low >= minimum):
            shown = low if math.isfinite(low) else None
            raise InputError(parameter, f"the lower end must be finite and >= {minimum:g}", shown)
        if math.isnan(high) or not high >= low:
            shown = high if math.isfinite(high) else None
            raise InputError(parameter, "the upper end must be >= the lower end", shown)
        return cls(low=float(low), high=float(high))

    @property
    def free(self) -> bool:
        """True for a range, False for a fixed list."""
        return self.values is None

    def contains(self, value: float) -> bool:
        """True when ``value`` is available (to 1e-12 relative for a listed value)."""
        if self.values is None:
            return self.low * (1 - 1e-12) <= value <= self.high * (1 + 1e-12)
        return any(abs(value - listed) <= 1e-12 * listed for listed in self.values)

    def clip(self, value: float) -> float:
        """The available value nearest ``value`` (in ratio, for a list)."""
        if self.values is None:
            return min(max(value, self.low), self.high)
        return min(self.values, key=lambda listed: abs(math.log(listed / value)))

    def describe(self, unit: str = "") -> str:
        if self.values is not None:
            return "one of " + ", ".join(f"{value:g}" for value in self.values)
        return f"between {self.low:g} and {self.high:g}{unit}"


@dataclass(frozen=True)
class Geometry:
    """One pad: its radius R (the cylinder's, or the rounded corners') and flat half-width c."""

    R: float
    c: float = 0.0


@dataclass(frozen=True)
class Rig:
    """A laboratory rig: the pad family, its material and the limits of what it applies.

    Parameters
    ----------
    family
        ``"hertz"`` (a cylindrical pad of radius R, (29)) or ``"flat-rounded"`` (a flat pad of
        half-width c with corners of radius R).
    E_star
        Plane-strain contact modulus of the rig's pad and specimen [force/length^2].
    mu
        Coefficient of friction of the rig's pair; None: the prototype's.
    radius
        The radii R available (a list or a range; default any).
    flat_half_width
        The flat half-widths c available (flat-rounded only; default any c >= 0).
    max_P, max_Q, max_sigma
        The largest normal load, shear force and bulk tension (in magnitude) it can apply.
    tension
        Whether it can apply bulk tension at all.
    """

    family: Family
    E_star: float
    mu: float | None = None
    radius: Available = field(default_factory=Available)
    flat_half_width: Available = field(default_factory=Available)
    max_P: float = math.inf
    max_Q: float = math.inf
    max_sigma: float = math.inf
    tension: bool = True

    def __post_init__(self) -> None:
        if self.family not in FAMILIES:
            raise InputError("rig", f"must be one of {', '.join(FAMILIES)}", self.family)
        E_star = float(as_float_array("rig_E_star", self.E_star))
        if not E_star > 0:
            raise InputError("rig_E_star", "must be > 0", E_star)
        object.__setattr__(self, "E_star", E_star)
        if self.mu is not None:
            mu = float(as_float_array("rig_mu", self.mu))
            if not mu > 0:
                raise InputError("rig_mu", "must be > 0", mu)
            object.__setattr__(self, "mu", mu)
        for name in ("max_P", "max_Q", "max_sigma"):
            value = float(getattr(self, name))
            if math.isnan(value) or not value > 0:
                shown = value if math.isfinite(value) else None  # never echo nan or -inf
                raise InputError(f"rig_{name}", "must be > 0 (leave it out for no limit)", shown)
            object.__setattr__(self, name, value)
        if self.radius.values is None and not self.radius.high > 0:
            raise InputError("rig_R", "the range must include a radius > 0", self.radius.high)
        if self.family == "hertz" and self.flat_half_width != Available():
            raise InputError("rig_c", "a flat half-width needs the flat-rounded rig")

    def law(self, geometry: Geometry) -> ContactLaw:
        """The contact law of one pad of this rig."""
        if self.family == "hertz":
            return HertzLaw(R=geometry.R, E_star=self.E_star)
        return FlatRoundedLaw(c=geometry.c, R=geometry.R, E_star=self.E_star)

    def admits(self, geometry: Geometry) -> bool:
        """True when the pad is on the shelf (its R and c available)."""
        flat_ok = self.family == "hertz" or self.flat_half_width.contains(geometry.c)
        return self.radius.contains(geometry.R) and flat_ok

    def limits_text(self) -> str:
        """The rig's limits in words (for the answer and refusals)."""
        parts = [f"R {self.radius.describe()}"]
        if self.family == "flat-rounded":
            parts.append(f"c {self.flat_half_width.describe()}")
        for name, value in (("P", self.max_P), ("|Q|", self.max_Q), ("|sigma|", self.max_sigma)):
            if math.isfinite(value):
                parts.append(f"{name} <= {value:g}")
        if not self.tension:
            parts.append("no bulk tension")
        return "; ".join(parts)
