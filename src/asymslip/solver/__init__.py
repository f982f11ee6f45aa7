"""The reference solver: incremental half-plane frictional contact, run to its steady state.

Two elastically similar bodies in plane strain (modulus E*), the half-plane formulation of the
paper (normal and tangential problems uncoupled), Coulomb friction mu, quasi-static and history
dependent, on a uniform grid of N elements: the paper's cycle or any closed load path of
(P, Q, sigma, M) points is applied period after period until the tractions repeat.  Every
boundary comes with an error bound of at least one element; :func:`refine` runs N, 2N, 4N
elements and extrapolates.  Runtime needs NumPy only (a typed profile needs SymPy, the
``derive`` extra; the PNG matplotlib, the ``plot`` extra).

The project's independent truth where no exact solution exists (bulk tension, asymmetric
profiles, general load paths): it never imports the asymptotes to compute; only
:mod:`asymslip.solver.compare` puts them side by side, and :mod:`asymslip.solver.error_map`
over a grid of cycles (the error map).

API
---
``solve(contact, loading, mu, *, elements=2000, steps=20, E_star=None, tolerance=1e-8,
max_cycles=20, domain=None) -> SolverResult``
    ``contact``: a built-in law with a profile (``HertzLaw``, ``FlatRoundedLaw``,
    ``PowerLaw``), or a :class:`Profile` (:class:`ExpressionProfile`,
    :class:`TableProfile`) with ``E_star``.  ``loading``: an :class:`asymslip.LoadCycle`
    or a :class:`LoadPath` (``LoadPath.from_csv(path)``, header ``P,Q,sigma,M``).

``refine(contact, loading, mu, *, elements=2000, levels=3, ...) -> RefinementResult``

``asymslip.solver.compare.with_asymptotes(result, law, cycle, mu)``
    the same result with every ``slip-zone`` estimate and its difference in elements.
``write_outputs(result, out_dir, *, png=True) -> list[Path]``
    tractions.csv, slip.csv, energy.csv and solver.png.
``result.to_dict()``
    shaped like ``slip-zone --json``: right edge on top, left edge under ``left``.

Conventions (:mod:`asymslip.solver.conventions`, every output states them in these words):
x from the contact centre (the profile's origin), b and a measured outward from it (right
edge: x; left edge: -x), as ``slip-zone``; q the shear traction exerted on the indenter by the
lower body, along +x (int q dx = Q, the shear force on the indenter; the lower body carries
-q); the slip delta the change of u_x(indenter) - u_x(lower body), along +x, since point 1 of
the steady period -- in a slip zone it has the sign opposite to q2 - q1 (friction on the
indenter opposes its slip); sigma the differential bulk tension with the sign of the paper's
(20) and (38) (Q and sigma both raise K_II at the right edge): the lower body's bulk tension
minus the indenter's (``derivations/solver_influence.py``).

Examples
--------
>>> from asymslip import HertzLaw, LoadCycle
>>> from asymslip.solver import solve
>>> result = solve(HertzLaw(R=1, E_star=1), LoadCycle(100, 0, 105, 1), mu=0.1, elements=500)
>>> round(result.right.b, 2), result.right.slip_direction, result.steady
(11.14, 1, True)
"""

from .outputs import write_outputs
from .path import LoadPath
from .profiles import ExpressionProfile, LawProfile, Profile, TableProfile
from .refine import RefinementResult, refine
from .result import EdgeResult, EdgeState, SolverResult, StateResult
from .run import DEFAULT_ELEMENTS, DEFAULT_STEPS, MIN_ELEMENTS, choose_domain, solve
from .toeplitz import SolverError

__all__ = [
    "DEFAULT_ELEMENTS",
    "DEFAULT_STEPS",
    "MIN_ELEMENTS",
    "EdgeResult",
    "EdgeState",
    "ExpressionProfile",
    "LawProfile",
    "LoadPath",
    "Profile",
    "RefinementResult",
    "SolverError",
    "SolverResult",
    "StateResult",
    "TableProfile",
    "choose_domain",
    "refine",
    "solve",
    "write_outputs",
]
