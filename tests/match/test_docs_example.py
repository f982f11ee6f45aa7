"""The worked example docs/examples/lab_recipe.py runs, prints its recipe and saves its figure."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

EXAMPLE = Path(__file__).resolve().parents[2] / "docs" / "examples" / "lab_recipe.py"


@pytest.mark.slow
def test_the_blade_root_example_designs_an_exact_recipe_the_solver_confirms(tmp_path: Path):
    pytest.importorskip("matplotlib")
    environment = dict(os.environ, PYTHONWARNINGS="error")
    run = subprocess.run(
        [sys.executable, str(EXAMPLE)],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        env=environment,
        timeout=120,
        check=False,
    )
    assert run.returncode == 0, run.stderr
    assert "(leading order, exact: True)" in run.stdout
    widths = next(line for line in run.stdout.splitlines() if "solver slip-zone widths" in line)
    difference, allowed = (float(part.split()[-1].rstrip(")")) for part in widths.split(",")[-2:])
    assert abs(difference) <= allowed
    # The near-edge stress amplitude, from both sources, within the asymptotes' accuracy.
    stress = [line for line in run.stdout.splitlines() if line.startswith("stress amplitude (")]
    assert len(stress) == 2 and all(line.endswith("within: True") for line in stress)
    # The command line's --verify answer, printed by the example itself.
    assert "Verification (reference solver):" in run.stdout
    assert "near-edge stress amplitude (state 2 - state 1" in run.stdout
    assert (tmp_path / "lab_recipe.png").stat().st_size > 10_000
