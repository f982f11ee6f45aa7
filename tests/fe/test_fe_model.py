"""The CalculiX cylinder-on-block model against Hertz, slip-zone, the reference solver and
calibrate (issue 23).  Slow: two ccx runs of a coarse mesh (a(P2)/30 at the contact, about
5,000 CPE4 elements, 9 steps), side by side, one per core.

The cycle: steel (E* = 115,385 MPa, nu = 0.3), R = 50 mm, mu = 0.5, P 1000 -> 1100 N/mm,
Q -100 -> 150 N/mm (lambda/mu = 5, slip zones of about three elements at each edge), without
and with a bulk tension change of 150 MPa in the block (then the two edges' slip zones differ
by about 2.5 elements).  References: Hertz (29) and (31) transcribed here (a about the FE
contact's own centre, :func:`fe_centre`, which moves with Q), slip-zone's headline b with its
stated accuracy, and the reference solver's b with its bound.
"""

from __future__ import annotations

import math
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

from asymslip import HertzLaw, LoadCycle, slip_zone
from asymslip.calibration import calibrate, read_traces
from asymslip.calibration.traces import Trace, Traces
from asymslip.fe import CylinderOnBlock, FeRun, run_model
from asymslip.solver import solve
from tests.fe.ccx import require_ccx

pytestmark = pytest.mark.slow

E_STAR = 210000.0 / (2 * (1 - 0.3**2))
R, MU = 50.0, 0.5
CYCLE = {"P1": 1000.0, "Q1": -100.0, "P2": 1100.0, "Q2": 150.0}
TENSIONS = {"no tension": 0.0, "tension": 150.0}


def hertz_a(P: float) -> float:
    """(29): a^2 = 4 P R / (pi E*)."""
    return math.sqrt(4 * P * R / (math.pi * E_STAR))


def hertz_L_I(P: float) -> float:
    """(31): L_I = (2P/pi) sqrt(2/a^3)."""
    return 2 * P / math.pi * math.sqrt(2 / hertz_a(P) ** 3)


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    """Both models, run side by side (one ccx each: the machine's two cores)."""
    require_ccx()
    models = {
        name: CylinderOnBlock(R=R, E_star=E_STAR, mu=MU, **CYCLE, sigma2=sigma2)
        for name, sigma2 in TENSIONS.items()
    }
    folders = {name: tmp_path_factory.mktemp(name.replace(" ", "_")) for name in models}
    with ThreadPoolExecutor(max_workers=len(models)) as pool:
        futures = {name: pool.submit(run_model, models[name], folders[name]) for name in models}
        return {name: (models[name], future.result()) for name, future in futures.items()}


@pytest.fixture(params=list(TENSIONS))
def run(request, runs):
    return runs[request.param]


def test_the_model_is_the_coarse_mesh_the_docstring_says(run):
    model, outcome = run
    assert model.elements_per_half_width == 30
    assert model.element_size == pytest.approx(hertz_a(1100.0) / 30)
    assert outcome.seconds is not None


def test_the_fe_contact_half_width_is_hertz_s_within_one_element(run):
    model, outcome = run
    h = model.element_size
    for side in ("right", "left"):
        edge = getattr(outcome.result, side)
        assert abs(edge.a1 - hertz_a(1000.0)) <= h, side
        assert abs(edge.a2 - hertz_a(1100.0)) <= h, side


def test_the_stick_boundary_is_steady(run):
    _, outcome = run
    for side in ("right", "left"):
        edge = getattr(outcome.result, side)
        assert edge.b == edge.b_unloading == edge.b_unloading_before, side


def test_the_fe_stick_boundary_agrees_with_slip_zone_within_one_element(run):
    model, outcome = run
    cycle = LoadCycle(**CYCLE, sigma1=0.0, sigma2=model.sigma2)
    found = slip_zone(HertzLaw(R, E_STAR), cycle, MU, edge="both")
    h = model.element_size
    for side, reference in (("right", found), ("left", found.left)):
        fe = getattr(outcome.result, side)
        assert abs(fe.b - reference.b) <= h + reference.b_accuracy, side


def test_the_fe_stick_boundary_agrees_with_the_reference_solver_within_one_element(run):
    model, outcome = run
    cycle = LoadCycle(**CYCLE, sigma1=0.0, sigma2=model.sigma2)
    solved = solve(HertzLaw(R, E_STAR), cycle, MU, elements=2000)
    h = model.element_size
    for side in ("right", "left"):
        fe, reference = getattr(outcome.result, side), solved.edge(side)
        assert abs(fe.b - reference.b) <= h + reference.b_error, side


def test_tension_moves_the_two_edges_apart_as_slip_zone_says(run):
    """With the tension the right edge's slip zone is wider than the left's by about 2.5
    elements (slip-zone: 0.065); the FE sees the same sign and size within two elements."""
    model, outcome = run
    if model.sigma2 == 0:
        assert outcome.result.right.b == outcome.result.left.b
        return
    fe = outcome.result.left.b - outcome.result.right.b
    found = slip_zone(HertzLaw(R, E_STAR), LoadCycle(**CYCLE, sigma2=model.sigma2), MU, edge="both")
    expected = found.left.b - found.b
    assert expected > 2 * model.element_size
    assert abs(fe - expected) <= 2 * model.element_size


def fe_centre(trace: Trace) -> float:
    """Where the FE contact is centred: its resultant's line of action, sum x p / sum p over
    the slave nodes (the fine zone's nodes are evenly spaced, so the nodal pressures weigh as
    the nodal forces do).

    Half-plane theory has the cylinder's contact centred under its axis at every Q.  The FE
    cylinder is a body of finite height, held against rotation at its top, through which Q
    reaches the contact: it bends, the profile at the contact tilts by some theta, and a tilted
    parabola is the same parabola moved by theta R -- Hertz's contact, of Hertz's a, centred
    there, and its resultant passes through that centre by symmetry.  So the FE model's own
    edges are at this centre +- Hertz's a (29), which no fit of the edges enters.
    """
    p = np.clip(trace.p, 0.0, None)
    return float(np.sum(trace.x * p) / np.sum(p))


def fe_edges(traces: Traces) -> dict[tuple[str, int], float]:
    """The FE model's own edge positions x at each load: fe_centre +- Hertz's a."""
    found = {}
    for trace in traces.traces:
        centre = fe_centre(trace)
        found["right", round(trace.P)] = centre + hertz_a(trace.P)
        found["left", round(trace.P)] = centre - hertz_a(trace.P)
    return found


def test_the_fe_contact_moves_with_q_alone_as_a_tilted_hertz_contact(run):
    """Its centre (fe_centre) is at x = 0 under the normal load alone (Q = 0), and moves in
    proportion to Q in the cycle: at state 1 (Q1 = -100, P = 1000) and state 2 (Q2 = 150,
    P = 1100) the two shifts stand as Q2 / Q1 = -1.5 (measured: -0.092 and +0.061 element);
    the bulk tension does not move it (the same in both runs, test below)."""
    _, outcome = run
    traces = read_traces(outcome.deck.with_suffix(".frd"))
    centre = {round(t.P): fe_centre(t) for t in traces.traces}
    h = outcome.result.element_size
    assert abs(centre[600]) < 1e-3 * h and abs(centre[800]) < 1e-3 * h
    assert 0.03 * h < centre[1000] < 0.2 * h
    assert centre[1100] / centre[1000] == pytest.approx(CYCLE["Q2"] / CYCLE["Q1"], rel=0.1)


def test_the_bulk_tension_does_not_move_the_fe_contact(runs):
    shifts = []
    for _, outcome in runs.values():
        traces = read_traces(outcome.deck.with_suffix(".frd"))
        shifts.append([fe_centre(t) for t in traces.traces])
    h = runs["tension"][0].element_size
    assert np.max(np.abs(np.subtract(*shifts))) < 0.02 * h


@pytest.mark.parametrize("suffix", [".frd", ".dat"])
def test_calibrate_on_the_fe_traces_recovers_a_and_L_I_within_their_reported_errors(run, suffix):
    _, outcome = run
    traces = read_traces(outcome.deck.with_suffix(suffix))
    assert [round(t.P) for t in traces.traces] == [600, 800, 1000, 1100]
    assert any("clipped to 0" in note for note in traces.notes)
    calibration = calibrate(traces, origin=0.0)
    edges = fe_edges(traces)
    for side in ("right", "left"):
        for fit in calibration.fits(side):
            assert abs(fit.x_edge - edges[side, round(fit.P)]) <= fit.a_error, (side, fit.P)
            assert abs(fit.L_I - hertz_L_I(fit.P)) <= fit.L_I_error, (side, fit.P)


def _true_over_reported(outcome: FeRun) -> tuple[list[float], list[float]]:
    """|true| / reported of a and L_I over both edges and the four loads: a against the FE
    model's own edges (fe_edges), L_I against Hertz's (31) (a tilt leaves L_I as it is)."""
    traces = read_traces(outcome.deck.with_suffix(".frd"))
    calibration = calibrate(traces, origin=0.0)
    edges = fe_edges(traces)
    ratios_a, ratios_L = [], []
    for side in ("right", "left"):
        for fit in calibration.fits(side):
            ratios_a.append(abs(fit.x_edge - edges[side, round(fit.P)]) / fit.a_error)
            ratios_L.append(abs(fit.L_I - hertz_L_I(fit.P)) / fit.L_I_error)
    return ratios_a, ratios_L


def test_the_reported_errors_on_the_fe_traces_cover_the_true_ones(run):
    ratios_a, ratios_L = _true_over_reported(run[1])
    assert max(ratios_a) <= 1.0 and max(ratios_L) <= 1.0


def test_the_reported_error_of_L_I_on_the_fe_traces_is_within_three_times_the_true_one(run):
    """Every one of the 8 fits of a run (measured: 0.36-0.72, median 0.58 over both runs; with
    the fixed 0.6 h/a allowance before, 0.28-0.67 and 6 of 8): the allowance follows where the
    fit put the edge (FE_ALLOWANCE_L, FE_ALLOWANCE_L_SLOPE)."""
    _, ratios_L = _true_over_reported(run[1])
    assert min(ratios_L) >= 1 / 3


def test_the_reported_error_of_a_on_the_fe_traces_is_within_three_times_the_true_one(run):
    """Every one of the 8 fits of a run (measured: 0.35-0.96, median 0.79 over both runs; with
    the fixed 0.2-element allowance before, 0.19-0.81 and 5 of 8): the allowance follows where
    the fit put the edge (FE_ALLOWANCE_A, FE_ALLOWANCE_A_AT_NODE)."""
    ratios_a, _ = _true_over_reported(run[1])
    assert min(ratios_a) >= 1 / 3
