"""The CalculiX cylinder-on-block model against Hertz, slip-zone, the reference solver and
calibrate (issue 23).  Slow: two ccx runs of a coarse mesh (a(P2)/30 at the contact, about
5,000 CPE4 elements, 9 steps), side by side, one per core.

The cycle: steel (E* = 115,385 MPa, nu = 0.3), R = 50 mm, mu = 0.5, P 1000 -> 1100 N/mm,
Q -100 -> 150 N/mm (lambda/mu = 5, slip zones of about three elements at each edge), without
and with a bulk tension change of 150 MPa in the block (then the two edges' slip zones differ
by about 2.5 elements).  References: Hertz (29) and (31) transcribed here, slip-zone's headline
b with its stated accuracy, and the reference solver's b with its bound.
"""

from __future__ import annotations

import math
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

from asymslip import HertzLaw, LoadCycle, slip_zone
from asymslip.calibration import calibrate, read_traces
from asymslip.fe import CylinderOnBlock, run_model
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


@pytest.mark.parametrize("suffix", [".frd", ".dat"])
def test_calibrate_on_the_fe_traces_recovers_a_and_L_I_within_their_reported_errors(run, suffix):
    _, outcome = run
    traces = read_traces(outcome.deck.with_suffix(suffix))
    assert [round(t.P) for t in traces.traces] == [600, 800, 1000, 1100]
    assert any("clipped to 0" in note for note in traces.notes)
    calibration = calibrate(traces, origin=0.0)
    for side in ("right", "left"):
        for fit in calibration.fits(side):
            assert abs(fit.position(0.0) - hertz_a(fit.P)) <= fit.a_error, (side, fit.P)
            assert abs(fit.L_I - hertz_L_I(fit.P)) <= fit.L_I_error, (side, fit.P)


def test_the_reported_errors_on_the_fe_traces_cover_the_true_ones_and_say_how_far(run):
    """True/reported against Hertz over both edges and the four loads.  L_I's reported error is
    within three times the true one at the median (measured 0.24-0.59, median 0.51).  a's is
    about four times it (measured 0.11-0.85, median 0.26): it is dominated by the allowance for
    the FE's own discretisation error, 0.3 element (edge_fit.FE_ALLOWANCE_A), which one mesh
    cannot measure and which reaches 0.28 element on coarser meshes, while this mesh's is
    0.06-0.24 element."""
    _, outcome = run
    calibration = calibrate(read_traces(outcome.deck.with_suffix(".frd")), origin=0.0)
    ratios_a, ratios_L = [], []
    for side in ("right", "left"):
        for fit in calibration.fits(side):
            ratios_a.append(abs(fit.position(0.0) - hertz_a(fit.P)) / fit.a_error)
            ratios_L.append(abs(fit.L_I - hertz_L_I(fit.P)) / fit.L_I_error)
    assert max(ratios_a) <= 1.0 and max(ratios_L) <= 1.0
    assert float(np.median(ratios_L)) >= 1 / 3
    assert float(np.median(ratios_a)) >= 0.2
