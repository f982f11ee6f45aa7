"""The solver's linear algebra against dense NumPy: FFT products, constrained CG, active sets."""

from __future__ import annotations

import numpy as np
import pytest

from asymslip.solver import qp as qp_module
from asymslip.solver import toeplitz
from asymslip.solver.grid import Grid, InfluenceOperators
from asymslip.solver.qp import BoxQP, solve_box_qp
from asymslip.solver.toeplitz import (
    Runs,
    SolverError,
    crt_layout,
    quick_length,
    solve_constrained,
    transform_length,
)

GRID = Grid.spanning(-1.0, 1.0, 160)
OPERATORS = InfluenceOperators(GRID, 1.0)
DENSE = OPERATORS.gap.column[np.abs(np.subtract.outer(np.arange(160), np.arange(160)))]
RNG = np.random.default_rng(7)


def test_quick_length_is_the_next_power_of_2_times_at_most_9_and_125():
    # By enumeration: every 2^a 3^b 5^c with b <= 2, c <= 3 up to 2^21, the smallest >= n.
    lengths = sorted(2**a * 3**b * 5**c for a in range(22) for b in range(3) for c in range(4))
    for n in (1, 7, 997, 3601, 8001, 199_999, 1_999_999):
        assert quick_length(n) == next(length for length in lengths if length >= n)
    assert [quick_length(n) for n in (7, 997, 199_999, 1_999_999)] == [8, 1000, 204_800, 2_048_000]


def test_fft_product_equals_the_dense_toeplitz_product():
    values = RNG.standard_normal((3, 160))
    assert np.allclose(OPERATORS.gap.apply(values), values @ DENSE.T, rtol=0, atol=1e-13)


@pytest.mark.parametrize("count", [160, 1000])
def test_two_dimensional_product_equals_the_dense_toeplitz_product(count, monkeypatch):
    # The layout of long circulants (CrtLayout), forced here on short ones: 320 = 5 x 64 and
    # 2000 = 125 x 16; into a kept buffer (the conjugate gradients' way) and into a new array.
    monkeypatch.setattr(toeplitz, "CRT_MIN_LENGTH", 0)
    operators = InfluenceOperators(Grid.spanning(-1.0, 1.0, count), 1.0)
    assert operators.gap._layout is not None
    dense = operators.gap.column[np.abs(np.subtract.outer(np.arange(count), np.arange(count)))]
    for _ in range(2):  # the second product reuses the layout's buffers
        values = RNG.standard_normal(count)
        expected = dense @ values
        buffer = operators.gap.product_buffer()
        assert np.allclose(operators.gap.apply(values, out=buffer), expected, rtol=0, atol=1e-13)
        assert np.allclose(operators.gap.apply(values), expected, rtol=0, atol=1e-13)


@pytest.mark.parametrize("count", [1000, 1001])
def test_product_by_half_size_blocks_equals_the_dense_toeplitz_product(count, monkeypatch):
    # HalvedProduct, forced on short grids: N = 1000 (halves of 500, sharing their input
    # array) and 1001 (501 and 500); blocks' circulant 1000 = 125 x 8 laid out in 2-D.
    monkeypatch.setattr(toeplitz, "CRT_MIN_LENGTH", 0)
    monkeypatch.setattr(toeplitz, "HALVED_MIN_LENGTH", 0)
    operators = InfluenceOperators(Grid.spanning(-1.0, 1.0, count), 1.0)
    assert operators.gap._halves is not None and operators.gap._layout is None
    dense = operators.gap.column[np.abs(np.subtract.outer(np.arange(count), np.arange(count)))]
    for _ in range(2):  # the second product reuses the shared arrays
        values = RNG.standard_normal(count)
        expected = dense @ values
        buffer = operators.gap.product_buffer()
        assert np.allclose(operators.gap.apply(values, out=buffer), expected, rtol=0, atol=1e-13)
        assert np.allclose(operators.gap.apply(values), expected, rtol=0, atol=1e-13)


def test_products_of_a_million_elements_are_taken_by_half_size_blocks():
    # 2,048,000 points (125 x 16,384) for the whole grid; blocks of 1,024,000 (125 x 8,192).
    assert transform_length(2 * 10**6 - 1) >= toeplitz.HALVED_MIN_LENGTH
    assert transform_length(10**6 - 1) == 1_024_000
    assert transform_length(2 * 10**5 - 1) < toeplitz.HALVED_MIN_LENGTH  # N = 10^5: unchanged


def test_two_dimensional_preconditioner_equals_the_one_dimensional_one(monkeypatch):
    # Runs of 800 and 810 elements share a circulant of 900 = 225 x 4 points (one layout,
    # refilled when the run length changes).
    count = 1000
    one_dimensional = InfluenceOperators(Grid.spanning(-1.0, 1.0, count), 1.0).gap
    monkeypatch.setattr(toeplitz, "CRT_MIN_LENGTH", 0)
    two_dimensional = InfluenceOperators(Grid.spanning(-1.0, 1.0, count), 1.0).gap
    for start, stop in ((100, 900), (95, 905), (100, 900)):
        mask = np.zeros(count, dtype=bool)
        mask[start:stop] = True
        runs = Runs.of(mask)
        residual = RNG.standard_normal(stop - start)
        rows = RNG.standard_normal((2, stop - start))  # the constraint rows' way: a 2-D array
        buffer = two_dimensional.preconditioner_buffer(runs)
        got = two_dimensional.precondition(runs, residual, out=buffer)
        got_rows = two_dimensional.precondition(runs, rows)
        monkeypatch.setattr(toeplitz, "CRT_MIN_LENGTH", 10**9)
        expected = one_dimensional.precondition(runs, residual)
        expected_rows = one_dimensional.precondition(runs, rows)
        monkeypatch.setattr(toeplitz, "CRT_MIN_LENGTH", 0)
        assert np.allclose(got, expected, rtol=0, atol=1e-13 * np.max(np.abs(expected)))
        assert np.allclose(
            got_rows, expected_rows, rtol=0, atol=1e-13 * np.max(np.abs(expected_rows))
        )
    assert list(two_dimensional._layouts) == [900]


def test_the_circulant_of_a_million_elements_is_applied_as_125_by_16384():
    layout = crt_layout(quick_length(2 * 10**6 - 1), 64)
    assert layout is not None and layout.shape == (125, 16_384)
    assert crt_layout(quick_length(2 * 10**5 - 1), 64) is None  # 204,800: one dimension
    assert crt_layout(2**21, 64) is None  # no odd factor to split off


def test_long_transforms_skip_the_powers_of_2():
    # From 2^19 points a length must split into an odd factor and a power of 2: for 1,048,571
    # points 2^20 is the quick length, 1,152,000 = 1125 x 2^10 the one transformed.
    assert quick_length(1_048_571) == 2**20
    assert transform_length(1_048_571) == 1_152_000
    assert [transform_length(n) for n in (199_999, 1_000_000, 1_999_999)] == [
        204_800,
        1_024_000,
        2_048_000,
    ]


def test_block_product_equals_the_dense_leading_block():
    values = RNG.standard_normal(57)
    expected = DENSE[:57, :57] @ values
    assert np.allclose(OPERATORS.gap.block_product(values), expected, rtol=0, atol=1e-13)


@pytest.mark.parametrize("rows", [0, 1, 2])
@pytest.mark.parametrize("mask", ["one run", "two runs"])
def test_constrained_cg_solves_the_dense_kkt_system(rows, mask):
    x = GRID.centres
    free = np.abs(x) < 0.6 if mask == "one run" else (np.abs(x) < 0.7) & (np.abs(x - 0.1) > 0.2)
    runs = Runs.of(free)
    n = runs.count
    H = DENSE[np.ix_(free, free)]
    A = np.vstack([np.ones(n), x[free]])[:rows]
    c = np.array([0.3, -0.05])[:rows]
    b = RNG.standard_normal(n)
    y, multipliers, iterations = solve_constrained(OPERATORS.gap, runs, b, A, c)
    kkt = np.block([[H, A.T], [A, np.zeros((rows, rows))]])
    reference = np.linalg.solve(kkt, np.concatenate([b, c]))
    assert np.allclose(y, reference[:n], rtol=1e-8, atol=1e-8 * np.abs(reference[:n]).max())
    assert np.allclose(multipliers, reference[n:], rtol=1e-7)
    assert iterations <= 25


def test_circulant_preconditioner_keeps_the_iterations_flat_in_n():
    counts = []
    for count in (500, 4000):
        grid = Grid.spanning(-1.0, 1.0, count)
        operators = InfluenceOperators(grid, 1.0)
        free = np.abs(grid.centres) < 0.9
        _, _, iterations = solve_constrained(
            operators.gap,
            Runs.of(free),
            grid.centres[free] ** 2,
            np.ones((1, free.sum())),
            np.array([1.0]),
        )
        counts.append(iterations)
    # Unpreconditioned CG needs ~80 and ~180 iterations here (log kernel, condition ~ N).
    assert max(counts) <= 20 and counts[1] <= counts[0] + 4


def _tangential_problem(seed: int) -> BoxQP:
    """A friction step: box |q| <= mu p over a Hertz-like contact, one force condition."""
    rng = np.random.default_rng(seed)
    x = GRID.centres
    contact = np.abs(x) < 0.8
    capacity = np.where(contact, 0.3 * np.sqrt(np.maximum(0.64 - x**2, 0)), 0.0)
    stiffness = OPERATORS.slip_stiffness
    old = np.where(contact, rng.uniform(-1, 1, GRID.count) * capacity, 0.0)
    linear = stiffness.apply(old) + rng.standard_normal() * 0.05 * x
    return BoxQP(
        stiffness,
        contact,
        -capacity,
        capacity,
        linear,
        np.full((1, GRID.count), GRID.width),
        np.array([0.1]),
    )


def _check_kkt(problem: BoxQP, solution) -> None:
    """Optimality, checked densely: a strictly convex programme has no other KKT point."""
    y, d = solution.y, problem.domain
    H = -OPERATORS.relative_slip(np.eye(GRID.count)).T  # the slip stiffness, densely
    gradient = H @ y - problem.linear + solution.multipliers @ problem.rows
    scale = np.abs(problem.linear[d]).max()
    assert np.all(y[d] >= problem.lower[d] - 1e-9) and np.all(y[d] <= problem.upper[d] + 1e-9)
    assert problem.rows @ y == pytest.approx(problem.targets, rel=1e-10)
    inside = d & (y > problem.lower + 1e-9) & (y < problem.upper - 1e-9)
    assert np.all(np.abs(gradient[inside]) <= 1e-7 * scale)
    assert np.all(gradient[d & ~inside & (y <= problem.lower + 1e-9)] >= -1e-7 * scale)
    assert np.all(gradient[d & ~inside & (y >= problem.upper - 1e-9)] <= 1e-7 * scale)


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_primal_dual_active_set_meets_the_optimality_conditions(seed):
    problem = _tangential_problem(seed)
    none = np.zeros(GRID.count, dtype=bool)
    solution = solve_box_qp(problem, none, none)
    assert solution.method == "primal-dual"
    _check_kkt(problem, solution)


def test_monotone_fallback_finds_the_same_minimiser(monkeypatch):
    problem = _tangential_problem(4)
    none = np.zeros(GRID.count, dtype=bool)
    primal_dual = solve_box_qp(problem, none, none)
    monkeypatch.setattr(qp_module, "MAX_PRIMAL_DUAL", 1)  # force the fallback
    start = problem.upper * 0.1 / (GRID.width * problem.upper.sum())  # in the box, force 0.1
    fallback = solve_box_qp(problem, none, none, feasible_start=start)
    assert fallback.method == "primal (fallback)"
    _check_kkt(problem, fallback)
    assert np.allclose(fallback.y, primal_dual.y, atol=1e-8 * np.abs(primal_dual.y).max())


def test_an_unsettled_active_set_without_a_fallback_raises(monkeypatch):
    problem = _tangential_problem(5)
    none = np.zeros(GRID.count, dtype=bool)
    monkeypatch.setattr(qp_module, "MAX_PRIMAL_DUAL", 1)
    with pytest.raises(SolverError, match="did not settle"):
        solve_box_qp(problem, none, none)


def test_an_element_whose_gap_closes_halfway_through_a_step_is_in_contact_for_half_of_it():
    from asymslip.solver.normal import NormalState
    from asymslip.solver.tangential import contact_fractions

    compliance = 0.5
    before = NormalState(
        1.0,
        0.0,
        np.array([1.0, 0.0, 2.0]),
        np.array([True, False, True]),
        0.0,
        0.0,
        1,
        np.array([0.0, 0.25, 0.0]),
    )
    after = NormalState(
        1.0,
        0.0,
        np.array([1.0, 0.5, 0.0]),
        np.array([True, True, False]),
        0.0,
        0.0,
        1,
        np.array([0.0, 0.0, 3.0]),
    )
    entering, leaving = contact_fractions(before, after, compliance)
    # gap 0.25 closing to an overlap 0.5 x 0.5 = 0.25: contact from t = 1/2
    assert entering.tolist() == [0.0, 0.5, 0.0]
    # overlap 0.5 x 2 = 1 opening to a gap 3: contact until t = 1/4
    assert leaving.tolist() == [0.0, 0.0, 0.25]
