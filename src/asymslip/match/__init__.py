"""Carry a laboratory test over to a prototype: the rig cycle whose contact edge is the
prototype's (``asymslip match``).

Under the paper's assumptions the state near one edge is fixed, to leading order, by mu,
L_I1, L_I2, L_II1, L_II2 and the advance a2 - a1 of the edge (LT1 of
``derivations/lab_transfer.py``).  :func:`match` finds the rig's pad and cycle that share them
-- exactly where the rig allows (for a Hertz pad with bulk tension the one answer of LT3, LT4;
for a rounded-flat rig the pad at the prototype's own half-widths, a second-order match, LT5),
else the closest by the edge-state mismatch of :mod:`.signature` -- and reports every matched
quantity of both contacts side by side with the validity measures (24)-(27), the slip-zone
widths and the match's stated accuracy.  :func:`verify` solves both contacts with the reference
solver and compares the near-edge shear change and slip in the edge's own coordinate.

Examples
--------
A blade-root-like rounded flat with bulk tension, reproduced by a cylindrical pad:

>>> from asymslip import FlatRoundedLaw, LoadCycle
>>> from asymslip.match import Rig, match
>>> blade = FlatRoundedLaw(c=1.0, R=10.0, E_star=1.0)
>>> result = match(blade, LoadCycle(0.5, 0.0, 0.52, 0.04, 0.0, 0.002), 0.3, Rig("hertz", 1.0))
>>> result.exact, result.order, round(result.geometry.R, 3)
(True, 'leading', 10.147)
>>> sorted(result.to_dict()["matched"])
['L_I1', 'L_I2', 'L_II1', 'L_II2', 'a2_minus_a1', 'slip_zone_width']
"""

from .matching import EXACT, match, rig_cycle
from .result import MatchResult, Mismatch, Pair
from .rig import FAMILIES, Available, Geometry, Rig
from .signature import QUANTITIES, EdgeSignature
from .verification import SolverProblem, Verification, verify

__all__ = [
    "EXACT",
    "FAMILIES",
    "QUANTITIES",
    "Available",
    "EdgeSignature",
    "Geometry",
    "MatchResult",
    "Mismatch",
    "Pair",
    "Rig",
    "SolverProblem",
    "Verification",
    "match",
    "rig_cycle",
    "verify",
]
