"""One solve's settings, as one record: what the incremental run and its results both need."""

from __future__ import annotations

from dataclasses import dataclass

from .grid import Grid
from .path import LoadPath
from .profiles import Profile

#: The largest change of a shear traction, relative to mu max p, by which two solves of one
#: load step at the conjugate gradients' tolerance may differ on ``RESOLUTION_ELEMENTS``
#: elements (measured on the Fig. 5 cycle at N = 10^4: up to 7.0e-10 from a solve to 1e-14,
#: so up to twice that between two solves).
RESOLUTION = 2e-9
#: The grid on which ``RESOLUTION`` holds; finer grids resolve less (:func:`steady_resolution`).
RESOLUTION_ELEMENTS = 10_000


def steady_resolution(count: int) -> float:
    """The smallest change of the shear tractions, relative to mu max p, that solves on a grid
    of ``count`` elements resolve: below it the steady check compares rounding, not physics.

    The conjugate gradients stop at a relative residual (``toeplitz.CG_TOLERANCE``) in the
    2-norm over the free elements; the error that is left sits at the ends of the free run
    (the stick zone's, where the friction reserve has its square root), so one element may
    carry a residual sqrt(N) times its share, and the influence matrix answers a residual on
    one element with a traction 1/h ~ N times larger than a smooth one: the error grows like
    N^3/2.  Measured on the paper's Fig. 5 cycle, against solves to 1e-14 with the same
    stick/slip sets: 4.3e-10 to 7.0e-10 mu max p at N = 10^4 and 1.4e-8 to 1.2e-7 at N = 10^6,
    at the free run's end element; and from one period to the next, with identical sets at
    every step, the tractions at 10^6 changed by up to 4.8e-7, at 10^4 by 3e-10 to 7e-10.  So
    ``RESOLUTION`` at ``RESOLUTION_ELEMENTS``, growing like N^3/2 (6.3e-8 at 10^5, 2e-6 at
    10^6; above the default tolerance 1e-8 from about 29,000 elements).
    """
    coarser: float = (count / RESOLUTION_ELEMENTS) ** 1.5  # float ** float: typed Any
    return RESOLUTION * max(1.0, coarser)


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
        Steady-state tolerance on the shear tractions, relative to mu max p, as given.
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

    @property
    def steady_tolerance(self) -> float:
        """The tolerance the steady check applies: ``tolerance``, or the solves' resolution
        on this grid (:func:`steady_resolution`) where that is larger (from about 29,000
        elements at the default 1e-8)."""
        return max(self.tolerance, steady_resolution(self.grid.count))


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
