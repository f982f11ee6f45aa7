"""The documented C, Fortran and MATLAB/Octave examples, compiled and run exactly as printed.

The code blocks and their build commands are read from the section "The formulas in C, Fortran
and MATLAB/Octave" of the generated-functions guide (``docs/guide/generated.md``, moved there
from the README), written to a scratch folder beside a link to ``generated/``, built with the
page's own command and run; their output is the NumPy value.
"""

from __future__ import annotations

import re
import subprocess

import numpy as np
import pytest

import asymslip_gen

from .toolchains import GENERATED, ROOT, require

SECTION = "## The formulas in C, Fortran and MATLAB/Octave"


def _blocks(language):
    text = (ROOT / "docs" / "guide" / "generated.md").read_text()
    section = text[text.index(SECTION) :]
    section = section[: section.find("\n## ", 1) if "\n## " in section[1:] else len(section)]
    return re.findall(rf"```{language}\n(.*?)```", section, re.DOTALL)


def _fig5(mu):
    P1, P2 = 100.0, 105.0
    a1 = asymslip_gen.hertz_half_width(P1, 1.0, 1.0)
    a2 = asymslip_gen.hertz_half_width(P2, 1.0, 1.0)
    L1 = asymslip_gen.hertz_normal_edge_multiplier(P1, 1.0, 1.0)
    L2 = asymslip_gen.hertz_normal_edge_multiplier(P2, 1.0, 1.0)
    return asymslip_gen.stick_boundary_proportional(np.asarray(mu), 0.2, 0.0, a1, a2, L1, L2)


def _build_and_run(tmp_path, source_name, language, command_index):
    (tmp_path / "generated").symlink_to(GENERATED)
    (code,) = _blocks(language)
    (tmp_path / source_name).write_text(code)
    command = _blocks("sh")[command_index].strip()
    completed = subprocess.run(
        ["bash", "-c", command], cwd=tmp_path, capture_output=True, text=True, timeout=300
    )
    assert completed.returncode == 0, completed.stderr
    return completed.stdout


def test_the_readme_c_example_compiles_and_prints_numpys_stick_boundary(tmp_path):
    require("gcc")
    output = _build_and_run(tmp_path, "fig5.c", "c", 0)
    value = float(re.fullmatch(r"b = (\S+)\n", output).group(1))
    assert value == pytest.approx(float(_fig5(0.1)), rel=1e-15)


def test_the_readme_fortran_example_compiles_and_prints_numpys_stick_boundaries(tmp_path):
    require("gfortran")
    output = _build_and_run(tmp_path, "fig5.f90", "fortran", 1)
    values = np.array([float(word) for word in output.split()])
    np.testing.assert_allclose(values, _fig5([0.1, 0.05, 0.02]), rtol=1e-15)


def test_the_readme_matlab_example_runs_in_octave_and_gives_numpys_stick_boundaries(tmp_path):
    octave = require("octave-cli")
    (tmp_path / "generated").symlink_to(GENERATED)
    (code,) = _blocks("matlab")
    script = code + "fprintf('%.17g\\n', b);\n"
    completed = subprocess.run(
        [octave, "--no-gui", "--norc", "--quiet", "--eval", script],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert completed.returncode == 0, completed.stderr
    values = np.array([float(line) for line in completed.stdout.splitlines()[-3:]])
    np.testing.assert_allclose(values, _fig5([0.1, 0.05, 0.02]), rtol=1e-15)
