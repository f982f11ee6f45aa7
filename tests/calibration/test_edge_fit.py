"""The near-edge fit: a and L_I of (4) from one load's nodal pressures, within its own error.

References: each built-in law's closed-form pressure ``law.pressure(x, P)`` (the traces), its
``half_width(P)`` and its ``normal_multiplier(P)`` ((19) from the law; for these symmetric
contacts (19) is the pressure's own edge multiplier, tests/test_contact_laws.py).  Meshes,
noise and the laws are described in tests/calibration/helpers.py.
"""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from asymslip.calibration.edge_fit import EdgeFitError, fit_edge, nodal_points
from tests.calibration.helpers import LAWS, REFERENCE_LOAD, mesh, noisy

CASES = list(itertools.product(LAWS, ["uniform", "graded"], [20, 200], [0.0, 0.01]))


def _fit_both_edges(law, x, p, P):
    a, L_I = float(law.half_width(P)), float(law.normal_multiplier(P))
    for side, x_edge in (("right", a), ("left", -a)):
        fit = fit_edge(x, p, side, P)
        yield side, fit, x_edge, L_I


@pytest.mark.parametrize(("name", "kind", "nodes", "noise"), CASES)
def test_edge_and_multiplier_lie_within_the_reported_errors(name, kind, nodes, noise):
    law = LAWS[name]
    rng = np.random.default_rng(CASES.index((name, kind, nodes, noise)))
    P = REFERENCE_LOAD * 1.07
    x = mesh(kind, float(law.half_width(REFERENCE_LOAD)), nodes, rng)
    p = noisy(law.pressure(x, P), noise, rng)
    for side, fit, x_edge, L_I in _fit_both_edges(law, x, p, P):
        assert abs(fit.x_edge - x_edge) <= fit.a_error, side
        assert abs(fit.L_I - L_I) <= fit.L_I_error, side


@pytest.mark.parametrize("name", list(LAWS))
def test_fine_exact_traces_give_the_edge_to_1e_5_and_the_multiplier_to_1e_3(name):
    """Not only honest but accurate: 200 nodes, no noise."""
    law = LAWS[name]
    rng = np.random.default_rng(7)
    a = float(law.half_width(REFERENCE_LOAD))
    x = mesh("uniform", a, 200, rng)
    for side, fit, x_edge, L_I in _fit_both_edges(
        law, x, law.pressure(x, REFERENCE_LOAD), REFERENCE_LOAD
    ):
        assert abs(fit.x_edge - x_edge) < 1e-5 * a, side
        assert abs(fit.L_I / L_I - 1) < 1e-3, side
        assert fit.a_error < 1e-3 * a and fit.L_I_error < 1e-2 * L_I, side


@pytest.mark.parametrize("name", list(LAWS))
def test_a_wrong_last_node_in_contact_is_left_out_with_a_note(name):
    law = LAWS[name]
    rng = np.random.default_rng(3)
    x = mesh("uniform", float(law.half_width(REFERENCE_LOAD)), 50, rng)
    p = law.pressure(x, REFERENCE_LOAD)
    last = int(np.flatnonzero(p > 0)[-1])
    p[last] *= 1.5  # the element across the edge overstates its node's pressure
    (side, fit, x_edge, L_I), _ = _fit_both_edges(law, x, p, REFERENCE_LOAD)
    assert not fit.last_node_used
    assert any("last node in contact" in note for note in fit.notes)
    assert abs(fit.x_edge - x_edge) <= fit.a_error
    assert abs(fit.L_I - L_I) <= fit.L_I_error


def test_points_interpolated_linearly_between_nodes_are_recognised_and_left_out():
    """A path report with three points per element gives the fit of the nodes alone."""
    law = LAWS["hertz"]
    rng = np.random.default_rng(5)
    x = mesh("graded", float(law.half_width(REFERENCE_LOAD)), 30, rng)
    p = law.pressure(x, REFERENCE_LOAD)
    fine = np.concatenate(
        [np.linspace(x[i], x[i + 1], 4)[:-1] for i in range(x.size - 1)] + [x[-1:]]
    )
    fine_p = np.interp(fine, x, p)
    assert np.array_equal(fine[nodal_points(fine, fine_p)], x[nodal_points(x, p)])
    on_nodes = fit_edge(x, p, "right", REFERENCE_LOAD)
    on_path = fit_edge(fine, fine_p, "right", REFERENCE_LOAD)
    assert (on_path.x_edge, on_path.L_I, on_path.a_error) == (
        on_nodes.x_edge,
        on_nodes.L_I,
        on_nodes.a_error,
    )
    assert "interpolating between nodes" in on_path.notes[0]


def test_too_few_nodes_near_the_edge_is_refused_naming_the_last_node_in_contact():
    law = LAWS["hertz"]
    a = float(law.half_width(REFERENCE_LOAD))
    x = np.linspace(-1.5 * a, 1.5 * a, 16)  # 10 nodes across the contact
    p = law.pressure(x, REFERENCE_LOAD)
    with pytest.raises(EdgeFitError, match="too few nodes near the edge") as caught:
        fit_edge(x, p, "right", REFERENCE_LOAD)
    assert caught.value.node == int(np.flatnonzero(p > 0)[-1])
    with pytest.raises(EdgeFitError) as caught:
        fit_edge(x, p, "left", REFERENCE_LOAD)
    assert caught.value.node == int(np.flatnonzero(p > 0)[0])


def test_a_contact_running_off_the_end_of_the_trace_is_refused():
    law = LAWS["hertz"]
    a = float(law.half_width(REFERENCE_LOAD))
    x = np.linspace(-1.5 * a, 0.9 * a, 100)
    with pytest.raises(EdgeFitError, match="the edge is not in the data"):
        fit_edge(x, law.pressure(x, REFERENCE_LOAD), "right", REFERENCE_LOAD)
    fit_edge(x, law.pressure(x, REFERENCE_LOAD), "left", REFERENCE_LOAD)  # the other is fine


@pytest.mark.slow
@pytest.mark.parametrize("noise_kind", ["relative", "absolute"])
def test_no_error_is_understated_over_many_meshes_loads_and_noise(noise_kind):
    """320 fits per noise model: every law, both meshes, 20 to 200 nodes, exact or 1 % noise."""
    rng = np.random.default_rng(11 if noise_kind == "relative" else 12)
    worst = 0.0
    for law in LAWS.values():
        for kind in ("uniform", "graded"):
            for nodes in (20, 35, 50, 100, 200):
                for _ in range(2):
                    P = REFERENCE_LOAD * rng.uniform(0.8, 1.25)
                    x = mesh(kind, float(law.half_width(REFERENCE_LOAD)), nodes, rng)
                    p = noisy(law.pressure(x, P), 0.01 * rng.integers(0, 2), rng, noise_kind)
                    for _side, fit, x_edge, L_I in _fit_both_edges(law, x, p, P):
                        worst = max(
                            worst,
                            abs(fit.x_edge - x_edge) / fit.a_error,
                            abs(fit.L_I - L_I) / fit.L_I_error,
                        )
    assert worst <= 1.0
