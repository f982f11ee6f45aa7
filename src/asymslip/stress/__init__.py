"""Stresses in the lower body near the contact edges, from surface tractions (issue 18).

Conventions
-----------
Stated here once; every function, command and file of :mod:`asymslip.stress` and
:mod:`asymslip.nucleation` uses them.

* x is measured from the contact centre, the right edge at +a and the left at -a; depth
  y >= 0 into the lower body, the body that carries the bulk tension sigma.
* The lower body's surface carries the pressure p >= 0 and the shear traction q exerted on it
  by the indenter, along +x.  The loads of a cycle are those of ``slip-zone`` and ``solve``
  (the paper's (20) and (38): Q and sigma both raise K_II at the right edge): Q is the shear
  force that the lower body exerts on the indenter, the solver's ``q`` the traction on the
  indenter.  The traction on the lower body is therefore q = -q_solver, with integral -Q,
  and in a slip zone q2 - q1 has the sign opposite to the solver's and the paper's q_diff.
  The check that this is the physics the solver solved: in a zone that has never slipped the
  two bodies strain alike, so the lower body's surface stress there is sxx = -p + sigma/2
  (``tests/stress/test_solver_source.py``).
* Stresses sxx, syy (normal to the surface) and sxy in the (x, y) frame, tension positive;
  plane strain, szz = nu (sxx + syy); elastically similar bodies (the half-plane formulation
  of the paper).  The bulk tension sigma adds to sxx in the lower body.
* The *amplitude* of a cycle is state 2 minus state 1: the change over its loading half,
  twice the fatigue amplitude.

API
---
:class:`SurfaceLoad` and :func:`half_plane_stress`
    the field of piecewise-linear tractions (``derivations/stress_half_plane.py``), summed
    fast or directly.
:class:`SemiEllipticLoad` and :func:`semi_elliptic_stress`
    the exact fields of Hertz and McEwen loads and their sums.
:func:`~asymslip.stress.solver_source.solver_stress`
    every state of a steady solver result (with the locked-in shear of its history).
:func:`~asymslip.stress.asymptote.edge_amplitude`
    the amplitude near one edge from the edge asymptotes, with a stated accuracy.

Examples
--------
Under the Hertz pressure p0 sqrt(1 - x^2/a^2) with the sliding shear 0.3 p, the surface
carries syy = -p (-p0 at the centre) and the trailing surface outside the edge is in tension:

>>> from asymslip.stress import SemiEllipticLoad, semi_elliptic_stress
>>> field = semi_elliptic_stress([SemiEllipticLoad(1.0, p0=1.0, q0=0.3)], [0.0, -1.0], [0.0, 0.0])
>>> [round(float(v), 4) for v in field.syy], [round(float(v), 4) for v in field.sxx]
([-1.0, 0.0], [-1.0, 0.6])
"""

from .field import CycleStress, StressField
from .half_plane import half_plane_stress
from .semi_elliptic import SemiEllipticLoad, semi_elliptic_stress
from .tractions import SurfaceLoad

__all__ = [
    "CycleStress",
    "SemiEllipticLoad",
    "StressField",
    "SurfaceLoad",
    "half_plane_stress",
    "semi_elliptic_stress",
]
