"""The solver refuses nonsense with an InputError naming the parameter and the rule."""

from __future__ import annotations

import numpy as np
import pytest

from asymslip import HertzLaw, InputError, LoadCycle, TableLaw
from asymslip.solver import ExpressionProfile, LoadPath, TableProfile, refine, solve

LAW = HertzLaw(R=1.0, E_star=1.0)
CYCLE = LoadCycle(100.0, 0.0, 105.0, 1.0)


@pytest.mark.parametrize(
    "options, match",
    [
        ({"elements": 10}, "elements: must be at least 64"),
        ({"elements": 100.5}, "elements: must be a whole number"),
        ({"elements": True}, "elements: must be a whole number"),
        ({"steps": 0}, "steps: must be at least 1"),
        ({"max_cycles": 1}, "max_cycles: must be at least 2"),
        ({"tolerance": 0.0}, "tolerance: must be > 0"),
        ({"tolerance": float("nan")}, "tolerance: must be finite"),
        ({"domain": (3.0, -3.0)}, "domain: must be .left, right. with right > left"),
        ({"E_star": 2.0}, "E_star: differs from the law's E"),
    ],
)
def test_bad_settings_are_refused(options, match):
    with pytest.raises(InputError, match=match):
        solve(LAW, CYCLE, 0.1, **options)


@pytest.mark.parametrize("mu", [0.0, -0.1, float("inf")])
def test_friction_coefficient_must_be_positive_and_finite(mu):
    with pytest.raises(InputError, match="mu: must be"):
        solve(LAW, CYCLE, mu)


def test_gross_sliding_anywhere_on_the_path_is_refused_naming_the_point():
    path = LoadPath([[100.0, 0.0], [105.0, 3.0], [102.0, 31.0]])
    with pytest.raises(InputError, match=r"path: point 3 \(P = 102, Q = 31\) has \|Q\| >= mu P"):
        solve(LAW, path, 0.3)


@pytest.mark.parametrize(
    "points, match",
    [
        ([[100.0, 0.0]], "path: needs at least 2 points"),
        ([[100.0, 0.0], [-5.0, 0.0]], r"path: P must be > 0 at every point \(point 2\)"),
        ([[100.0, 0.0], [100.0, 0.0]], "path: all points are the same"),
        ([[100.0], [105.0]], r"path: must be rows of \(P, Q"),
        ([[100.0, 0.0], [105.0, float("nan")]], "path: must be finite"),
    ],
)
def test_bad_paths_are_refused(points, match):
    with pytest.raises(InputError, match=match):
        LoadPath(np.array(points, dtype=float))


def test_a_profile_needs_a_modulus():
    with pytest.raises(InputError, match="E_star: is needed with a profile"):
        solve(ExpressionProfile("x**2/2"), CYCLE, 0.1)


def test_a_law_without_a_profile_is_refused_with_the_way_out():
    table = TableLaw([1.0, 2.0, 4.0, 8.0], [1.0, 1.4, 2.0, 2.8])
    with pytest.raises(InputError, match="law: the table law has no profile h.x.*or a table"):
        solve(table, LoadCycle(2.0, 0.0, 2.1, 0.01), 0.3)


@pytest.mark.parametrize(
    "text, match",
    [
        ("x**2/(2*R)", "profile: has names without values|profile: unknown name"),
        ("__import__('os')", "profile"),
        ("", "profile: is empty"),
    ],
)
def test_bad_profile_formulas_are_refused(text, match):
    with pytest.raises(InputError, match=match):
        ExpressionProfile(text)


def test_a_profile_that_is_not_finite_over_the_contact_is_refused():
    profile = ExpressionProfile("x**2/2 + 1/(x - 0.3)")
    with pytest.raises(InputError, match="profile: "):
        solve(profile, CYCLE, 0.1, E_star=1.0, elements=200, domain=(-13.0, 13.0))


def test_a_contact_beyond_the_table_is_refused():
    x = np.linspace(-2.0, 2.0, 21)
    table = TableProfile(x, x**2 / 2)  # a contact of half-width ~11 at P = 100 is far wider
    with pytest.raises(InputError, match="profile: the contact reaches .* beyond the table's x"):
        solve(table, CYCLE, 0.1, E_star=1.0, elements=200)


@pytest.mark.parametrize(
    "x, h, match",
    [
        ([0.0, 1.0], [0.0, 1.0], "profile: a table needs at least 3 points"),
        ([0.0, 2.0, 1.0], [1.0, 0.0, 1.0], "profile: the table's x must be strictly increasing"),
        ([0.0, 1.0, 2.0], [1.0, 0.0], "profile: the x and h columns must have the same length"),
    ],
)
def test_bad_tables_are_refused(x, h, match):
    with pytest.raises(InputError, match=match):
        TableProfile(x, h)


def test_refinement_levels_must_make_a_sequence():
    with pytest.raises(InputError, match="levels: must be at least 2"):
        refine(LAW, CYCLE, 0.1, elements=100, levels=1)
