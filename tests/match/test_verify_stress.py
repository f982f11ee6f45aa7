"""``match --verify`` compares the near-edge stress amplitude of prototype and rig (issue 19).

Expected values: the amplitude's uniform sxx is half the cycle's bulk-tension change (the
stick zone's strain compatibility, worked by hand from each cycle); an exact match shares the
edge's square-root loads, so its asymptotic amplitude is the prototype's to rounding; the
reference solver's fields (an independent computation) confirm the asymptotes' verdict within
their stated accuracies, and its own grid noise on these points is measured here (the
prototype on 2000 and on 2741 elements).
"""

from __future__ import annotations

import numpy as np
import pytest

from asymslip import HertzLaw, LoadCycle
from asymslip.match import Available, Rig, match, verify
from asymslip.match.near_edge_stress import asymptote_comparison, asymptotic_amplitudes
from tests.match.cases import BLADE, BLADE_CYCLE, MU

#: A Hertz prototype with bulk tension, shear-driven slip (lam/mu = 1.67 > pi eta a1/(4 mu)).
HERTZ = HertzLaw(R=10.0, E_star=1.0)
HERTZ_CYCLE = LoadCycle(10.0, 0.0, 10.2, 0.1, 0.0, 0.005)
HERTZ_MU = 0.3
ELEMENTS = 2000


def test_exact_hertz_rig_of_another_modulus_has_the_prototypes_asymptotic_amplitude():
    result = match(HERTZ, HERTZ_CYCLE, HERTZ_MU, Rig("hertz", 2.0))
    assert result.exact
    check = asymptote_comparison(result)
    assert check.points == 24 and check.near_edge
    assert check.difference < 1e-12
    assert check.within_stated_accuracy


def test_amplitude_uniform_sxx_is_half_of_each_cycles_tension_change():
    result = match(BLADE, BLADE_CYCLE, MU, Rig("hertz", 1.0))
    uniform = asymptote_comparison(result).uniform_sxx
    assert uniform is not None
    assert uniform.prototype == pytest.approx((0.002 - 0.0) / 2, rel=1e-12)
    rig_change = float(result.cycle.sigma2) - float(result.cycle.sigma1)
    assert uniform.rig == pytest.approx(rig_change / 2, rel=1e-12)
    # The edge match fixes eta, not dP: the rounded flat's rig changes its tension by less.
    assert uniform.rig < 0.9 * uniform.prototype


def test_the_match_warns_that_the_uniform_sxx_of_the_amplitude_is_not_matched():
    result = match(BLADE, BLADE_CYCLE, MU, Rig("hertz", 1.0))
    rig_half = (float(result.cycle.sigma2) - float(result.cycle.sigma1)) / 2
    text = next(w for w in result.warnings if "uniform sxx" in w)
    assert f"prototype {0.001:.4g}, rig {rig_half:.4g}" in text


def test_an_exact_hertz_rig_of_a_hertz_prototype_has_its_uniform_sxx_and_no_such_warning():
    result = match(HERTZ, HERTZ_CYCLE, HERTZ_MU, Rig("hertz", 2.0))
    assert not any("uniform sxx" in w for w in result.warnings)
    assert float(result.cycle.sigma2) - float(result.cycle.sigma1) == pytest.approx(0.005)


def test_compared_points_lie_where_both_asymptotes_hold():
    # A rounded flat's edge length scale is 1/|k_p|, shorter than its half-width: the grid
    # shrinks to 0.99 x 0.1 of the shorter of the two contacts' scales.
    amplitudes = asymptotic_amplitudes(match(BLADE, BLADE_CYCLE, MU, Rig("hertz", 1.0)))
    assert amplitudes.prototype.near_edge is not None and amplitudes.rig.near_edge is not None
    assert amplitudes.prototype.near_edge.all() and amplitudes.rig.near_edge.all()
    reach = float(amplitudes.prototype.x.max() - amplitudes.prototype.x.min())
    assert reach == pytest.approx(2.5 * amplitudes.grid.unit, rel=1e-12)


def _grid_noise(elements: int) -> float:
    """The prototype's solver amplitude on two grids at the comparison's points, relative."""
    from asymslip.match.verification import _solver_amplitude, solve_edge

    result = match(HERTZ, HERTZ_CYCLE, HERTZ_MU, Rig("hertz", 2.0))
    grid = asymptotic_amplitudes(result).grid
    fields = []
    for n in (elements, int(1.37 * elements) + 1):
        solved = solve_edge(HERTZ, HERTZ_CYCLE, HERTZ_MU, "right", n, None, None)
        fields.append(_solver_amplitude(solved, grid.global_x(solved.a2, "right"), grid.depth))
    difference = max(
        float(np.max(np.abs(fields[1].component(name) - fields[0].component(name))))
        for name in ("sxx", "syy", "sxy")
    )
    scale = max(float(np.max(np.abs(fields[0].component(name)))) for name in ("sxx", "syy", "sxy"))
    return difference / scale


@pytest.mark.slow
def test_matched_hertz_rig_reproduces_the_near_edge_amplitude_within_the_stated_accuracy():
    result = match(HERTZ, HERTZ_CYCLE, HERTZ_MU, Rig("hertz", 2.0))
    asymptote, solver = verify(result, elements=ELEMENTS).stress
    noise = _grid_noise(ELEMENTS)
    print(
        f"exact Hertz rig: solver difference {solver.difference:.3g}, grid noise {noise:.3g}, "
        f"stated accuracy of the two asymptotes {solver.allowed:.3g} (of the largest component)"
    )
    assert asymptote.difference < 1e-12
    assert solver.within_stated_accuracy and solver.explained
    # The allowance is not the solver's grid noise in disguise.
    assert noise < solver.allowed / 3
    assert solver.difference < 2 * noise


@pytest.mark.slow
def test_unreachable_rig_near_edge_mismatch_is_reported_and_the_solver_finds_it():
    # Only a pad of R = 40 for a prototype that needs R = 10: the closest cycle matches the edge
    # state to 0.3 % but needs ten times the tension change, whose uniform sxx the edge
    # signature does not hold.
    rig = Rig("hertz", 1.0, radius=Available.listed("rig_R", [40.0]))
    result = match(HERTZ, HERTZ_CYCLE, HERTZ_MU, rig)
    assert not result.exact
    assert any("R = 10" in text for text in result.unmatched)
    asymptote, solver = verify(result, elements=ELEMENTS).stress
    print(
        f"R = 40 rig: asymptote difference {asymptote.difference:.3g}, solver "
        f"{solver.difference:.3g}, stated accuracy {asymptote.allowed:.3g}"
    )
    assert not asymptote.within_stated_accuracy
    assert not solver.within_stated_accuracy
    assert solver.explained
    assert solver.difference == pytest.approx(asymptote.difference, abs=solver.allowed)
    assert asymptote.uniform_sxx is not None
    assert asymptote.uniform_sxx.rig > 5 * asymptote.uniform_sxx.prototype


@pytest.mark.slow
def test_rounded_flat_prototype_and_its_hertz_rig_agree_near_the_edge_from_both_sources():
    asymptote, solver = verify(
        match(BLADE, BLADE_CYCLE, MU, Rig("hertz", 1.0)), elements=ELEMENTS
    ).stress
    print(f"blade: asymptote {asymptote.difference:.3g}, solver {solver.difference:.3g}")
    assert asymptote.within_stated_accuracy and solver.within_stated_accuracy
    assert solver.explained
