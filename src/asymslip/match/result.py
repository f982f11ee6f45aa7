"""What a match answers: the rig and its cycle, the quantities side by side, how far to trust it.

Examples
--------
>>> from asymslip.match import Pair
>>> round(Pair(prototype=0.2, rig=0.21).relative_difference, 12)
0.05
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

from ..cycle import LoadCycle
from ..laws.base import ContactLaw
from ..slip_zones import SlipZoneResult
from ..solver.result import Edge
from .rig import Geometry, Rig
from .signature import QUANTITIES, EdgeSignature
from .solutions import Order


@dataclass(frozen=True)
class Pair:
    """One quantity of the prototype's edge and of the rig's."""

    prototype: float
    rig: float

    @property
    def relative_difference(self) -> float:
        return (self.rig - self.prototype) / abs(self.prototype) if self.prototype else math.inf


@dataclass(frozen=True)
class Mismatch:
    """One matched quantity's mismatch (a component of the edge-state measure) and what it
    alone does to the consistent slip-zone width (17) and the peak shear change (LT2): each
    relative change is the prototype's edge with only this quantity set to the rig's."""

    quantity: str
    mismatch: float
    width_change: float
    peak_change: float


@dataclass(frozen=True)
class MatchResult:
    """The rig cycle whose edge reproduces the prototype's, and the evidence.

    ``order`` is ``"second"`` when the rig also shares the prototype's contact half-widths (the
    headline slip-zone widths then agree to second order), ``"leading"`` when the five edge
    quantities match exactly (to 1e-9), ``"approximate"`` otherwise (the closest rig cycle by
    the edge-state mismatch ``measure``, :mod:`asymslip.match.signature`).  ``accuracy`` is the
    match's stated accuracy on the slip-zone width: the sum of the two contacts' accuracies (the
    headline ones, second order, for a second-order match; 2 (da/a1) |a1 - b| each otherwise).
    ``margin`` is the fraction of the friction limit left at the rig's worse state,
    min over its two states of 1 - |Q|/(mu P).
    """

    rig: Rig
    geometry: Geometry
    law: ContactLaw
    mu: float
    cycle: LoadCycle
    edge: Edge
    prototype: SlipZoneResult
    rig_result: SlipZoneResult
    matched: dict[str, Pair]
    width_accuracy: Pair
    peak_shear_change: Pair
    exact: bool
    order: Order
    measure: float
    mismatches: tuple[Mismatch, ...]
    accuracy: float
    margin: float
    unmatched: tuple[str, ...]
    warnings: tuple[str, ...]
    prototype_law: Any = field(repr=False)
    prototype_cycle: LoadCycle = field(repr=False)
    prototype_state: EdgeSignature = field(repr=False)
    rig_state: EdgeSignature = field(repr=False)
    verification: Any = None

    def rig_dict(self) -> dict[str, object]:
        data: dict[str, object] = {"law": self.rig.family, "R": self.geometry.R}
        if self.rig.family == "flat-rounded":
            data = {"law": self.rig.family, "c": self.geometry.c, "R": self.geometry.R}
        data.update(E_star=self.rig.E_star, mu=self.mu)
        return data

    def to_dict(self) -> dict[str, object]:
        """The JSON object of ``asymslip match --json``."""
        cycle = self.cycle
        matched: dict[str, dict[str, float]] = {
            key: {"prototype": pair.prototype, "rig": pair.rig}
            for key, pair in self.matched.items()
        }
        matched["slip_zone_width"].update(
            prototype_accuracy=self.width_accuracy.prototype, rig_accuracy=self.width_accuracy.rig
        )
        data: dict[str, object] = {
            "rig": self.rig_dict(),
            "cycle": {
                key: float(getattr(cycle, key))
                for key in ("P1", "Q1", "sigma1", "P2", "Q2", "sigma2")
            },
            "edge": self.edge,
            "matched": matched,
            "exact": self.exact,
            "order": self.order,
            "accuracy": self.accuracy,
            "measure": self.measure,
            "mismatch": {
                item.quantity: {
                    "mismatch": item.mismatch,
                    "slip_zone_width_change": item.width_change,
                    "peak_shear_change_change": item.peak_change,
                }
                for item in self.mismatches
            },
            "peak_shear_change": {
                "prototype": self.peak_shear_change.prototype,
                "rig": self.peak_shear_change.rig,
            },
            "gross_sliding_margin": self.margin,
            "validity": {
                "prototype": dict(self.prototype.validity),
                "rig": dict(self.rig_result.validity),
            },
            "unmatched": list(self.unmatched),
            "warnings": list(self.warnings),
        }
        if self.verification is not None:
            data["verification"] = self.verification.to_dict()
        return data


__all__ = ["QUANTITIES", "MatchResult", "Mismatch", "Pair"]
