"""The FE-table contact law: a monotone log-log fit whose reported error bounds its real error.

References are transcribed by hand: Hertz (29), a^2 = 4 P R/(pi E*), and the law of the
profile h(x) = x^2/(2R) + k x^4, for which
    P(a) = (E*/2) int_{-a}^{a} x h'(x)/sqrt(a^2 - x^2) dx = pi E* a^2/(4R) + 3 pi E* k a^4/4,
a quadratic in a^2 (solved in closed form below): a law that is not a power law, so the fit
has a real error to estimate.  L_I is (19): sqrt(2/a) P'(a)/pi.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from asymslip import InputError, LoadCycle, slip_zone
from asymslip.laws.base import ContactLaw
from asymslip.laws.table import TableLaw
from tests.transcription.section2 import eq22

QUARTIC = 1e-3  # k of the profile x^2/2 + k x^4 (R = E* = 1): 6% of the load at a = 8


def hertz_a(P):
    return np.sqrt(4 * P / np.pi)


def quartic_load(a):
    return np.pi * a**2 / 4 + 3 * np.pi * QUARTIC * a**4 / 4


def quartic_load_slope(a):
    return np.pi * a / 2 + 3 * np.pi * QUARTIC * a**3


def quartic_a(P):
    """Root of (3 pi k/4) A^2 + (pi/4) A - P = 0 for A = a^2, in the cancellation-free form."""
    p, q = np.pi / 4, 3 * np.pi * QUARTIC / 4
    return np.sqrt(2 * P / (p + np.sqrt(p**2 + 4 * q * P)))


def multiplier_19(a, dP_da):
    return np.sqrt(2 / a) * dP_da / np.pi


class QuarticProfileLaw(ContactLaw):
    """The exact law of the profile x^2/2 + k x^4, for the slip-zone reference."""

    name = "quartic"

    def load(self, a):
        return quartic_load(np.asarray(a, dtype=float))

    def load_slope(self, a):
        return quartic_load_slope(np.asarray(a, dtype=float))

    def half_width(self, P):
        return quartic_a(np.asarray(P, dtype=float))


def quartic_table(points: int) -> TableLaw:
    a = np.linspace(8.0, 14.0, points)
    return TableLaw(quartic_load(a), a)


# --- Hertz: a power law is a straight line in log-log, reproduced exactly ------------------
@pytest.mark.parametrize("points", [5, 10, 50])
def test_hertz_table_reproduces_a_and_its_slope_and_L_I_to_1e_12(points):
    P = np.linspace(50.0, 200.0, points)
    law = TableLaw(P, hertz_a(P))
    loads = np.linspace(50.0, 200.0, 1001)
    a = hertz_a(loads)
    assert np.max(np.abs(law.half_width(loads) / a - 1)) < 1e-14
    assert np.max(np.abs(law.half_width_slope(loads) / (a / (2 * loads)) - 1)) < 1e-12
    L_I = multiplier_19(a, np.pi * a / 2)  # dP/da of (29) with R = E* = 1
    assert np.max(np.abs(law.normal_multiplier(loads) / L_I - 1)) < 1e-12
    assert np.max(np.abs(law.normal_multiplier_slope(loads) / (L_I / (4 * loads)) - 1)) < 1e-9


@pytest.mark.parametrize("points", [5, 10, 50])
def test_hertz_table_reports_an_error_at_rounding_level(points):
    P = np.linspace(50.0, 200.0, points)
    law = TableLaw(P, hertz_a(P))
    loads = np.linspace(50.0, 200.0, 101)
    errors = law.error_estimate(loads)
    assert np.max(errors["a"] / hertz_a(loads)) < 1e-13
    assert np.max(errors["L_I"] / law.normal_multiplier(loads)) < 1e-11


@pytest.mark.parametrize("points", [5, 20, 50])
def test_hertz_table_gives_the_hertz_stick_boundary_within_its_reported_error(points):
    P = np.linspace(80.0, 130.0, points)
    law = TableLaw(P, hertz_a(P))
    cycle, mu = LoadCycle(100, 0, 105, 1), 0.1  # the paper's Fig. 5 cycle
    a1, a2 = hertz_a(100.0), hertz_a(105.0)
    b_hertz = eq22(mu, 0.2, 0.0, a1, a2, np.sqrt(a1 / 2), np.sqrt(a2 / 2))  # (22) with (31)
    b_table = slip_zone(law, cycle, mu).b_paper
    error = law.error_of(lambda fit: slip_zone(fit, cycle, mu).b_paper)
    assert abs(b_table - b_hertz) <= max(float(error), 1e-12 * b_hertz)
    assert abs(b_table - b_hertz) < 1e-12 * b_hertz


# --- a law that is not a power law: the reported error bounds the true one --------------
def true_fit_errors(law, loads):
    """|fit - quartic law| of a, a'(P) and L_I (19) at ``loads``."""
    a = quartic_a(loads)
    return {
        "a": np.abs(law.half_width(loads) - a),
        "a_slope": np.abs(law.half_width_slope(loads) - 1 / quartic_load_slope(a)),
        "L_I": np.abs(law.normal_multiplier(loads) - multiplier_19(a, quartic_load_slope(a))),
    }


@pytest.mark.parametrize("points", [5, 10, 20, 50])
def test_fit_error_of_a_slope_and_L_I_never_exceeds_the_reported_error(points):
    law = quartic_table(points)
    loads = np.linspace(law.P[0], law.P[-1], 4001)
    true = true_fit_errors(law, loads)
    reported = law.error_estimate(loads)
    for key in true:
        assert np.all(true[key] <= reported[key]), key


@pytest.mark.parametrize("points", [5, 10, 20, 50])
def test_reported_error_is_within_100x_of_the_true_error(points):
    law = quartic_table(points)
    loads = np.linspace(law.P[0], law.P[-1], 4001)
    true = true_fit_errors(law, loads)
    reported = law.error_estimate(loads)
    for key in true:
        # Measured: 3x-30x (a), 3x-9x (a', L_I) for 5-50 points.
        assert reported[key].max() < 100 * true[key].max(), key


def test_fit_error_shrinks_with_the_cube_of_the_spacing():
    loads = np.linspace(quartic_load(8.0), quartic_load(14.0), 4001)
    errors = [
        np.max(np.abs(quartic_table(n).half_width(loads) - quartic_a(loads))) for n in (11, 21, 41)
    ]
    # Halving the spacing divides a third-order error by ~8.
    assert 6 < errors[0] / errors[1] < 12 and 6 < errors[1] / errors[2] < 12


@pytest.mark.parametrize("points", [5, 10, 50])
@pytest.mark.parametrize(
    "P1, dP, Q2", [(400.0, 20.0, 3.0), (900.0, 10.0, 1.5), (2000.0, 50.0, 8.0)]
)
def test_stick_boundary_22_from_the_table_is_within_its_reported_error(points, P1, dP, Q2):
    law = quartic_table(points)
    cycle, mu = LoadCycle(P1, 0.0, P1 + dP, Q2), 0.1
    exact = slip_zone(QuarticProfileLaw(), cycle, mu)
    fitted = slip_zone(law, cycle, mu)
    for key in ("b", "slip_zone_width"):
        error = law.error_of(lambda fit, key=key: getattr(slip_zone(fit, cycle, mu), key))
        assert abs(getattr(fitted, key) - getattr(exact, key)) <= error, key


@pytest.mark.parametrize("seed", range(12))
def test_largest_error_of_a_scattered_fe_table_is_within_the_largest_reported_error(seed):
    # Hertz points with a 1e-4 relative scatter, as from a mesh-limited FE model.  Pointwise
    # the fit's error at a point is that point's scatter, which the refits see only in part;
    # over the table the largest reported error covers the largest error.
    P = np.linspace(50.0, 200.0, [6, 10, 16, 30][seed % 4])
    rng = np.random.default_rng(seed)
    noise = 1e-4 * (rng.uniform(-1, 1, P.size) if seed % 2 else rng.normal(0, 1, P.size))
    law = TableLaw(P, hertz_a(P) * (1 + noise))
    loads = np.linspace(50.0, 200.0, 2001)
    a = hertz_a(loads)
    reported = law.error_estimate(loads)
    assert np.abs(law.half_width(loads) - a).max() <= reported["a"].max()
    assert np.abs(law.half_width_slope(loads) - a / (2 * loads)).max() <= reported["a_slope"].max()


# --- the law's other duties --------------------------------------------------------------
def test_growth_keeps_full_precision_at_dP_over_P1_of_1e_10_even_across_a_table_point():
    law = quartic_table(10)
    dP = 2.0**-33 * law.P[4]
    for P1 in (0.5 * (law.P[3] + law.P[4]), law.P[4] - 0.5 * dP):
        growth = law.half_width_growth(P1, dP)
        # a2 - a1 = a'(P1) dP (1 + O(dP a''/a')) with dP a''/a' ~ 1e-10.
        assert abs(growth / (law.half_width_slope(P1) * dP) - 1) < 1e-8


def test_growth_equals_the_difference_of_half_widths_for_a_large_step():
    law = quartic_table(10)
    P1, dP = law.P[1] * 1.01, law.P[6] - law.P[1]
    expected = law.half_width(P1 + dP) - law.half_width(P1)
    assert law.half_width_growth(P1, dP) == pytest.approx(expected, rel=1e-13)


def test_load_inverts_the_fitted_half_width():
    law = quartic_table(10)
    loads = np.linspace(law.P[0], law.P[-1], 50)
    assert np.allclose(law.load(law.half_width(loads)), loads, rtol=1e-14, atol=0)
    assert np.allclose(
        law.load_slope(law.half_width(loads)) * law.half_width_slope(loads), 1, rtol=1e-13, atol=0
    )


def test_multiplier_slope_matches_a_central_difference_of_L_I():
    law = quartic_table(10)
    P = 0.5 * (law.P[4] + law.P[5])
    step = 1e-4 * P
    difference = (law.normal_multiplier(P + step) - law.normal_multiplier(P - step)) / (2 * step)
    assert law.normal_multiplier_slope(P) == pytest.approx(difference, rel=1e-7)


def test_loads_outside_the_table_are_reported_as_warnings():
    law = quartic_table(10)
    low, high = law.load_range
    assert law.load_warnings(low, high) == []
    messages = law.load_warnings(0.5 * low, 2 * high)
    assert len(messages) == 2
    # The value itself is in the result (P1, P2); the warning says what is wrong with it.
    assert messages[0].startswith("P1 is outside the table's loads")
    assert messages[1].startswith("P2 is outside the table's loads")


@settings(max_examples=60, deadline=None)
@given(
    steps_P=st.lists(st.floats(0.01, 10.0), min_size=4, max_size=30),
    ratios=st.lists(st.floats(0.001, 10.0), min_size=4, max_size=30),
)
def test_fit_of_any_increasing_table_is_strictly_increasing(steps_P, ratios):
    size = min(len(steps_P), len(ratios))
    P = np.cumsum(steps_P[:size])
    a = np.cumsum(ratios[:size])
    law = TableLaw(P, a)
    inside = np.linspace(P[0], P[-1], 2001)
    assert np.all(law.half_width_slope(inside) > 0)
    # Beyond the table the fit continues as the power law of its end slope.  With an extreme
    # table (a growing 500-fold over a 1 % load step) that exponent runs into the thousands and
    # the half-width leaves the double range not far out: such a load has no half-width (marked,
    # and refused by half_width), never inf or 0.  Every other load's half-width is a positive
    # double, increasing with the load.
    outside = np.concatenate(
        [np.linspace(0.5 * P[0], P[0], 500), np.linspace(P[-1], 2 * P[-1], 500)]
    )
    loads = np.sort(np.concatenate([inside, outside]))
    values, found = law.half_width_where_possible(loads)
    assert found[(loads >= P[0]) & (loads <= P[-1])].all()
    assert np.all(np.isfinite(values[found]) & (values[found] > 0))
    assert np.all(np.diff(values[found]) >= 0)
    assert np.isnan(values[~found]).all()
    if not found.all():
        with pytest.raises(InputError, match="beyond double precision"):
            law.half_width(loads[~found])
    assert np.allclose(law.half_width(P), a, rtol=1e-13, atol=0)


def test_a_steep_table_refuses_loads_whose_continuation_leaves_the_doubles():
    """Hypothesis found this table: the last point's a jumps 3 -> 8 over a load step of
    0.09 %, so the continuation is a ~ P^1067 and a(2 P_max) was inf (with a RuntimeWarning
    from the arithmetic on it).  Now that load has no half-width: refused by the law, marked
    by the cycle, and the slip zone names --P2; within double range the law still answers."""
    law = TableLaw(np.cumsum([1, 6, 10, 0.015625]), np.cumsum([1, 1, 1, 5]))
    P_max = law.load_range[1]
    exponent = float(np.log(8 / 3) / np.log(P_max / 17))  # the end secant's exponent
    with pytest.raises(InputError, match=r"^P: is outside the range.*beyond double precision"):
        law.half_width(2 * P_max)
    with pytest.raises(InputError, match="beyond double precision"):
        law.half_width_slope(2 * P_max)
    _, found = law.half_width_where_possible(np.array([P_max, 2 * P_max]))
    assert found.tolist() == [True, False]
    state = law.cycle_state(17.0, 2 * P_max - 17.0)
    assert not bool(state.found2) and np.isnan(state.a2)
    with pytest.raises(InputError, match="^P2: "):
        slip_zone(law, LoadCycle(17.0, 0.0, 2 * P_max, 0.0), 0.3)
    # a load just beyond the table: a finite power-law continuation of about that exponent
    a = float(law.half_width(1.001 * P_max))
    assert 8 < a < 8 * 1.001 ** (2 * exponent)


# --- reading the table --------------------------------------------------------------------
def write(tmp_path, text):
    path = tmp_path / "law.csv"
    path.write_text(text)
    return path


def test_csv_with_extra_columns_comments_and_any_column_order_reads_like_the_arrays(tmp_path):
    P = np.array([80.0, 90.0, 100.0, 110.0, 120.0])
    rows = "\n".join(
        f"{a!r}, {p!r}, mesh-{i}"
        for i, (p, a) in enumerate(zip(P.tolist(), hertz_a(P).tolist(), strict=True))
    )
    law = TableLaw.from_csv(write(tmp_path, f"# FE run 12\na, P, note\n{rows}\n\n"))
    assert np.array_equal(law.P, P) and np.array_equal(law.a, hertz_a(P))


@pytest.mark.parametrize(
    "text, message",
    [
        ("P,b\n1,1\n2,2\n3,3\n4,4\n", r"^table: .*line 1: the header has no column a"),
        ("load,a\n1,1\n2,2\n3,3\n4,4\n", r"^table: .*line 1: the header has no column P\b"),
        ("P,a\n1,1\n2,2\n3,x3\n4,4\n", r"^table: .*line 4: a: 'x3' is not a number"),
        ("P,a\n1,1\n2,2\n\n3,3,9\n", r"^table: .*line 5: line has 3 fields, the header has 2"),
        ("P,a\n1,1\n2,2\n3,3\n", r"^table: .*: needs at least 4 points .*\(got 3\)"),
        (
            "P,a\n1,1\n2,2\n3,2\n4,4\n",
            r"^table: .*: a: table values must be strictly increasing \(line 4 does not exceed "
            r"line 3\)",
        ),
        # Lines as an editor numbers them: the header is line 1.
        (
            "P,a\n1,1\n3,2\n2,3\n4,4\n",
            r"^table: .*: P: table values must be strictly increasing \(line 4 does not exceed "
            r"line 3\)",
        ),
        ("P,a\n0,1\n1,2\n2,3\n4,4\n", r"^table: .*: P: table values must be > 0 \(line 2\)"),
        (
            "# comment\nP,a\n\n1,1\n2,nan\n3,3\n4,4\n",
            r"^table: .*: a: table values must be finite \(not inf or nan; line 5\)",
        ),
        ("# only a comment\n", r"^table: .*has no header"),
    ],
)
def test_bad_table_files_are_refused_with_the_line_and_the_rule(tmp_path, text, message):
    with pytest.raises(InputError, match=message):
        TableLaw.from_csv(write(tmp_path, text))


def test_a_missing_table_file_is_refused_by_name(tmp_path):
    with pytest.raises(InputError, match=r"^table: cannot read .*nothing\.csv"):
        TableLaw.from_csv(tmp_path / "nothing.csv")
