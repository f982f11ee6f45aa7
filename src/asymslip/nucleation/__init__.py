"""Crack-nucleation parameters near the contact edges (issue 18).

Conventions: those of :mod:`asymslip.stress` (x from the contact centre, depth into the lower
body that carries the bulk tension, tension positive, plane strain).  A critical plane contains
the z axis; its angle is that of its normal from +x towards the depth, in degrees in [0, 180).

API
---
:class:`Material`, :class:`Criterion`
    the lower body's constants (E, nu; the yield stress and each criterion's k where needed;
    the critical distance L) and the criteria (ruiz, swt, fs, findley).
:func:`nucleation`
    each criterion's peak near each edge of a steady solver result, with its location and
    critical plane, and with L the point and line methods of the theory of critical
    distances below the surface hot spot.
:func:`critical_plane`
    the largest value of a criterion over the planes through each point of a stress history.

Examples
--------
Findley's parameter of a uniaxial stress from 0 to 100 (k = 0.3): 25 sin 2t + 15 (1 + cos
2t) is largest, sqrt(850) + 15, where tan 2t = 25/15:

>>> import numpy as np
>>> history = History(np.array([[0.0], [100.0]]), np.zeros((2, 1)), np.zeros((2, 1)))
>>> material = Material(E=2e5, nu=0.3, k_findley=0.3)
>>> value, angle = critical_plane(history, Criterion.FINDLEY, material)
>>> round(float(value[0]), 3), round(float(np.degrees(angle[0])), 2)
(44.155, 29.52)
"""

from .assessment import Finding, NucleationResult, nucleation
from .criteria import Criterion, History, Material, criteria_from_names, critical_plane

__all__ = [
    "Criterion",
    "Finding",
    "History",
    "Material",
    "NucleationResult",
    "critical_plane",
    "criteria_from_names",
    "nucleation",
]
