"""The worked example docs/examples/law_to_crack_site.py runs, prints its numbers and saves its
figure: the asymptote within its stated accuracy of the solver everywhere it maps."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

EXAMPLE = Path(__file__).resolve().parents[2] / "docs" / "examples" / "law_to_crack_site.py"


@pytest.mark.slow
def test_the_law_to_crack_site_example_runs_and_agrees_with_the_solver(tmp_path: Path):
    pytest.importorskip("matplotlib")
    environment = dict(os.environ, PYTHONWARNINGS="error")
    run = subprocess.run(
        [sys.executable, str(EXAMPLE)],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        env=environment,
        timeout=300,
        check=False,
    )
    assert run.returncode == 0, run.stderr
    assert "within the stated accuracy at 100% of the points" in run.stdout
    assert "right      swt            peak" in run.stdout
    assert (tmp_path / "law_to_crack_site.png").stat().st_size > 10_000
