"""Session fixtures: each language built (or run) once, on the same sampled points."""

from __future__ import annotations

import json

import numpy as np
import pytest

import asymslip_gen

from .domains import sample
from .toolchains import (
    GENERATED,
    build_c_library,
    build_fortran_library,
    call_each_point,
    octave_evaluate,
)

POINTS_PER_FUNCTION = 1000
RECORDS = json.loads((GENERATED / "asymslip_gen" / "formulas.json").read_text(encoding="utf-8"))
#: Every emitted function with its argument names and the languages it is emitted in.
FUNCTIONS = {
    record["name"]: ([arg["name"] for arg in record["args"]], record["languages"])
    for record in RECORDS["formulas"]
}


@pytest.fixture(scope="session")
def points():
    """Function name -> its sampled arguments (the same points for every language)."""
    return {
        name: sample(name, arguments, POINTS_PER_FUNCTION)
        for name, (arguments, _) in FUNCTIONS.items()
    }


@pytest.fixture(scope="session")
def numpy_values(points):
    return {
        name: np.asarray(getattr(asymslip_gen, name)(*args.values()), dtype=np.float64)
        for name, args in points.items()
    }


def _in(language):
    return [name for name, (_, languages) in FUNCTIONS.items() if language in languages]


@pytest.fixture(scope="session")
def c_values(points, tmp_path_factory):
    library = build_c_library(tmp_path_factory.mktemp("c"))
    return {name: call_each_point(library, name, points[name]) for name in _in("C")}


@pytest.fixture(scope="session")
def fortran_values(points, tmp_path_factory):
    library = build_fortran_library(tmp_path_factory.mktemp("fortran"))
    return {name: call_each_point(library, name, points[name]) for name in _in("Fortran")}


@pytest.fixture(scope="session")
def octave_values(points, tmp_path_factory):
    folder = tmp_path_factory.mktemp("octave")
    return octave_evaluate({name: points[name] for name in _in("MATLAB/Octave")}, folder)
