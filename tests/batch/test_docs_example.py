"""The worked example docs/examples/parameter_study.py runs on a 2-worker LocalCluster, prints
its solver check and saves its figure."""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

EXAMPLE = Path(__file__).resolve().parents[2] / "docs" / "examples" / "parameter_study.py"


@pytest.mark.slow
def test_the_parameter_study_sweeps_every_cycle_and_the_solver_confirms_the_asymptote(
    tmp_path: Path,
):
    pytest.importorskip("matplotlib")
    run = subprocess.run(
        [sys.executable, str(EXAMPLE)],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        env=dict(os.environ, PYTHONWARNINGS="error"),
        timeout=300,
        check=False,
    )
    assert run.returncode == 0, run.stderr
    assert "swept 40,000 cycles" in run.stdout
    worst = re.search(r"from the solver: ([\d.]+) elements", run.stdout)
    assert worst is not None and float(worst.group(1)) <= 1.0  # within the solver's bound
    assert (tmp_path / "parameter_study.png").stat().st_size > 10_000
