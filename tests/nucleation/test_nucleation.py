"""Crack-nucleation parameters against an independent evaluation.

The reference is built without the code under test: the stresses by mpmath quadrature of
Flamant's point-force fields over the solver's tractions (``tests.stress.references``), the
plane quantities written here by hand (the traction on a plane by rotation, plane-strain
Hooke's law), and the critical plane by a brute-force search over 36,000 angles.
"""

from __future__ import annotations

import functools

import mpmath
import numpy as np
import pytest

from asymslip import FlatRoundedLaw, HertzLaw, LoadCycle
from asymslip.errors import InputError
from asymslip.nucleation import Criterion, History, Material, critical_plane, nucleation
from asymslip.solver import solve
from asymslip.stress.solver_source import solver_load
from tests.stress.references import flamant_quadrature

MATERIAL = Material(E=2.0, nu=0.3, sigma_y=0.5, k_findley=0.3, k_fatemi_socie=0.6, L=0.2)
ANGLES = np.linspace(0.0, np.pi, 36001)[:-1]


def _by_hand(history: np.ndarray, theta: np.ndarray, criterion: Criterion) -> np.ndarray:
    """The criterion on planes theta from states x (sxx, syy, sxy), written from the
    definitions: n = (cos, sin), t = (-sin, cos), sigma_n = n.s.n, tau = t.s.n; plane strain
    eps = ((1 + nu) s - nu tr(s) I)/E with szz = nu (sxx + syy); gamma = 2 t.eps.n."""
    E, nu = MATERIAL.E, MATERIAL.nu
    c, s = np.cos(theta)[None, :], np.sin(theta)[None, :]
    sxx, syy, sxy = (history[:, i][:, None] for i in range(3))
    normal = sxx * c * c + syy * s * s + 2 * sxy * s * c
    shear = (syy - sxx) * s * c + sxy * (c * c - s * s)
    trace = (1 + nu) * (sxx + syy)
    exx, eyy, exy = (
        ((1 + nu) * sxx - nu * trace) / E,
        ((1 + nu) * syy - nu * trace) / E,
        ((1 + nu) * sxy / E),
    )
    strain = exx * c * c + eyy * s * s + 2 * exy * s * c
    gamma = 2 * ((eyy - exx) * s * c + exy * (c * c - s * s))

    def amplitude(values: np.ndarray) -> np.ndarray:
        return 0.5 * (values.max(axis=0) - values.min(axis=0))

    largest = normal.max(axis=0)
    if criterion is Criterion.FINDLEY:
        return amplitude(shear) + MATERIAL.k_findley * largest
    if criterion is Criterion.FATEMI_SOCIE:
        return amplitude(gamma) * (1 + MATERIAL.k_fatemi_socie * largest / MATERIAL.sigma_y)
    return np.maximum(largest, 0) * amplitude(strain)


PLANE_CRITERIA = (Criterion.SWT, Criterion.FATEMI_SOCIE, Criterion.FINDLEY)


def _brute_force(history: np.ndarray, criterion: Criterion) -> tuple[float, float]:
    """(largest value, its angle): 36,000 angles, then 5,000 across the best one's two
    neighbouring intervals (1.7e-8 rad apart: a kink of the criterion costs at most that
    times its slope)."""
    coarse = _by_hand(history, ANGLES, criterion)
    best = ANGLES[int(np.argmax(coarse))]
    step = ANGLES[1] - ANGLES[0]
    fine = np.linspace(best - step, best + step, 5001)
    values = _by_hand(history, fine, criterion)
    index = int(np.argmax(values))
    return float(values[index]), float(np.mod(fine[index], np.pi))


@pytest.mark.parametrize("criterion", PLANE_CRITERIA)
def test_critical_plane_search_finds_the_brute_force_maximum(criterion):
    rng = np.random.default_rng(11)
    states = rng.normal(size=(2, 3, 40))  # two states, (sxx, syy, sxy), 40 points
    history = History(states[:, 0], states[:, 1], states[:, 2])
    values, angles = critical_plane(history, criterion, MATERIAL)
    for point in range(40):
        best, _ = _brute_force(states[:, :, point], criterion)
        assert values[point] == pytest.approx(best, rel=1e-9, abs=1e-12)
        at_angle = _by_hand(states[:, :, point], np.array([angles[point]]), criterion)[0]
        assert at_angle == pytest.approx(values[point], rel=1e-12, abs=1e-15)


@pytest.fixture(scope="module")
def fig5():
    """The paper's cycle on a coarse grid (the reference quadratures run over its elements)."""
    return solve(HertzLaw(R=1.0, E_star=1.0), LoadCycle(100, 0, 105, 1), mu=0.1, elements=400)


@functools.cache
def _flamant_history(x: float, depth: float) -> np.ndarray:
    """(states, components) at (x, depth) by mpmath quadrature over each state's load; on the
    surface the limit: sxx = -p - (2/pi) PV int q/(x - t) dt (the pole subtracted), syy = -p,
    sxy = -q."""
    result = _solved()
    rows = []
    for state in result.states:
        load = solver_load(result, state)
        t, p, q = load.nodes, load.pressure, load.shear
        total = [mpmath.mpf(0)] * 3
        for j in range(t.size - 1):
            if p[j] == p[j + 1] == q[j] == q[j + 1] == 0:
                continue
            ends = (t[j], t[j + 1])

            def pressure(v, j=j, t=t, p=p):
                return p[j] + (p[j + 1] - p[j]) * (v - t[j]) / (t[j + 1] - t[j])

            def shear(v, j=j, t=t, q=q):
                return q[j] + (q[j + 1] - q[j]) * (v - t[j]) / (t[j + 1] - t[j])

            if depth > 0:
                part = flamant_quadrature(pressure, shear, ends, x, depth, digits=18)
                total = [a + b for a, b in zip(total, part, strict=True)]
                continue
            # The surface: int q/(x - t) over the element is q_e(x) log|x - t0|/|x - t1| -
            # s (t1 - t0), q_e the element's line; a log of 0 (x on a node) cancels against
            # the neighbour's, q being continuous, and is left out.
            with mpmath.workdps(18):
                slope = (q[j + 1] - q[j]) / (t[j + 1] - t[j])
                logs = sum(
                    sign * mpmath.log(abs(x - end))
                    for sign, end in ((1, ends[0]), (-1, ends[1]))
                    if x != end
                )
                total[0] += -2 / mpmath.pi * (shear(x) * logs - slope * (ends[1] - ends[0]))
        if depth == 0:  # the local terms: the tractions at the point
            total[0] += -np.interp(x, t, p)
            total[1] += -np.interp(x, t, p)
            total[2] += -np.interp(x, t, q)
        rows.append([float(total[0]) + state.sigma, float(total[1]), float(total[2])])
    return np.array(rows)


@functools.cache
def _solved():
    return solve(HertzLaw(R=1.0, E_star=1.0), LoadCycle(100, 0, 105, 1), mu=0.1, elements=400)


@pytest.mark.slow
@pytest.mark.parametrize("criterion", PLANE_CRITERIA)
def test_peak_and_critical_distances_match_flamant_quadrature_and_brute_force(criterion):
    result = _solved()
    found = nucleation(result, MATERIAL, [criterion], edges=["right"])
    for method in ("peak", "point"):
        finding = found.find("right", criterion.value, method)
        history = _flamant_history(finding.x, finding.depth)
        best, angle = _brute_force(history, criterion)
        assert finding.value == pytest.approx(best, rel=1e-6, abs=1e-15)
        if best == 0:  # SWT where no plane opens: every plane gives 0, no angle
            assert finding.angle is None
            continue
        degrees = float(np.degrees(angle))
        assert min(abs(finding.angle - degrees), 180 - abs(finding.angle - degrees)) < 0.01


def test_ruiz_parameters_are_the_products_of_the_solvers_traction_slip_and_surface_stress(fig5):
    found = nucleation(fig5, MATERIAL, [Criterion.RUIZ], edges=["right"])
    work = found.find("right", "ruiz", "frictional_work")
    ruiz = found.find("right", "ruiz", "ruiz")
    for finding in (work, ruiz):
        index = int(np.argmin(np.abs(fig5.x - finding.x)))
        traction = max(abs(state.shear[index]) for state in fig5.states)
        delta = fig5.slip_range[index] / 2
        if finding.method == "frictional_work":
            assert finding.value == pytest.approx(traction * delta, rel=1e-12)
        else:
            history = _flamant_history(float(fig5.x[index]), 0.0)
            sigma_t = max(history[:, 0].max(), 0.0)
            assert finding.value == pytest.approx(sigma_t * traction * delta, rel=1e-6)
    # The frictional work peaks inside the slip zone of the right edge, between b and a2.
    assert fig5.right.b < work.x < fig5.states[1].right.a


def test_a_criterion_without_its_constants_is_refused(fig5):
    bare = Material(E=2.0, nu=0.3)
    with pytest.raises(InputError, match="findley needs"):
        nucleation(fig5, bare, [Criterion.FINDLEY])
    with pytest.raises(InputError, match="fs .Fatemi-Socie. needs"):
        nucleation(fig5, bare, [Criterion.FATEMI_SOCIE])


@pytest.mark.parametrize(
    "keywords, parameter",
    [
        ({"E": -1.0, "nu": 0.3}, "E"),
        ({"E": 1.0, "nu": 0.5}, "nu"),
        ({"E": 1.0, "nu": 0.3, "L": 0}, "L"),
    ],
)
def test_bad_material_constants_are_refused_naming_them(keywords, parameter):
    with pytest.raises(InputError) as caught:
        Material(**keywords)
    assert caught.value.parameter == parameter


def test_blade_root_cycle_cracks_start_at_the_trailing_surface_of_the_slipping_edge():
    """A rounded flat under a growing shear and bulk tension: the right edge slips, the left
    does not; every criterion peaks on the surface within the right edge's slip zone or at its
    contact edge, and is larger there than at the left edge."""
    law = FlatRoundedLaw(c=1.0, R=10.0, E_star=1.0)
    P1, P2 = float(law.load(2.0)), float(law.load(2.1))
    mu = 0.5
    cycle = LoadCycle(P1, 0.1 * mu * P1, P2, 0.1 * mu * P1 + 1.2 * mu * (P2 - P1), 0.0, 0.05)
    result = solve(law, cycle, mu=mu, elements=600)
    found = nucleation(result, MATERIAL, list(PLANE_CRITERIA))
    for criterion in PLANE_CRITERIA:
        right = found.find("right", criterion.value, "peak")
        left = found.find("left", criterion.value, "peak")
        assert right.value > left.value
        assert right.depth == 0.0
        window = float(np.ptp(found.maps[0].x))
        assert (
            result.right.b - window < right.x <= result.states[1].right.a + 2 * result.element_size
        )
