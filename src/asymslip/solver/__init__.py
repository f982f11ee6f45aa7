"""The reference solver: incremental half-plane frictional contact, run to its steady state.

Two elastically similar bodies in plane strain (modulus E*), the half-plane formulation of the
paper (normal and tangential problems uncoupled), Coulomb friction mu, quasi-static and history
dependent, on a uniform grid of N elements: the paper's cycle or any closed load path of
(P, Q, sigma, M) points is applied period after period until the stick zones and tractions
repeat.  Every boundary comes with an error bound of at least one element; :func:`refine` runs
N, 2N, 4N elements and extrapolates.  Runtime needs NumPy only.

The project's independent truth where no exact solution exists (bulk tension, asymmetric
profiles, general load paths): it never imports the asymptotes to compute; only
:mod:`asymslip.solver.compare` puts them side by side.

Examples
--------
>>> from asymslip import HertzLaw, LoadCycle
>>> from asymslip.solver import solve
>>> result = solve(HertzLaw(R=1, E_star=1), LoadCycle(100, 0, 105, 1), mu=0.1, elements=500)
>>> round(result.right.b, 2), result.right.slip_direction, result.steady
(11.14, 1, True)
"""

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
]
