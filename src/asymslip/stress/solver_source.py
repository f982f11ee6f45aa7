"""The stress field from the reference solver: every state of its steady cycle, in full.

The solver (:mod:`asymslip.solver`) gives the pressure and the shear traction of every element
at each point of the steady load path, with the shear locked in by the history, for any
profile, moment and load path it takes.  Here they become the surface load of the lower body
(conventions: :mod:`asymslip.stress`; the solver's shear acts on the indenter, so the lower
body's is its negative) and the field is summed by :func:`~asymslip.stress.half_plane_stress`,
with the state's bulk tension added to sxx (the lower body carries it, the indenter none).

The element values are collocation values at the element centres; the load runs linearly
between centres and down to zero half an element beyond the last element in contact.
Measured on a Hertz contact under full sliding (the solver's pressure at N = 4000, q = mu p),
against McEwen's exact field (``tests/stress/test_solver_source.py``): 7e-6 p0 at the points
of |x| <= 2a, 0 <= y <= 2a spaced a/10; within three elements of an edge 3.9e-3 p0 on the
surface, 6.6e-4 p0 one element deep and 7e-5 p0 five deep -- the resolution of the solver's
grid there (its edge lies 0.08 element from the exact one).  Laying the last stretch on the
square root (4), or ending the load at the solver's fitted edge, was measured to be no better
(4.7e-3 and 6.0e-3 p0 on the surface).

Examples
--------
Far below the contact only the bulk tension of each state is left:

>>> from asymslip import HertzLaw, LoadCycle
>>> from asymslip.solver import solve
>>> result = solve(HertzLaw(1, 1), LoadCycle(100, 0, 105, 1, 0.1, 0.5), mu=0.1, elements=200)
>>> field = solver_stress(result, [0.0], [1e5])
>>> [round(float(state.sxx[0]), 3) for state in field.states]
[0.1, 0.5]
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from ..errors import InputError
from ..solver import SolverResult, StateResult
from .field import CycleStress, StressField
from .half_plane import Method, half_plane_stress, points
from .tractions import SurfaceLoad, from_element_values

SOURCE = "solver"


def solver_load(result: SolverResult, state: StateResult) -> SurfaceLoad:
    """The pressure and the shear traction on the lower body at one state of ``result``."""
    centres, width = result.x, result.element_size
    pressure = np.where(state.contact, state.pressure, 0.0)
    shear = np.where(state.contact, -state.shear, 0.0)  # the solver's q acts on the indenter
    return from_element_values(centres, width, pressure, shear)


def solver_stress(
    result: SolverResult,
    x: ArrayLike,
    depth: ArrayLike,
    *,
    method: Method = "fast",
) -> CycleStress:
    """The field at the points (x, depth) at every state of the solver's steady path.

    Parameters
    ----------
    result
        A solved steady cycle (:func:`asymslip.solver.solve`).
    x, depth
        The points (broadcast together; depth >= 0), x in the solver's (the profile's) frame.
    method
        How the half-plane sums are done (see :func:`~asymslip.stress.half_plane_stress`).

    Returns
    -------
    CycleStress
        One field per state of the path (the paper's cycle: state 1 and state 2), and for the
        paper's cycle the amplitude, state 2 minus state 1.
    """
    xs, ys = points(x, depth)
    if not result.steady:
        raise InputError(
            "solver",
            "the solver did not reach its steady state; the stresses of a transient period "
            "are not those of the steady cycle (raise max_cycles)",
        )
    states = tuple(
        half_plane_stress(solver_load(result, state), xs, ys, method=method).with_bulk(state.sigma)
        for state in result.states
    )
    amplitude: StressField | None = states[1] - states[0] if result.is_cycle else None
    return CycleStress(
        source=SOURCE,
        edge=None,
        x=xs,
        depth=ys,
        states=states,
        labels=tuple(state.label for state in result.states),
        amplitude=amplitude,
        warnings=tuple(result.warnings),
    )
