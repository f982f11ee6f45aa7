"""Build and run the generated C, Fortran and MATLAB/Octave code for the comparison tests.

The tools come from the project's own set-up (``make toolchains``, which runs
``.ci/install-toolchains``: gfortran and Octave from Debian's packages where missing).  A
missing tool skips the tests that need it, so that ``make test`` passes on a machine with only
Python (the README's promise); the root ``tests/conftest.py`` sums the skips up in one line
saying how to run them.  Where the tools are required -- ``make test-languages`` and CI set
``ASYMSLIP_REQUIRE_TOOLCHAINS=1`` -- a missing tool is a failure, never a skip.
"""

from __future__ import annotations

import ctypes
import os
import shutil
import subprocess
from collections.abc import Mapping, Sequence
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
GENERATED = ROOT / "generated"
C_SOURCE = GENERATED / "c" / "asymslip_gen.c"
FORTRAN_SOURCE = GENERATED / "fortran" / "asymslip_gen.f90"
MATLAB_FOLDER = GENERATED / "matlab"

#: Strict builds: any warning is an error.  FP contraction is off so that no compiler fuses
#: a*b + c into one rounding that NumPy does not do.
C_FLAGS = ["-std=c99", "-pedantic", "-Wall", "-Wextra", "-Werror", "-O2", "-ffp-contract=off"]
#: The two warnings switched off are by design: a formula may ignore an argument (the
#: functions keep the NumPy argument list, and Fortran has no "(void)x" idiom), and NumPy's
#: sign(x) is 0 exactly at x == 0, which gfortran flags as a real equality test.
FORTRAN_FLAGS = [
    "-std=f2008",
    "-Wall",
    "-Wextra",
    "-Werror",
    "-Wno-unused-dummy-argument",
    "-Wno-compare-reals",
    "-O2",
    "-ffp-contract=off",
]


#: Set to 1 where the compiled-language tests must run (CI, ``make test-languages``).
REQUIRED = "ASYMSLIP_REQUIRE_TOOLCHAINS"
#: The start of every skip reason this module gives (the summary line counts them by it).
MISSING = "toolchain missing:"


def require(tool: str) -> str:
    """Path of ``tool``; skip where it is missing, fail where the toolchains are required."""
    found = shutil.which(tool)
    if found:
        return found
    if os.environ.get(REQUIRED) == "1":
        pytest.fail(f"{tool} is not installed and {REQUIRED}=1: run `make toolchains` first")
    pytest.skip(f"{MISSING} {tool} (`make test-languages` installs it and runs these tests)")


def run(command: Sequence[str], cwd: Path | None = None, timeout: float = 300) -> str:
    completed = subprocess.run(
        list(command), cwd=cwd, capture_output=True, text=True, timeout=timeout
    )
    assert completed.returncode == 0, (
        f"{' '.join(map(str, command))} failed:\n{completed.stdout}\n{completed.stderr}"
    )
    return completed.stdout


def build_c_library(folder: Path, source: Path = C_SOURCE) -> ctypes.CDLL:
    compiler = require("gcc")
    library = folder / "libasymslip_gen_c.so"
    run([compiler, *C_FLAGS, "-fPIC", "-shared", str(source), "-o", str(library), "-lm"])
    return ctypes.CDLL(str(library))


def build_fortran_library(folder: Path, source: Path = FORTRAN_SOURCE) -> ctypes.CDLL:
    compiler = require("gfortran")
    library = folder / "libasymslip_gen_f.so"
    # -J: the .mod file goes to the scratch folder, not the working directory.
    run(
        [
            compiler,
            *FORTRAN_FLAGS,
            "-fPIC",
            "-shared",
            "-J",
            str(folder),
            str(source),
            "-o",
            str(library),
        ]
    )
    return ctypes.CDLL(str(library))


def call_each_point(
    library: ctypes.CDLL, name: str, points: Mapping[str, np.ndarray]
) -> np.ndarray:
    """``asymslip_<name>`` of the library at every point, one call per point (scalar API)."""
    function = getattr(library, f"asymslip_{name}")
    function.restype = ctypes.c_double
    function.argtypes = [ctypes.c_double] * len(points)
    columns = [column.tolist() for column in points.values()]
    return np.array([function(*row) for row in zip(*columns, strict=True)], dtype=np.float64)


def octave_evaluate(
    cases: Mapping[str, Mapping[str, np.ndarray]], folder: Path, functions: Path = MATLAB_FOLDER
) -> dict[str, np.ndarray]:
    """Every function of ``cases`` evaluated by Octave on whole columns (vectorised), at once.

    The inputs and outputs cross as raw little-endian doubles, so no digit is lost in text.
    """
    octave = require("octave-cli")
    names = list(cases)
    for name, points in cases.items():
        np.column_stack(list(points.values())).astype("<f8").T.tofile(folder / f"{name}.in")
    script = folder / "evaluate_all.m"
    listed = ", ".join(f"'{name}'" for name in names)
    counts = " ".join(str(len(cases[name])) for name in names)
    rows = " ".join(str(len(next(iter(cases[name].values())))) for name in names)
    script.write_text(
        f"addpath('{functions}');\n"
        f"names = {{{listed}}};\nnargs = [{counts}];\nrows = [{rows}];\n"
        "for i = 1:numel(names)\n"
        "  fid = fopen([names{i} '.in'], 'r', 'ieee-le');\n"
        "  X = fread(fid, [rows(i), nargs(i)], 'double');\n"
        "  fclose(fid);\n"
        "  args = num2cell(X, 1);\n"
        "  y = feval(['asymslip_' names{i}], args{:});\n"
        "  if ~isequal(size(y), [rows(i), 1])\n"
        "    error('%s returned size %s', names{i}, mat2str(size(y)));\n"
        "  end\n"
        "  fid = fopen([names{i} '.out'], 'w', 'ieee-le');\n"
        "  fwrite(fid, y, 'double');\n"
        "  fclose(fid);\n"
        "end\n"
    )
    run(
        [octave, "--no-gui", "--norc", "--quiet", "--no-window-system", str(script.name)],
        cwd=folder,
    )
    return {name: np.fromfile(folder / f"{name}.out", dtype="<f8") for name in names}


def relative_difference(values: np.ndarray, reference: np.ndarray) -> np.ndarray:
    """|values - reference| / |reference|, 0 where both are the same number (zeros included)."""
    same = values == reference
    scale = np.where(reference == 0, 1.0, np.abs(reference))
    return np.where(same, 0.0, np.abs(values - reference) / scale)
