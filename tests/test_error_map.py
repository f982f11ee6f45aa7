"""The error map: every estimate of the stick boundary against the reference solver.

The claims are read from the committed ``generated/report/error_map.csv`` (written by
``make error-map``); the slow tests recompute rows with the solver and check that the committed
map is fresh and that its left edges are the mirror images of fresh right-edge runs.  Errors
are in solver elements, and "bounds" are the solver's stated bound on its stick boundary (one
element, or a little more where it was extrapolated in the load steps).  The independent
reference for b_exact is (33) with each law's own a(P), transcribed here.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from asymslip import FlatRoundedLaw, HertzLaw, InputError, PowerLaw
from asymslip.cli import main
from asymslip.codegen.report import ERROR_MAP_ESTIMATES, error_map_section
from asymslip.solver import solve
from asymslip.solver.error_map import (
    CHECK_CASES,
    COLUMNS,
    ESTIMATES,
    MU,
    MapCase,
    compare_texts,
    csv_text,
    error_map,
    map_cases,
    read_csv,
    row_differences,
)

ROOT = Path(__file__).resolve().parents[1]
CSV = ROOT / "generated" / "report" / "error_map.csv"
TEXT = CSV.read_text(encoding="utf-8")
ROWS = read_csv(TEXT)
SLIPPING = [row for row in ROWS if row["slip_direction"] != "0"]
LAWS = ("hertz", "flat-rounded", "power-1.5", "power-3")


def number(row: dict[str, str], key: str) -> float:
    return float(row[key])


def bounds(row: dict[str, str], estimate: str) -> float:
    """|estimate - solver b| in units of the solver's bound."""
    return abs(number(row, f"{estimate}_elements")) / number(row, "b_error_elements")


def tension(row: dict[str, str]) -> bool:
    return number(row, "tau") != 0


def quiet(row: dict[str, str]) -> bool:
    """slip_zone gives no validity warning (eq24-eq27 all at most 0.1)."""
    return row["validity_warning"] == "0"


# --- what the map covers --------------------------------------------------------------------------
def test_the_map_has_both_edges_of_every_cycle_of_the_grid():
    assert len(map_cases()) == 180
    keys = [(row["law"], row["a2_a1"], row["lam_mu"], row["tau"], row["edge"]) for row in ROWS]
    assert len(keys) == len(set(keys)) == 360
    assert {row["law"] for row in ROWS} == set(LAWS)
    assert {row["a2_a1"] for row in ROWS} == {"1.02", "1.05", "1.10"}
    assert list(ROWS[0]) == list(COLUMNS)


@pytest.mark.parametrize("law", LAWS)
def test_every_law_has_the_other_edge_slipping_each_way_and_sticking(law):
    branches = {row["other_edge"] for row in SLIPPING if row["law"] == law}
    assert branches == {"same", "opposite", "none"}


def test_the_edges_see_tension_of_both_signs_and_none():
    taus = {number(row, "edge_tau") for row in SLIPPING}
    assert min(taus) <= -1 and max(taus) >= 2 and 0 in taus
    assert sum(not tension(row) for row in SLIPPING) == 72


def test_every_slip_zone_spans_at_least_five_elements():
    # The bound (about one element) is at most 18 % of the narrowest slip zone, 1 % of the widest.
    widths = [number(row, "width_elements") for row in SLIPPING]
    assert min(widths) > 5 and max(widths) > 100


# --- the solver against the exact solution, and the slip directions -------------------------------
def test_slip_zone_and_the_solver_agree_on_the_slip_direction_of_every_edge():
    assert all(row["slip_direction"] == row["solver_slip_direction"] for row in ROWS)


def test_without_tension_a_of_PK_lies_within_a_tenth_of_a_bound_of_the_solver():
    """Jaeger-Ciavarella is exact without tension: this is the solver's check."""
    exact = [bounds(row, "b_exact") for row in SLIPPING if not tension(row)]
    assert len(exact) == 72
    assert max(exact) < 0.1  # measured 0.09


def test_where_an_edge_does_not_slip_the_solver_sticks_up_to_a1():
    sticking = [row for row in ROWS if row["slip_direction"] == "0"]
    assert len(sticking) == 48
    assert all(
        abs(number(row, "b_elements")) <= number(row, "b_error_elements") for row in sticking
    )


def half_width(law: str, P: float) -> float:
    """a(P) of each law of the map, transcribed: Hertz (29); the power law P = K E* A a^n,
    K = sqrt(pi) Gamma((n+1)/2)/Gamma(n/2); the rounded flat by bisection on
    P = E* a^2 (pi - 2 phi0 - sin 2 phi0)/(4R), phi0 = arcsin(c/a)."""
    if law == "hertz":
        return math.sqrt(4 * P / math.pi)
    if law.startswith("power"):
        A, n = (0.3, 1.5) if law == "power-1.5" else (0.05, 3.0)
        K = math.sqrt(math.pi) * math.gamma((n + 1) / 2) / math.gamma(n / 2)
        return (P / (K * A)) ** (1 / n)

    def load(a: float) -> float:
        phi0 = math.asin(1.0 / a)
        return a**2 * (math.pi - 2 * phi0 - math.sin(2 * phi0)) / 40

    low, high = 1.0, 10.0
    for _ in range(200):
        middle = (low + high) / 2
        low, high = (middle, high) if load(middle) < P else (low, middle)
    return (low + high) / 2


@pytest.mark.parametrize("law", LAWS)
def test_b_exact_in_the_map_is_a_of_PK_from_33(law):
    """b_solver + b_exact_elements x element = a(P_K), P_K = (P1 + P2)/2 - |dQ|/(2 mu) (33)."""
    laws = {
        "hertz": HertzLaw(1.0, 1.0),
        "flat-rounded": FlatRoundedLaw(1.0, 10.0, 1.0),
        "power-1.5": PowerLaw(0.3, 1.5, 1.0),
        "power-3": PowerLaw(0.05, 3.0, 1.0),
    }
    for row in (r for r in SLIPPING if r["law"] == law and not tension(r)):
        P1 = float(laws[law].load(2.0))
        P2 = float(laws[law].load(2.0 * number(row, "a2_a1")))
        P_K = (P1 + P2) / 2 - abs(number(row, "lam_mu") * MU * (P2 - P1)) / (2 * MU)
        mapped = number(row, "b_solver") + number(row, "b_exact_elements") * number(row, "element")
        # The printed precision: b_exact_elements to 1e-3 of an element.
        assert mapped == pytest.approx(half_width(law, P_K), abs=1e-3 * number(row, "element"))


# --- the headline claims --------------------------------------------------------------------------
def test_b_lies_within_one_bound_wherever_slip_zone_gives_no_validity_warning():
    chosen = [row for row in SLIPPING if quiet(row)]
    # All of a2/a1 = 1.02 and most of 1.05; at 1.10 the contact growth eq24 exceeds 0.1.
    assert len(chosen) == 180
    assert max(bounds(row, "b") for row in chosen if not tension(row)) < 0.1  # measured 0.09
    assert max(bounds(row, "b") for row in chosen if tension(row)) < 0.5  # measured 0.38


@pytest.mark.parametrize("law", LAWS)
def test_with_tension_eq22_misses_by_more_than_three_bounds_where_b_is_within_one(law):
    chosen = [row for row in SLIPPING if row["law"] == law and tension(row) and quiet(row)]
    worst = max(chosen, key=lambda row: bounds(row, "b_paper"))
    assert bounds(worst, "b_paper") > 3
    assert bounds(worst, "b") <= 1


def test_with_tension_eq22_overstates_the_slip_zone_by_up_to_three_quarters():
    worst = max(abs(number(row, "b_paper_fraction")) for row in SLIPPING if tension(row))
    assert 0.7 < worst < 0.8  # measured 0.756 (power n = 3, a2/a1 = 1.10)


def test_b_is_within_its_stated_accuracy_plus_the_bound_wherever_eq27_is_at_most_a_tenth():
    chosen = [row for row in SLIPPING if number(row, "eq27") <= 0.1]
    assert all(
        abs(number(row, "b_elements"))
        <= number(row, "b_accuracy_elements") + number(row, "b_error_elements")
        for row in chosen
    )


def test_where_b_exceeds_its_stated_accuracy_slip_zone_warns():
    beyond = [
        row
        for row in SLIPPING
        if abs(number(row, "b_elements"))
        > number(row, "b_accuracy_elements") + number(row, "b_error_elements")
    ]
    assert len(beyond) == 17  # the rounded flat and power n = 3, a2/a1 = 1.10, lam/mu >= 2
    assert all(row["validity_warning"] == "1" for row in beyond)
    assert {row["law"] for row in beyond} == {"flat-rounded", "power-3"}


def test_the_first_order_estimates_miss_by_more_than_two_bounds_before_any_warning():
    chosen = [row for row in SLIPPING if quiet(row)]
    assert max(bounds(row, "b_first_order") for row in chosen) > 3  # measured 4.8
    assert max(bounds(row, "b_corrective_stick") for row in chosen) > 2  # measured 2.6


# --- the CSV, its check and the report ------------------------------------------------------------
def test_a_number_may_differ_by_one_unit_in_its_last_printed_place():
    row = dict(ROWS[0])
    assert (
        row_differences(row, {**row, "b_elements": f"{number(row, 'b_elements') + 1e-3:.3f}"}) == []
    )
    assert row_differences(row, {**row, "b_elements": f"{number(row, 'b_elements') + 2e-3:.3f}"})
    assert row_differences(
        row, {**row, "other_edge": "opposite" if row["other_edge"] == "same" else "same"}
    )


def test_the_check_finds_a_changed_committed_number():
    fresh_text = TEXT  # compared with itself: fresh
    assert compare_texts(TEXT, fresh_text) == []
    lines = TEXT.splitlines(keepends=True)
    header = next(i for i, line in enumerate(lines) if line.startswith("law,"))
    fields = lines[header + 1].split(",")
    column = list(COLUMNS).index("b_paper_elements")
    fields[column] = f"{float(fields[column]) + 0.01:.3f}"
    tampered = "".join([*lines[: header + 1], ",".join(fields), *lines[header + 2 :]])
    problems = compare_texts(tampered, fresh_text)
    assert len(problems) == 1 and "b_paper_elements" in problems[0]
    assert compare_texts("".join(lines[:-2]), fresh_text)[0].startswith("the committed map has")


def test_an_unknown_law_is_refused_by_name():
    with pytest.raises(InputError, match="law"):
        MapCase("cylinder", 1.05, 2.0, 0.0)


def test_the_code_generator_reads_the_file_the_figure_command_writes():
    from asymslip.codegen.runner import ERROR_MAP_FILE, REPORT_FOLDER
    from asymslip.figures import ERROR_MAP_CSV

    assert CSV == ROOT / "generated" / REPORT_FOLDER / ERROR_MAP_FILE
    assert ERROR_MAP_FILE == ERROR_MAP_CSV


def test_the_report_summary_reads_the_largest_errors_from_the_csv():
    section = "\n".join(error_map_section(TEXT))
    assert set(ERROR_MAP_ESTIMATES) == set(ESTIMATES)
    worst = max(
        SLIPPING,
        key=lambda row: abs(number(row, "b_paper_elements"))
        if tension(row) and row["law"] == "power-3"
        else 0,
    )
    value = f"{abs(number(worst, 'b_paper_elements')):.2f}"
    assert "| power n = 3 | yes | 60 |" in section and value in section
    committed = (ROOT / "generated" / "report" / "derivation.md").read_text(encoding="utf-8")
    assert section in committed


@pytest.mark.slow  # matplotlib: about 2.5 s
def test_figure_error_map_redraws_the_png_from_the_committed_csv(tmp_path):
    (tmp_path / "error_map.csv").write_text(TEXT, encoding="utf-8")
    assert main(["figure", "error-map", "--out", str(tmp_path), "--redraw"]) == 0
    assert (tmp_path / "error_map.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert (tmp_path / "error_map.csv").read_text(encoding="utf-8") == TEXT


@pytest.mark.parametrize("option", [["--data", "x"], ["--redraw"], ["--every-row"]])
def test_figure_fig5_refuses_the_error_map_options(tmp_path, option, capsys):
    assert main(["figure", "fig5", "--out", str(tmp_path), *option]) == 2
    assert "applies to the error map only" in capsys.readouterr().err


def test_redrawing_without_a_csv_is_refused_naming_the_data_folder(tmp_path):
    with pytest.raises(InputError, match="data"):
        from asymslip.figures import write_error_map

        write_error_map(tmp_path, redraw=True)


# --- recomputed with the solver (CI's slow step) --------------------------------------------------
@pytest.mark.slow
def test_the_committed_map_is_fresh_at_its_printed_precision():
    """The check cases recomputed (one per law, each branch of the other edge): a few seconds."""
    fresh = csv_text(error_map([MapCase(*case) for case in CHECK_CASES]))
    assert compare_texts(TEXT, fresh) == []


@pytest.mark.slow
@pytest.mark.parametrize(
    "case", [("hertz", 1.10, 2.0, 0.5), ("power-3", 1.05, 0.5, 2.0)], ids=["same-way", "opposite"]
)
def test_the_left_edge_of_tau_is_the_right_edge_of_minus_tau(case):
    """By mirror symmetry: a fresh run with the tension reversed gives, at its right edge, the
    committed left edge (so the map's tau >= 0 covers both signs)."""
    law, ratio, lam_mu, tau = case
    committed = next(
        row
        for row in ROWS
        if (
            row["law"],
            number(row, "a2_a1"),
            number(row, "lam_mu"),
            number(row, "tau"),
            row["edge"],
        )
        == (*case, "left")
    )
    mirrored = error_map([MapCase(law, ratio, lam_mu, -tau)])[0]
    assert mirrored["edge"] == "right"
    difference = abs(mirrored["b_solver"] - number(committed, "b_solver"))
    assert difference <= number(committed, "b_error_elements") * number(committed, "element")


@pytest.mark.slow
def test_a_cycle_whose_edges_both_slip_needs_one_load_step():
    """The map runs such cycles with one step per half-cycle: 8 steps give the same b."""
    case = MapCase("flat-rounded", 1.10, 2.0, 0.5)
    law, cycle = case.contact_law, case.cycle()
    one, eight = (solve(law, cycle, MU, elements=2000, steps=steps) for steps in (1, 8))
    for side in ("right", "left"):
        assert abs(one.edge(side).b - eight.edge(side).b) <= 1e-3 * one.element_size


@pytest.mark.slow
def test_figure_error_map_check_exits_1_naming_a_stale_row(tmp_path, capsys):
    law, ratio, lam_mu, tau = CHECK_CASES[0]
    lines = TEXT.splitlines(keepends=True)
    target = f"{law},{ratio:.2f},{lam_mu:.2f},{tau:.2f},right,"
    index = next(i for i, line in enumerate(lines) if line.startswith(target))
    fields = lines[index].split(",")
    column = list(COLUMNS).index("b_solver")
    fields[column] = f"{float(fields[column]) + 1e-6:.10f}"
    lines[index] = ",".join(fields)
    (tmp_path / "error_map.csv").write_text("".join(lines), encoding="utf-8")
    assert main(["figure", "error-map", "--check", str(tmp_path)]) == 1
    out = capsys.readouterr()
    assert "b_solver" in out.out and "right edge" in out.out and "is stale" in out.err
