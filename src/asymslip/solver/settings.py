"""One solve's settings, as one record: what the incremental run and its results both need."""

from __future__ import annotations

from dataclasses import dataclass

from .grid import Grid
from .path import LoadPath
from .profiles import Profile


@dataclass(frozen=True)
class SolverSettings:
    """The problem and the numerical settings of one :func:`asymslip.solver.solve` on one grid.

    Attributes
    ----------
    profile
        The initial gap h(x).
    E_star
        Plane-strain contact modulus [force/length^2].
    path
        One period of the load path.
    mu
        Coulomb friction coefficient.
    grid
        The uniform grid of the computational domain.
    steps
        Load steps per segment of the path.
    tolerance
        Steady-state tolerance on the shear tractions, relative to mu max p.
    max_cycles
        Most periods to run.
    is_cycle
        Whether the path is the paper's two-state cycle (``q_diff`` and the asymptotes exist).
    """

    profile: Profile
    E_star: float
    path: LoadPath
    mu: float
    grid: Grid
    steps: int
    tolerance: float
    max_cycles: int
    is_cycle: bool


@dataclass(frozen=True)
class Convergence:
    """How the run went: periods, whether and how closely it reached a steady state, the work."""

    cycles: int  # periods begun
    steady: bool
    change: float  # largest change of q over the last period compared / (mu max p)
    load_steps: int
    active_set_solves: int
    cg_iterations: int
    fallbacks: int
    normal_solves: int  # distinct loads whose normal problem was solved
