"""One cycle on Python floats gives exactly what the arrays give for the same cycle.

The slip-zone core runs one edge pipeline (:mod:`asymslip.core.edge_state`) over two sets of
operations: Python floats and the ``math`` kernels for a single cycle, NumPy arrays for many
(:mod:`asymslip.core.operations`).  The reference here is the array run of the same cycle as an
array of one element: the other operations through the same lines, so every double and every
warning flag must agree exactly -- and a cycle refused on floats must be refused with the
array path's message.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest

import asymslip.core.evaluation as core_evaluation
from asymslip import FlatRoundedLaw, HertzLaw, LoadCycle, PowerLaw, TableLaw, slip_zone
from asymslip.core.estimates import DISAGREEMENT_ROUNDING
from asymslip.core.flags import MEASURE_KEYS, NUMBER_KEYS
from asymslip.core.operations import RuleBroken
from asymslip.errors import InputError
from asymslip_gen import programs as array_programs
from asymslip_gen import scalar_programs

_FLAT = FlatRoundedLaw(c=1.0, R=10.0, E_star=1.0)
_LOADS = np.geomspace(2.0, 400.0, 20)
LAWS = {
    "hertz": HertzLaw(R=1.0, E_star=1.0),
    "power": PowerLaw(A=0.1, n=1.5, E_star=1.0),
    "flat-rounded": _FLAT,
    "table": TableLaw(_LOADS, _FLAT.half_width(_LOADS)),
}


def _cycles(seed: int, count: int) -> list[tuple[float, ...]]:
    """(P1, Q1, P2, Q2, sigma1, sigma2, mu): load steps from 1e-4 to 2 times P1, shear changes
    that slip forward, backward or not at all, with and without bulk tension, and some whose
    slip zones leave the contact or have no steady state (refused)."""
    rng = np.random.default_rng(seed)
    cycles = []
    for _ in range(count):
        P1 = float(rng.uniform(5.0, 150.0))
        P2 = P1 * (1 + float(10 ** rng.uniform(-4, np.log10(2.0))))
        mu = float(rng.uniform(0.05, 0.8))
        lam = float(rng.uniform(-1.6, 1.6)) * mu
        Q1 = float(rng.uniform(-0.9, 0.9)) * mu * P1
        sigma1 = float(rng.uniform(-1, 1))
        eta = 0.0 if rng.random() < 0.5 else float(rng.uniform(-0.3, 0.3))
        cycles.append((P1, Q1, P2, Q1 + lam * (P2 - P1), sigma1, sigma1 + eta * (P2 - P1), mu))
    # Refused for certain: gross sliding at state 2, and a load step three times P1 with the
    # shear near its limit.
    return [
        *cycles,
        (100.0, 0.0, 105.0, 20.0, 0.0, 0.0, 0.1),
        (10.0, 0.0, 40.0, 11.9, 0.0, 0.0, 0.3),
    ]


def _array_result(law, loads: tuple[float, ...], mu: float):
    cycle = LoadCycle(*(np.array([value]) for value in loads))
    return slip_zone(law, cycle, np.array([mu]), edge="both", invalid="mark")


def _same_edge(one, many) -> None:
    for key in NUMBER_KEYS:
        single, element = getattr(one, key), float(getattr(many, key)[0])
        if single is None:
            assert np.isnan(element), key
        else:
            assert single == element, (key, single, element)
    for key in MEASURE_KEYS:
        assert one.validity[key] == float(many.validity[key][0]), key
    assert one.warning_flags == int(many.warning_flags[0])


@pytest.mark.parametrize("name", LAWS)
def test_every_answered_cycle_has_the_array_paths_doubles_and_flags(name):
    law = LAWS[name]
    answered = refused = 0
    for *loads, mu in _cycles(seed=len(name), count=60):
        cycle = LoadCycle(*loads)
        array = _array_result(law, tuple(loads), mu)
        if array.errors is not None:
            with pytest.raises(InputError) as refusal:
                slip_zone(law, cycle, mu, edge="both")
            assert str(refusal.value) == array.errors[0]
            refused += 1
            continue
        assert core_evaluation.evaluate(law, cycle, mu).shape == ()  # answered on floats
        one = slip_zone(law, cycle, mu, edge="both")
        _same_edge(one, array)
        _same_edge(one.left, array.left)
        answered += 1
    assert answered >= 30 and refused >= 1, (answered, refused)


def test_without_tension_the_mirrored_left_edge_reuses_the_right_edges_estimates(monkeypatch):
    # The left edge of the Fig. 5 cycle is the right edge mirrored: one call of the kernels
    # answers both, and the left edge reports the same b with the opposite shear multipliers
    # and slip direction.  With bulk tension the mirror breaks and both edges are computed, in
    # one call of the program of both edges.
    calls = []
    both = []
    original = core_evaluation.edge_estimates
    original_both = scalar_programs.both_edges

    def counted(*arguments):
        calls.append(arguments)
        return original(*arguments)

    def counted_both(*arguments):
        both.append(arguments)
        return original_both(*arguments)

    monkeypatch.setattr(core_evaluation, "edge_estimates", counted)
    monkeypatch.setattr(scalar_programs, "both_edges", counted_both)
    result = slip_zone(LAWS["hertz"], LoadCycle(100, 0, 105, 1), 0.1, edge="both")
    assert (len(calls), len(both)) == (1, 0)
    assert result.left.b == result.b and result.left.slip_zone_width == result.slip_zone_width
    assert (result.left.L_II2, result.left.slip_direction, result.slip_direction) == (
        -result.L_II2,
        -1,
        1,
    )
    calls.clear()
    tension = slip_zone(LAWS["hertz"], LoadCycle(100, 0, 105, 1, 0, 0.5), 0.1, edge="both")
    assert (len(calls), len(both)) == (0, 1)
    assert tension.left.b != tension.b  # no mirror image: the tension breaks the symmetry


@pytest.mark.parametrize("sigma2", [0.5, -0.5, 3.0])
@pytest.mark.parametrize("dQ", [1.0, -1.0, 0.0, 6.0])
def test_the_program_of_both_edges_gives_each_edges_own_bits(dQ, sigma2):
    # both_edges is edge_shear and edge_estimates for each edge, the law's quantities once: the
    # same doubles, bit for bit, as the two single-edge programs in each edge's own frame
    # (lam -> -lam for the left edge), on floats and on arrays.
    state = LAWS["hertz"].cycle_state(100.0, 5.0)
    mu, lam, eta = 0.1, dQ / 5.0, sigma2 / 5.0
    law_args = (state.a1, state.a2, state.da, state.L_I1, state.L_I2, state.P1, 5.0)
    slopes = (state.load_slope1, state.load_slope2, state.L_I_slope1, state.L_I_slope2)
    for programs in (scalar_programs, array_programs):
        both = programs.both_edges(mu, lam, eta, *law_args, *slopes, DISAGREEMENT_ROUNDING)
        shears = [
            programs.edge_shear(mu, own, eta, state.a1, state.a2, state.L_I1, state.L_I2)
            for own in (lam, -lam)
        ]
        singles = [
            programs.edge_estimates(
                mu, own, eta, *law_args, *slopes, shear[2], other[2], DISAGREEMENT_ROUNDING
            )
            for own, shear, other in ((lam, shears[0], shears[1]), (-lam, shears[1], shears[0]))
        ]
        expected = (*shears[0], *shears[1], *singles[0], *singles[1])
        assert len(both) == len(expected) == 34
        assert [float(value).hex() for value in both] == [float(value).hex() for value in expected]


def test_a_rule_broken_on_floats_ends_the_cycle_and_is_named_as_on_arrays():
    # Tension so large that (17) has no steady partial-slip state at an edge (denominator):
    # the float run stops there, and its message is the array run's.
    law, cycle = LAWS["hertz"], LoadCycle(100, 0, 105, 1, 0, 30)
    evaluation = core_evaluation.evaluate(law, cycle, 0.1)
    assert isinstance(evaluation.checked, RuleBroken)
    assert evaluation.checked.key == "denominator_tension"  # the tension change is to blame
    array = _array_result(law, (100, 0, 105, 1, 0, 30), 0.1)
    with pytest.raises(InputError) as refusal:
        slip_zone(law, cycle, 0.1)
    assert str(refusal.value) == array.errors[0]
    assert np.isnan(slip_zone(law, cycle, 0.1, invalid="mark").b)


def test_gross_sliding_is_named_for_one_cycle():
    law, cycle = LAWS["hertz"], LoadCycle(100, 0, 105, 20)  # |Q2| = 20 > mu P2 = 10.5
    with pytest.raises(InputError, match="gross sliding"):
        slip_zone(law, cycle, 0.1)


@pytest.mark.parametrize("name", ["flat-rounded", "table"])
def test_a_law_on_numpy_gives_no_warning_on_the_fast_path(name):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        result = slip_zone(LAWS[name], LoadCycle(50, 0, 52, 0.5, 0, 0.1), 0.3, edge="both")
    assert 0 < result.b < result.a1


def test_many_cycles_take_the_arrays_and_one_cycle_the_floats():
    law = LAWS["hertz"]
    evaluate = core_evaluation.evaluate
    assert evaluate(law, LoadCycle([100, 101], 0, 105, 1), 0.1).shape == (2,)
    assert evaluate(law, LoadCycle(100, 0, 105, 1), np.array([0.1, 0.2])).shape == (2,)
    one = evaluate(law, LoadCycle(100, 0, 105, 1), np.float64(0.1))
    assert type(one.edges["right"].b) is float  # Python floats, not NumPy scalars
