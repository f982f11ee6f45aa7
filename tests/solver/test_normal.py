"""The normal problem: every built-in law's pressure and a(P), tilt under a moment, refusals.

References are independent of the solver: each law's closed-form pressure and half-width
(``law.pressure``, ``law.half_width``, derived from the profile in their own derivations), and
for the tilted punch the continuum conditions of an incomplete contact on (l, r) (Barber,
Elasticity, Ch. 12), evaluated here by Gauss-Chebyshev quadrature:
    int_l^r (h'(t) - theta) / sqrt((t - l)(r - t)) dt = 0              (bounded at both ends)
    P = (E*/2) int_l^r t (h'(t) - theta) / sqrt((t - l)(r - t)) dt.
"""

from __future__ import annotations

import numpy as np
import pytest

from asymslip import FlatRoundedLaw, HertzLaw, InputError, PowerLaw
from asymslip.solver import ExpressionProfile, LoadPath, solve
from asymslip.solver.grid import Grid, InfluenceOperators
from asymslip.solver.normal import NormalSolver
from asymslip.solver.result import ORIENTATION

LAWS = {
    "hertz": HertzLaw(R=1.0, E_star=1.0),
    "flat-rounded": FlatRoundedLaw(c=1.0, R=10.0, E_star=1.0),
    "power n=1.5": PowerLaw(A=0.3, n=1.5, E_star=1.0),
    "power n=3": PowerLaw(A=0.05, n=3.0, E_star=1.0),
    "wedge n=1": PowerLaw(A=0.1, n=1.0, E_star=1.0),
}
#: Largest |p - p_law| / max p over |x| < 0.95 a (measured at N = 1000: 8e-6, 2e-4, 2e-3 at
#: the cusp of |x|^1.5, 1e-5; the wedge is checked away from its logarithmic apex).
PRESSURE_TOLERANCE = {
    "hertz": 5e-5,
    "flat-rounded": 5e-4,
    "power n=1.5": 5e-3,
    "power n=3": 5e-5,
    "wedge n=1": 2e-3,
}


def normal_state(law, P: float, count: int = 1000, M: float = 0.0):
    a = float(law.half_width(P))
    grid = Grid.spanning(-1.03 * a, 1.03 * a, count)
    solver = NormalSolver(grid, InfluenceOperators(grid, law.E_star), law.profile(grid.centres))
    return grid, solver.solve(P, M)


@pytest.mark.parametrize("name", LAWS)
def test_pressure_of_every_builtin_law_matches_its_closed_form(name):
    if name.startswith("power n=1.5"):
        pytest.importorskip("scipy")  # the law's 2F1 pressure
    law = LAWS[name]
    P = float(law.load(2.0))
    grid, state = normal_state(law, P)
    x = grid.centres
    exact = law.pressure(x, P)
    inner = np.abs(x) < 0.95 * 2.0
    if name == "wedge n=1":
        inner &= np.abs(x) > 0.05 * 2.0  # the element average of a log singularity differs
    peak = np.max(exact[np.isfinite(exact)])
    assert np.max(np.abs(state.pressure - exact)[inner]) <= PRESSURE_TOLERANCE[name] * peak
    assert np.sum(state.pressure) * grid.width == pytest.approx(P, rel=1e-12)


@pytest.mark.parametrize("name", LAWS)
@pytest.mark.parametrize("a", [1.3, 2.0])
def test_contact_half_width_of_every_builtin_law_matches_its_law(name, a):
    law = LAWS[name]
    P = float(law.load(a))
    result = solve(law, LoadPath([[P, 0.0], [1.02 * P, 0.0]]), 0.3, elements=600, steps=2)
    state = result.states[0]
    for side in ("right", "left"):
        edge = state.edge(side)
        assert abs(edge.a - a) <= edge.a_error
        assert abs(edge.a - a) <= 0.2 * result.element_size  # measured: 0.02-0.1 elements


def _continuum_conditions(law, left: float, right: float, theta: float) -> np.ndarray:
    """(int (h' - theta)/sqrt(...) dt, (E*/2) int t (h' - theta)/sqrt(...) dt) on (l, r).

    Gauss-Chebyshev quadrature: t = mid + half cos(phi) turns both into int_0^pi ... dphi,
    evaluated by the midpoint rule in phi (20000 nodes; the integrand has a kink at t = 0).
    """
    phi = (np.arange(20000) + 0.5) * np.pi / 20000
    t = (left + right) / 2 + (right - left) / 2 * np.cos(phi)
    slope = law.n * law.A * np.sign(t) * np.abs(t) ** (law.n - 1) - theta
    weight = np.pi / phi.size
    return np.array([np.sum(slope) * weight, law.E_star / 2 * np.sum(t * slope) * weight])


def test_tilted_punch_satisfies_the_continuum_contact_conditions():
    law = LAWS["power n=3"]
    P = float(law.load(2.0))
    M = 0.15 * P * 2.0  # the pressure's centre 0.3 off the axis, on a contact about 4 wide
    result = solve(
        law, LoadPath([[P, 0.0, 0.0, M], [1.02 * P, 0.0, 0.0, M]]), 0.3, elements=1000, steps=2
    )
    state = result.states[0]
    assert np.sum(result.x * state.pressure) * result.element_size == pytest.approx(M, rel=1e-10)
    assert state.tilt > 0 and state.right.a > 2.0 > state.left.a  # the contact moves to +x
    # Given the solver's tilt and P, find the continuum edges (Newton on the two conditions)
    # and compare them with the solver's, which must be within an element.
    edges = np.array([-state.left.a, state.right.a])
    target = np.array([0.0, P])
    for _ in range(30):
        residual = _continuum_conditions(law, *edges, state.tilt) - target
        step = 1e-7 * (edges[1] - edges[0])
        jacobian = np.column_stack(
            [
                (_continuum_conditions(law, *(edges + step * e), state.tilt) - target - residual)
                / step
                for e in np.eye(2)
            ]
        )
        change = np.linalg.solve(jacobian, -residual)
        edges += change
        if np.max(np.abs(change)) < 1e-12:
            break
    assert abs(edges[0] - -state.left.a) <= result.element_size
    assert abs(edges[1] - state.right.a) <= result.element_size


def test_mirrored_profile_and_moment_give_the_mirrored_contact():
    profile = ExpressionProfile("x**2/2 + x**3/20")
    mirrored = ExpressionProfile("x**2/2 - x**3/20")
    loads = [[3.0, 0.0, 0.0, 0.4], [3.2, 0.0, 0.0, 0.4]]
    one = solve(profile, LoadPath(loads), 0.3, E_star=1.0, elements=400, steps=2, domain=(-3, 3))
    two = solve(
        mirrored,
        LoadPath(np.array(loads) * [1, 1, 1, -1]),
        0.3,
        E_star=1.0,
        elements=400,
        steps=2,
        domain=(-3, 3),
    )
    assert np.allclose(one.states[0].pressure, two.states[0].pressure[::-1], atol=1e-12)
    assert one.states[0].tilt == pytest.approx(-two.states[0].tilt, rel=1e-9)
    assert one.states[0].right.a == pytest.approx(two.states[0].left.a, rel=1e-9)


@pytest.mark.parametrize(
    "law", [HertzLaw(1.0, 1.0), PowerLaw(0.5, 2.0, 1.0), FlatRoundedLaw(0.0, 1.0, 1.0)]
)
def test_a_cylinder_refuses_a_moment(law):
    with pytest.raises(InputError, match="M: a moment cannot be resisted.*cylinder"):
        solve(law, LoadPath([[100.0, 0.0, 0.0, 5.0], [105.0, 1.0, 0.0, 5.0]]), 0.3, elements=200)


def test_a_profile_whose_contact_splits_is_refused():
    two_bumps = ExpressionProfile("(x**2 - 1)**2")  # lowest at x = -1 and x = +1
    with pytest.raises(InputError, match="profile: gives a contact in 2 pieces"):
        solve(two_bumps, LoadPath([[0.01, 0.0], [0.011, 0.0]]), 0.3, E_star=1.0, elements=200)


def test_edges_are_reported_as_distances_along_the_outward_direction():
    assert ORIENTATION == {"right": 1, "left": -1}
    grid, state = normal_state(LAWS["hertz"], 100.0, count=400)
    assert state.pressure[: state.first].max(initial=0) == 0
    assert grid.centres[state.first] < 0 < grid.centres[state.last]
