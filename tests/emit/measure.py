"""Print the largest relative difference from NumPy per language and function.

``python -m tests.emit.measure`` (after ``make toolchains``): the figures the README and the
report quote, from the same points and builds as the tests.
"""

from __future__ import annotations

import tempfile
import time
from pathlib import Path

import numpy as np

import asymslip_gen

from .conftest import FUNCTIONS, POINTS_PER_FUNCTION
from .domains import sample
from .toolchains import (
    build_c_library,
    build_fortran_library,
    call_each_point,
    octave_evaluate,
    relative_difference,
)


def main() -> None:
    points = {
        name: sample(name, args, POINTS_PER_FUNCTION) for name, (args, _) in FUNCTIONS.items()
    }
    reference = {
        name: np.asarray(getattr(asymslip_gen, name)(*p.values()), dtype=np.float64)
        for name, p in points.items()
    }
    with tempfile.TemporaryDirectory() as scratch:
        folder = Path(scratch)
        start = time.perf_counter()
        c = build_c_library(folder)
        built_c = time.perf_counter()
        f = build_fortran_library(folder)
        built_f = time.perf_counter()
        values = {
            "C": {name: call_each_point(c, name, p) for name, p in points.items()},
            "Fortran": {name: call_each_point(f, name, p) for name, p in points.items()},
        }
        called = time.perf_counter()
        values["MATLAB/Octave"] = octave_evaluate(points, folder)
        octave = time.perf_counter()
    print(
        f"build C {built_c - start:.2f} s, build Fortran {built_f - built_c:.2f} s, "
        f"ctypes calls {called - built_f:.2f} s, Octave {octave - called:.2f} s"
    )
    for language, results in values.items():
        worst = {
            name: float(relative_difference(results[name], reference[name]).max())
            for name in results
        }
        name = max(worst, key=worst.get)
        exact = sum(value == 0 for value in worst.values())
        print(
            f"{language}: largest relative difference {worst[name]:.2e} ({name}); "
            f"{exact} of {len(worst)} functions bit-identical at every point"
        )
        for item in sorted(worst, key=worst.get, reverse=True)[:5]:
            print(f"    {item}: {worst[item]:.2e}")


if __name__ == "__main__":
    main()
