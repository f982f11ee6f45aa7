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
from tests.calibration import census
from tests.calibration.helpers import LAWS, REFERENCE_LOAD, mesh, noisy

# Exact traces: their error is deterministic and every fit's reported error must cover it.  With
# scatter the reported error is a 95 % bound, which one draw in twenty exceeds by design: the
# slow census tests below check its coverage over many draws.
CASES = list(itertools.product(LAWS, ["uniform", "graded"], [20, 200], [0.0]))


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


def test_a_fine_exact_trace_gives_error_estimates():
    """Hertz's pressure on 200 nodes: the nested windows show the expansion's order, so the
    errors are estimates (within three times the true error: measured 0.45-0.54 here)."""
    law = LAWS["hertz"]
    x = mesh("uniform", float(law.half_width(REFERENCE_LOAD)), 200, np.random.default_rng(100))
    for _, fit, x_edge, L_I in _fit_both_edges(law, x, law.pressure(x, 90.0), 90.0):
        assert fit.error_kind == "estimate"
        assert 1 / 3 <= abs(fit.x_edge - x_edge) / fit.a_error <= 1
        assert 1 / 3 <= abs(fit.L_I - L_I) / fit.L_I_error <= 1


def test_a_coarse_trace_short_of_the_asymptotic_range_gives_bounds_and_says_so():
    """The power law h ~ |x|^1.5 on 20 uniform nodes: Richardson's estimate exceeds the next
    term's (the windows do not show the expansion's order), so the errors are bounds, named in
    a note -- they cover the true errors, but by far (measured true/reported 0.11-0.13 for a,
    0.19-0.21 for L_I)."""
    law = LAWS["power-1.5"]
    x = mesh("uniform", float(law.half_width(REFERENCE_LOAD)), 20, np.random.default_rng(0))
    P = REFERENCE_LOAD
    for _, fit, x_edge, L_I in _fit_both_edges(law, x, law.pressure(x, P), P):
        assert fit.error_kind == "bound"
        assert any("bounds, not estimates" in n and "asymptotic range" in n for n in fit.notes)
        assert abs(fit.x_edge - x_edge) <= fit.a_error and abs(fit.L_I - L_I) <= fit.L_I_error


@pytest.mark.slow
def test_on_exact_traces_every_reported_error_covers_the_true_one_and_estimates_are_within_3x():
    """80 fits (tests/calibration/census.py, one seed): every law, both meshes, 20 to 200 nodes.
    Exact data have a deterministic error (truncation, discretisation): per fit, the reported
    error covers it, is typically twice it (TRUNCATION_SAFETY), and where the fit reports an
    estimate (65 of the 80; the rest bounds, on 20- to 50-node meshes of the rounded flat punch
    and the power laws) within three times it: measured 0.456-0.541 (a) and 0.444-0.54 (L_I);
    every fit 0.064-0.548 and 0.167-0.587, 88.8 % within three times."""
    fits = census.exact(seeds=1)
    a, L_I = census.exact_distributions(fits)
    assert a.maximum <= 1 and L_I.maximum <= 1
    assert 0.4 <= a.median <= 0.6 and 0.4 <= L_I.median <= 0.6
    a, L_I = census.exact_distributions(fits, "estimate")
    assert a.count >= 60
    assert a.within_three == 1 and L_I.within_three == 1


@pytest.mark.slow
@pytest.mark.parametrize("noise_kind", census.NOISE_KINDS)
def test_with_1_percent_scatter_the_reported_error_is_a_95_percent_bound(noise_kind):
    """Every law, both meshes, 20, 50 and 200 nodes, 8 draws of 1 % scatter (relative or of
    the peak pressure) each, both edges: 384 fits.  The reported error states a 95 % bound: it
    covers 93-98 % of the true errors (measured: a 97.1 % and 94.8 %, L_I 96.4 % and 96.4 %),
    and per configuration the RMS true error is a median 0.39-0.47 of the median reported one
    (the 95 % bound of Gaussian scatter alone is 1.96 times its RMS: 0.51).  The share of
    configurations within a factor of three (RMS true / reported in [1/3, 1]) is 69-94 % on
    these 8 draws (82-95 % on the census's 40, docs/guide/calibration.md); the issue asks
    90 %, so this floor only guards against going back (before, on these draws: 58-92 % with
    the noise model read from residuals of p, 42-81 % before that)."""
    summary = census.noisy_summary(
        list(census.noisy_configurations(noise_kind, draws=8, nodes_list=(20, 50, 200)))
    )
    for coverage in (summary.coverage_a, summary.coverage_L):
        assert 0.93 <= coverage <= 0.98
    for ratio in (summary.ratio_a, summary.ratio_L):
        assert 1 / 3 <= ratio.median <= 1 and ratio.maximum <= 1
        assert ratio.within_three >= 0.65
