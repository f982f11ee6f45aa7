"""What the solver hands on: the JSON dictionary, the asymptotes beside it, files, refinement."""

from __future__ import annotations

import builtins
import json

import numpy as np
import pytest

from asymslip import HertzLaw, InputError, LoadCycle
from asymslip.solver import LoadPath, refine, solve
from asymslip.solver.compare import with_asymptotes
from asymslip.solver.outputs import write_outputs
from asymslip.solver.refine import extrapolate

LAW = HertzLaw(R=1.0, E_star=1.0)
CYCLE = LoadCycle(100.0, 0.0, 105.0, 1.0)
TENSION = LoadCycle(100.0, 0.0, 105.0, 1.0, 0.0, 0.05)


@pytest.fixture(scope="module")
def result():
    return solve(LAW, CYCLE, 0.1, elements=400, steps=5)


def test_dictionary_has_the_right_edge_on_top_and_the_left_under_left(result):
    data = json.loads(json.dumps(result.to_dict()))  # plain JSON types only
    for edge in (data, data["left"]):
        for key in (
            "b",
            "b_error",
            "slip_direction",
            "a1",
            "a1_error",
            "a2",
            "a2_error",
            "b1",
            "b2",
        ):
            assert key in edge
        assert edge["b_error"] >= data["solver"]["element_size"]
    assert data["b"] == result.right.b and data["left"]["b"] == result.left.b
    assert data["solver"]["steady"] is True and data["solver"]["cycles"] == result.cycles
    assert [s["label"] for s in data["states"]] == ["1", "2"]


def test_asymptotes_are_reported_with_their_difference_in_elements(result):
    compared = with_asymptotes(result, LAW, CYCLE, 0.1)
    entry = compared.right.asymptotes["b_exact"]
    exact = float(LAW.half_width(97.5))
    assert entry["value"] == pytest.approx(exact, rel=1e-14)
    assert entry["difference"] == pytest.approx(exact - result.right.b, rel=1e-12)
    assert entry["elements"] == pytest.approx(entry["difference"] / result.element_size)
    assert entry["within_error"] is True
    data = compared.to_dict()
    assert set(data["asymptotes"]) == {
        "b",
        "b_paper",
        "b_first_order",
        "b_corrective_stick",
        "b_exact",
    }
    assert set(data["left"]["asymptotes"]) == set(data["asymptotes"])


def test_b_exact_does_not_exist_with_tension():
    tension = solve(LAW, TENSION, 0.1, elements=300, steps=4)
    compared = with_asymptotes(tension, LAW, TENSION, 0.1)
    assert compared.right.asymptotes["b_exact"] is None
    assert compared.right.asymptotes["b"]["value"] is not None


def test_asymptotes_refuse_a_result_of_another_cycle(result):
    with pytest.raises(InputError, match="cycle: the solver result was computed for another"):
        with_asymptotes(result, LAW, TENSION, 0.1)
    path_result = solve(LAW, LoadPath([[100.0, 0.0], [105.0, 1.0]]), 0.1, elements=200)
    with pytest.raises(InputError, match="only for the paper's two-state cycle"):
        with_asymptotes(path_result, LAW, CYCLE, 0.1)


def test_outputs_are_written_and_read_back(result, tmp_path):
    files = write_outputs(result, tmp_path / "out")
    assert [f.name for f in files] == ["tractions.csv", "slip.csv", "energy.csv", "solver.png"]
    assert files[-1].read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    table = np.genfromtxt(files[0], delimiter=",", names=True, skip_header=3)
    assert np.array_equal(table["q_2"], result.states[1].shear)  # 17 digits read back exactly
    assert np.array_equal(table["q_diff"], result.q_diff)
    energy = np.genfromtxt(files[2], delimiter=",", names=True, skip_header=3)
    assert np.array_equal(energy["energy"], result.energy)
    assert not list((tmp_path / "out").glob(".*partial"))


def test_missing_matplotlib_is_one_input_error_and_nothing_is_written(
    result, tmp_path, monkeypatch
):
    real_import = builtins.__import__

    def no_matplotlib(name, *args, **kwargs):
        if name.startswith("matplotlib"):
            raise ImportError("no matplotlib here")
        return real_import(name, *args, **kwargs)

    monkeypatch.setattr(builtins, "__import__", no_matplotlib)
    with pytest.raises(InputError, match=r"out: .*install the 'plot' extra"):
        write_outputs(result, tmp_path / "out")
    assert not (tmp_path / "out").exists()
    assert len(write_outputs(result, tmp_path / "csv", png=False)) == 3


def test_an_existing_file_is_not_an_output_folder(result, tmp_path):
    target = tmp_path / "taken"
    target.write_text("x")
    with pytest.raises(InputError, match="out: must be a folder"):
        write_outputs(result, target)


def test_richardson_recovers_the_limit_and_order_of_a_clean_sequence():
    limit, constant = 2.0, 0.3
    values = tuple(limit + constant * (1 / 2**k) ** 2 for k in range(3))  # second order
    extrapolation = extrapolate(values)
    assert extrapolation.method == "richardson"
    assert extrapolation.order == pytest.approx(2.0)
    assert extrapolation.value == pytest.approx(limit, rel=1e-14)
    assert extrapolation.error >= abs(values[2] - values[1])


def test_an_erratic_sequence_reports_its_spread():
    extrapolation = extrapolate((1.0, 1.2, 1.1))
    assert extrapolation.method == "spread"
    assert extrapolation.value == 1.1 and extrapolation.error == pytest.approx(0.1)


def test_refinement_brackets_the_exact_boundaries():
    P1, P2 = 100.0, 105.0
    cycle = LoadCycle(P1, 0.0, P2, 2.5)
    refined = refine(LAW, cycle, 0.2, elements=250, levels=3, steps=4)
    assert [r.elements for r in refined.results] == [250, 500, 1000]
    assert len({(r.grid.start, r.grid.end) for r in refined.results}) == 1  # nested grids
    exact = {
        "b": float(LAW.half_width((P1 + P2) / 2 - 2.5 / (2 * 0.2))),
        "a1": float(LAW.half_width(P1)),
        "a2": float(LAW.half_width(P2)),
    }
    for key, value in exact.items():
        extrapolation = refined.right[key]
        assert abs(extrapolation.value - value) <= extrapolation.error
    data = refined.to_dict()
    assert data["refinement"]["b"]["values"] == [r.right.b for r in refined.results]
    assert data["solver"]["refinement_elements"] == [250, 500, 1000]


def test_a_refinement_carries_the_asymptotes_of_its_finest_run():
    refined = refine(LAW, CYCLE, 0.1, elements=200, levels=2, steps=3)
    compared = with_asymptotes(refined, LAW, CYCLE, 0.1)
    data = compared.to_dict()
    assert data["asymptotes"]["b_exact"]["difference"] == pytest.approx(
        float(LAW.half_width(97.5)) - refined.finest.right.b, rel=1e-12
    )
    assert "refinement" in data and "asymptotes" in data["left"]


def test_the_solver_imports_neither_the_asymptotes_nor_an_optional_extra():
    import subprocess
    import sys

    code = (
        "import sys, asymslip.solver, asymslip.solver.run; "
        "print(sorted(m for m in ('asymslip.slip_zones', 'matplotlib', 'sympy', 'scipy') "
        "if m in sys.modules))"
    )
    completed = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True
    )
    assert completed.stdout.strip() == "[]"
