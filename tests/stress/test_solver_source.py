"""The stress field from the reference solver's tractions against exact fields.

References: McEwen's closed form (:mod:`tests.stress.references`) for Hertz under full sliding;
the Jaeger-Ciavarella amplitude (47) as a sum of semi-elliptic loads, each checked against
McEwen in ``test_half_plane``; and two statements of mechanics the solver was not told: far
below the contact only the bulk tension is left, and where the bodies have never slipped they
strain alike, so the lower body's surface carries sxx = -p + sigma/2.
"""

from __future__ import annotations

import numpy as np
import pytest

from asymslip import HertzLaw, LoadCycle
from asymslip.errors import InputError
from asymslip.solver import LoadPath, solve
from asymslip.stress import SemiEllipticLoad, SurfaceLoad, half_plane_stress, semi_elliptic_stress
from asymslip.stress.solver_source import solver_load, solver_stress
from tests.stress.references import mcewen

LAW = HertzLaw(R=1.0, E_star=1.0)
MU = 0.1
FIG5 = LoadCycle(100, 0, 105, 1)  # the paper's Fig. 5 cycle


@pytest.fixture(scope="module")
def fig5():
    return solve(LAW, FIG5, mu=MU, elements=4000)


def _grid(a: float) -> tuple[np.ndarray, np.ndarray]:
    """|x| <= 2a, 0 <= depth <= 2a, spaced a/10 (no point on an edge)."""
    return np.meshgrid(np.linspace(-2 * a, 2 * a, 40), np.linspace(0, 2 * a, 21))


def _largest(field, reference) -> float:
    return max(
        float(np.max(np.abs(getattr(field, name) - values)))
        for name, values in zip(("sxx", "syy", "sxy"), reference, strict=True)
    )


def _peak_pressure(P: float) -> float:
    return 2 * P / (np.pi * float(LAW.half_width(P)))  # (48) at x = 0


def test_solver_pressure_under_full_sliding_matches_mcewen_to_2e_3(fig5):
    """The solver's pressure at state 2 (N = 4000) with q = mu p: measured 7e-6 p0."""
    state = fig5.states[1]
    a, p0 = float(LAW.half_width(105)), _peak_pressure(105)
    load = solver_load(fig5, state)
    sliding = SurfaceLoad.from_nodes(load.nodes, load.pressure, MU * load.pressure)
    x, z = _grid(a)
    error = _largest(half_plane_stress(sliding, x, z), mcewen(x.ravel(), z.ravel(), a, p0, MU * p0))
    assert error <= 2e-5 * p0  # the issue asks 2e-3 p0


def test_near_the_edges_the_solver_field_is_within_its_grid_resolution(fig5):
    """Within three elements of an edge: 3.9e-3 p0 on the surface, 6.6e-4 p0 one element
    down (the solver's edge is 0.08 element from the exact one)."""
    state = fig5.states[1]
    a, p0, h = float(LAW.half_width(105)), _peak_pressure(105), fig5.element_size
    load = solver_load(fig5, state)
    sliding = SurfaceLoad.from_nodes(load.nodes, load.pressure, MU * load.pressure)
    x = a + np.linspace(-3, 3, 48) * h
    x = np.concatenate([x, -x])
    for depth, bound in ((0.0, 5e-3), (h, 1e-3), (5 * h, 1e-4)):
        z = np.full(x.size, depth)
        error = _largest(half_plane_stress(sliding, x, z), mcewen(x, z, a, p0, MU * p0))
        assert error <= bound * p0


def _jaeger_ciavarella_amplitude(x, z) -> object:
    """State 2 minus state 1 of the Fig. 5 cycle, exactly: the pressure change and the shear
    change of (47), -mu (p(P2) + p(P1) - 2 p(P_K)) on the lower body (the paper's q_diff is
    the traction on the indenter)."""
    P_K = (FIG5.P1 + FIG5.P2) / 2 - (FIG5.Q2 - FIG5.Q1) / (2 * MU)  # (33)
    loads = [
        SemiEllipticLoad(float(LAW.half_width(P)), p0=sign * _peak_pressure(P), q0=shear)
        for P, sign, shear in (
            (FIG5.P2, 1.0, -MU * _peak_pressure(FIG5.P2)),
            (FIG5.P1, -1.0, -MU * _peak_pressure(FIG5.P1)),
        )
    ]
    loads.append(SemiEllipticLoad(float(LAW.half_width(P_K)), q0=2 * MU * _peak_pressure(P_K)))
    return semi_elliptic_stress(loads, x, z)


def test_solver_amplitude_matches_jaeger_ciavarella(fig5):
    """Hertz partial slip without tension: the exact amplitude is a sum of Hertz and McEwen
    fields.  The solver's is measured 2.1e-4 p0 off at worst, on the surface three elements
    inside the state-1 edge (the grid's resolution there, as under sliding)."""
    a = float(LAW.half_width(105))
    x, z = _grid(a)
    solver = solver_stress(fig5, x, z)
    exact = _jaeger_ciavarella_amplitude(x, z)
    error = _largest(solver.amplitude, (exact.sxx, exact.syy, exact.sxy))
    assert error <= 3e-4 * _peak_pressure(105)


def test_amplitude_is_state_two_minus_state_one(fig5):
    field = solver_stress(fig5, [0.5, 11.0], [0.2, 0.0])
    assert field.labels == ("1", "2")
    assert np.array_equal(field.amplitude.sxx, field.states[1].sxx - field.states[0].sxx)
    assert np.array_equal(field.amplitude.sxy, field.states[1].sxy - field.states[0].sxy)


@pytest.fixture(scope="module")
def tension():
    return solve(LAW, LoadCycle(100, 0, 110, 6, 0.0, 0.06), mu=0.3, elements=2000)


def test_where_the_bodies_never_slipped_the_surface_carries_half_the_tension(tension):
    """Bonded similar bodies strain alike: the lower body (tension sigma, traction q) and the
    indenter (traction -q, no tension) have equal surface sxx, so sxx = -p + sigma/2 in the
    zone that has stuck since the first loading (measured to 2e-7 of sigma at N = 4000)."""
    b = min(tension.right.b, tension.left.b)
    x = np.linspace(-0.3 * b, 0.3 * b, 7)
    field = solver_stress(tension, x, 0.0)
    for state, values in zip(tension.states, field.states, strict=True):
        assert np.max(np.abs(values.sxx - values.syy - state.sigma / 2)) <= 1e-4 * 0.06


def test_far_below_the_contact_only_the_bulk_tension_is_left(tension):
    """sxx -> sigma as the depth grows, the rest decaying like Flamant's 2 P/(pi y)."""
    depths = np.array([1e3, 1e4, 1e5])
    field = solver_stress(tension, 0.0, depths)
    for state, values in zip(tension.states, field.states, strict=True):
        decay = 2 * (state.P + abs(state.Q)) / (np.pi * depths)
        assert np.all(np.abs(values.sxx - state.sigma) <= decay)
        assert np.all(np.abs(values.syy) <= decay) and np.all(np.abs(values.sxy) <= decay)
    assert abs(field.states[1].sxx[-1] - 0.06) < 1e-3 * 0.06


def test_a_load_path_gives_every_state_and_no_amplitude():
    path = LoadPath(np.array([[100.0, 0, 0, 0], [105, 1, 0, 0], [103, -1, 0, 0]]))
    result = solve(LAW, path, mu=MU, elements=400)
    field = solver_stress(result, [0.0, 5.0], [1.0, 0.0])
    assert len(field.states) == 3 and field.amplitude is None


def test_an_unsteady_result_is_refused(fig5):
    from dataclasses import replace

    with pytest.raises(InputError, match="steady"):
        solver_stress(replace(fig5, steady=False), [0.0], [0.0])
