"""What a solve needs is checked before it is taken, and --out writes what was asked for.

The memory estimate (:mod:`asymslip.solver.memory`) must refuse a grid no machine holds at
once, without allocating it, and must lie above what a solve really uses (the peak resident
memory of a fresh process, measured here).
"""

from __future__ import annotations

import builtins
import json
import subprocess
import sys
import time
import tracemalloc
from pathlib import Path

import pytest

from asymslip import HertzLaw, InputError, LoadCycle
from asymslip.cli import main
from asymslip.solver import refine, solve
from asymslip.solver.memory import check_memory, estimate
from asymslip.solver.path import LoadPath

LAW = HertzLaw(R=1.0, E_star=1.0)
CYCLE = LoadCycle(100.0, 0.0, 105.0, 1.0)
PATH = LoadPath.from_cycle(CYCLE)
HERTZ = ("--law", "hertz", "--R", "1", "--E-star", "1", "--mu", "0.1")
LOADS = ("--P1", "100", "--Q1", "0", "--P2", "105", "--Q2", "1")


def test_a_billion_elements_are_refused_with_the_figure_before_anything_is_allocated():
    tracemalloc.start()
    started = time.process_time()
    with pytest.raises(InputError, match=r"^elements: 1,000,000,000 elements need about 1\.\d+ TB"):
        solve(LAW, CYCLE, 0.1, elements=10**9)
    _, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    assert peak < 10 * 2**20  # nothing of the grid's size was allocated
    assert time.process_time() - started < 5.0


def test_the_refusal_follows_the_memory_available():
    need = estimate(10**6, 20, PATH).total
    check_memory(10**6, 20, PATH, available=need + 1)  # fits: no error
    with pytest.raises(InputError, match=r"elements: .* more than the .* available: give at most"):
        check_memory(10**6, 20, PATH, available=need - 1)


def test_a_refinement_is_checked_at_its_finest_grid():
    with pytest.raises(InputError, match=r"^elements: the finest grid \(4,000,000,000 elements\)"):
        refine(LAW, CYCLE, 0.1, elements=10**9, levels=3)


def test_the_estimate_counts_the_steps_kept_and_the_normal_solutions_a_solve_makes():
    need = estimate(1000, 20, PATH)
    # The paper's cycle goes up and down one line: 21 distinct loads (P1 and 20 steps).
    assert (need.steps_kept, need.loads_kept) == (40, 21)
    assert solve(LAW, CYCLE, 0.1, elements=200, steps=20).normal_solves == 21
    triangle = LoadPath([[100.0, 0.0], [105.0, 1.0], [102.0, -1.0]])
    result = solve(LAW, triangle, 0.3, elements=200, steps=5)
    assert estimate(1000, 5, triangle).steps_kept == 15
    assert estimate(1000, 5, triangle).loads_kept == result.normal_solves


@pytest.mark.skipif(not Path("/proc/self/status").exists(), reason="needs Linux's /proc")
@pytest.mark.parametrize("elements", [20_000])
def test_the_estimate_lies_above_the_measured_peak_memory(elements):
    # VmHWM, the peak of this process image: ru_maxrss of a child also counts the memory of the
    # parent it was forked from (here a whole test session).
    code = (
        "from asymslip import HertzLaw, LoadCycle; from asymslip.solver import solve; "
        f"solve(HertzLaw(1, 1), LoadCycle(100, 0, 105, 1), 0.1, elements={elements}); "
        "print([int(line.split()[1]) * 1024 for line in open('/proc/self/status') "
        "if line.startswith('VmHWM:')][0])"
    )
    completed = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert completed.returncode == 0, completed.stderr
    peak = int(completed.stdout)
    assert peak <= estimate(elements, 20, PATH).total


@pytest.mark.slow
@pytest.mark.parametrize("elements", [200_000])
def test_the_estimate_lies_above_the_measured_peak_memory_on_a_large_grid(elements):
    test_the_estimate_lies_above_the_measured_peak_memory(elements)


def _block_matplotlib(monkeypatch: pytest.MonkeyPatch) -> None:
    real_import = builtins.__import__

    def no_matplotlib(name, *args, **kwargs):  # noqa: ANN001, ANN002, ANN003, ANN202
        if name.startswith("matplotlib"):
            raise ImportError("no matplotlib here")
        return real_import(name, *args, **kwargs)

    monkeypatch.setattr(builtins, "__import__", no_matplotlib)


def test_no_plot_writes_the_csv_files_only_without_matplotlib(tmp_path, monkeypatch, capsys):
    _block_matplotlib(monkeypatch)
    out = tmp_path / "out"
    status = main(
        [
            "solve",
            *HERTZ,
            *LOADS,
            "--elements",
            "200",
            "--steps",
            "2",
            "--out",
            str(out),
            "--no-plot",
            "--json",
        ]
    )
    assert status == 0
    assert sorted(path.name for path in out.iterdir()) == [
        "energy.csv",
        "slip.csv",
        "tractions.csv",
    ]
    assert json.loads(capsys.readouterr().out)["solver"]["steady"] is True


def test_without_matplotlib_the_refusal_names_the_way_to_the_csv_files(
    tmp_path, monkeypatch, capsys
):
    _block_matplotlib(monkeypatch)
    out = tmp_path / "out"
    status = main(["solve", *HERTZ, *LOADS, "--elements", "200", "--steps", "2", "--out", str(out)])
    error = capsys.readouterr().err.strip().splitlines()
    assert status == 2 and len(error) == 1
    assert error[0].startswith("asymslip: error: --out: drawing solver.png needs matplotlib")
    assert "--no-plot" in error[0]
    assert not out.exists()
