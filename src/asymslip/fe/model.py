"""The plane-strain cylinder-on-block model: what it is, in one record.

A cylinder of radius R pressed on a block of the same material (plane strain, so E* = E /
(2 (1 - nu^2)) of (29) for two elastically similar bodies), loaded by the paper's steady cycle:
the normal load P and the shear force Q (through the cylinder's top, held rigid and prevented
from rotating, so that the contact carries no moment), and the differential bulk tension sigma
in the block.  Q and sigma mean what they mean to ``slip-zone`` and ``solve``: Q is the shear
force that the block exerts on the cylinder (q and Q act on the indenter), sigma the block's
bulk tension, so that (38) adds both at the right edge.  :mod:`.deck` writes it as a CalculiX
input deck; :mod:`.results` reads its steady stick boundaries back.

Sizes are chosen from the Hertz half-width a2 = a(P2) of (29): elements of ``a2 /
elements_per_half_width`` over the fine zone |x| <= ``fine_zone`` a2, growing geometrically
(``growth``) out to ``extent`` a2 in width and depth, in both bodies -- large beside the
contact, so that the half-plane idealisation of the paper holds.

Runtime needs NumPy only.

Examples
--------
>>> from asymslip.fe.model import CylinderOnBlock
>>> model = CylinderOnBlock(R=50.0, E_star=115384.6, mu=0.5, P1=1000.0, Q1=-100.0,
...                         P2=1100.0, Q2=150.0)
>>> round(model.a2, 4), round(model.element_size, 5)
(0.779, 0.02597)
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from ..errors import InputError
from ..laws.hertz import HertzLaw

#: The normal load is applied in steps to these fractions of P1 (frictionless, Q = sigma = 0)
#: before the cycle starts; each step's end is a trace for ``asymslip calibrate``.
PRELOAD_FRACTIONS = (0.6, 0.8, 1.0)
#: The model is a half-plane idealisation only while the contact is small beside the cylinder.
MAX_HALF_WIDTH_OVER_R = 0.05


@dataclass(frozen=True)
class CylinderOnBlock:
    """The model and its cycle.

    Parameters
    ----------
    R, E_star
        Cylinder radius and plane-strain contact modulus E* of (29) (the ``--law hertz``
        options of ``slip-zone``).
    mu
        Coefficient of friction.
    P1, Q1, P2, Q2, sigma1, sigma2
        The steady cycle as for ``slip-zone`` (P2 > P1; sigma is the block's bulk tension).
    nu
        Poisson's ratio of both bodies (E = 2 (1 - nu^2) E*).
    elements_per_half_width
        a(P2) over the element size at the contact.
    fine_zone, extent, growth
        The uniform zone's half-width and the bodies' half-width and depth, in units of
        a(P2); the element growth factor beyond the fine zone.
    cycles
        Full cycles 1 -> 2 -> 1 after the first loading to state 1 (the stick boundaries are
        read from the last one and checked against the one before).
    normal_penalty, stick_penalty
        The contact's normal and tangential (stick) penalty stiffness, in units of E/h
        (h the element size).
    """

    R: float
    E_star: float
    mu: float
    P1: float
    Q1: float
    P2: float
    Q2: float
    sigma1: float = 0.0
    sigma2: float = 0.0
    nu: float = 0.3
    elements_per_half_width: int = 30
    fine_zone: float = 1.3
    extent: float = 10.0
    growth: float = 1.2
    cycles: int = 2
    normal_penalty: float = 50.0
    stick_penalty: float = 10.0
    preload_fractions: tuple[float, ...] = field(default=PRELOAD_FRACTIONS)

    def __post_init__(self) -> None:
        for name in ("R", "E_star", "mu", "P1", "P2", "growth", "extent", "fine_zone"):
            value = getattr(self, name)
            if not (math.isfinite(value) and value > 0):
                raise InputError(name, "must be a finite number > 0", value)
        for name in ("Q1", "Q2", "sigma1", "sigma2"):
            if not math.isfinite(getattr(self, name)):
                raise InputError(name, "must be finite")
        if not self.P2 > self.P1:
            raise InputError("P2", "must exceed P1 (state 2 has the larger normal load)")
        if not 0.0 <= self.nu < 0.5:
            raise InputError("nu", "must be in [0, 0.5)", self.nu)
        if not (
            isinstance(self.elements_per_half_width, int) and self.elements_per_half_width >= 8
        ):
            raise InputError(
                "elements_per_half_width", "must be an integer >= 8", self.elements_per_half_width
            )
        if not self.growth >= 1.0:
            raise InputError("growth", "must be >= 1", self.growth)
        if not self.fine_zone * self.P1 > 0 or not self.fine_zone > 1.05:
            raise InputError("fine_zone", "must exceed 1.05 (the contact and its edges)")
        if not self.extent >= 2 * self.fine_zone:
            raise InputError("extent", "must be at least twice fine_zone", self.extent)
        if not (isinstance(self.cycles, int) and self.cycles >= 2):
            raise InputError(
                "cycles", "must be an integer >= 2 (the last checked against the one before)"
            )
        for state, (P, Q) in enumerate(((self.P1, self.Q1), (self.P2, self.Q2)), start=1):
            if not abs(Q) < self.mu * P:
                raise InputError(
                    f"Q{state}",
                    f"gross sliding at state {state}: |Q{state}| >= mu P{state} "
                    "(no partial-slip state exists)",
                )
        ratio = self.a2 * self.extent / self.R
        if not self.a2 / self.R <= MAX_HALF_WIDTH_OVER_R or not ratio < 1.0:
            raise InputError(
                "R",
                f"the contact half-width a(P2) = {self.a2:.4g} is not small beside "
                f"R = {self.R:.4g} (a/R must be <= {MAX_HALF_WIDTH_OVER_R}, the half-plane "
                "idealisation)",
            )

    @property
    def law(self) -> HertzLaw:
        """The Hertz law (29) of this cylinder."""
        return HertzLaw(R=self.R, E_star=self.E_star)

    @property
    def a1(self) -> float:
        return float(self.law.half_width(self.P1))

    @property
    def a2(self) -> float:
        return float(self.law.half_width(self.P2))

    @property
    def element_size(self) -> float:
        """h, the element size over the fine zone."""
        return self.a2 / self.elements_per_half_width

    @property
    def E(self) -> float:
        """Young's modulus of both bodies: E* = E / (2 (1 - nu^2)) for similar bodies."""
        return 2.0 * (1.0 - self.nu**2) * self.E_star
