"""The state of one contact edge to leading order, and how far two of them are apart.

By LT1 of ``derivations/lab_transfer.py``, in the edge's own coordinate (the distance from the
edge) the slip-zone width (17), the shear-traction change (49) and the slip depend on a contact
only through mu, L_I1, L_I2, L_II1, L_II2 and da = a2 - a1.  A rig whose edge shares the five
numbers other than mu (with mu L_I shared where the rig's mu differs) reproduces the edge.

The measure of the distance between two edge states (the "edge-state mismatch"), stated once
here and used for every approximate match: the root sum of squares of five dimensionless
mismatches,

* ln(L_I1 rig / L_I1 target), ln(L_I2 rig / L_I2 target) -- the pressure multipliers, relative;
* (L_II1 rig - L_II1 target) / (mu L_I1 target), likewise at state 2 -- the shear multipliers
  in units of the friction limit mu L_I, the scale against which (8) and (11) judge slip;
* ln(da rig / da target) -- the advance of the edge, relative.

It is zero exactly when the edges coincide to leading order; 0.01 means about a 1 % change of
one of them.

Examples
--------
>>> from asymslip.match import EdgeSignature
>>> edge = EdgeSignature(mu=0.3, L_I1=2.0, L_I2=2.1, L_II1=0.7, L_II2=0.9, da=0.05)
>>> edge.direction, round(edge.width, 6), round(edge.peak_shear_change, 6)
(1.0, 0.013107, 0.226954)
>>> round(EdgeSignature(0.3, 2.0, 2.1, 0.7, 0.9, 0.051).distance(edge), 6)  # ln(51/50)
0.019803
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from asymslip_gen.corrective_slip import slip_zone_width_from_multipliers
from asymslip_gen.lab_transfer import peak_shear_change

from ..core.estimates import slip_direction

#: The matched quantities, in the order of :meth:`EdgeSignature.mismatch` (JSON names).
QUANTITIES = ("L_I1", "L_I2", "L_II1", "L_II2", "a2_minus_a1")


@dataclass(frozen=True)
class EdgeSignature:
    """mu, the four edge multipliers of (4), (5) and the advance of the edge da = a2 - a1."""

    mu: float
    L_I1: float
    L_I2: float
    L_II1: float
    L_II2: float
    da: float

    @property
    def direction(self) -> float:
        """+1 forward slip on loading, -1 backward, 0 none (derivations/edge_symmetry.py)."""
        return float(slip_direction(self.mu, self.L_I2, self.L_II2))

    @property
    def width(self) -> float:
        """a1 - b of (17): the consistent slip-zone width (0 where the edge does not slip)."""
        direction = self.direction
        if direction == 0:
            return 0.0
        return float(
            slip_zone_width_from_multipliers(
                self.mu,
                self.da,
                self.L_I1,
                self.L_I2,
                direction * self.L_II1,
                direction * self.L_II2,
            )
        )

    @property
    def peak_shear_change(self) -> float:
        """|q2 - q1| at the stick boundary, its largest value over the slip zone (LT2)."""
        return float(peak_shear_change(self.mu, self.L_I1, self.L_I2, self.width, self.da))

    def value(self, quantity: str) -> float:
        """One of :data:`QUANTITIES`."""
        return self.da if quantity == "a2_minus_a1" else float(getattr(self, quantity))

    def with_value(self, quantity: str, value: float) -> EdgeSignature:
        """This state with one quantity replaced."""
        return replace(self, **{"da" if quantity == "a2_minus_a1" else quantity: value})

    def for_friction(self, mu: float) -> EdgeSignature:
        """The state a pair of friction coefficient ``mu`` must have to slip as this one does:
        the same L_II and mu L_I (the slip conditions (8), (11) compare L_II with mu L_I)."""
        scale = self.mu / mu
        return replace(self, mu=mu, L_I1=self.L_I1 * scale, L_I2=self.L_I2 * scale)

    def mismatch(self, target: EdgeSignature) -> tuple[float, ...]:
        """The five dimensionless mismatches of the module's measure, in :data:`QUANTITIES`
        order (zero where this state is the target)."""
        mu = target.mu
        return (
            math.log(self.L_I1 / target.L_I1),
            math.log(self.L_I2 / target.L_I2),
            (self.L_II1 - target.L_II1) / (mu * target.L_I1),
            (self.L_II2 - target.L_II2) / (mu * target.L_I2),
            math.log(self.da / target.da),
        )

    def distance(self, target: EdgeSignature) -> float:
        """The edge-state mismatch: the root sum of squares of :meth:`mismatch`."""
        return math.sqrt(sum(value * value for value in self.mismatch(target)))
