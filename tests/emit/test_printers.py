"""The printers carry every construct over: compiled and run on formulas beyond the records.

The records of today use a subset of what a derivation may emit; these synthetic formulas
(``synthetic.py``) cover the rest -- integer literals inside Max/Min, x**-1, rational powers
and constants, pi, sign, atan2, log1p/expm1, names differing only in case -- through the same
renderers as ``make generate``, compiled and compared with the NumPy module at 2,000 points.
A formula needing a special function no target has is left out of each, with a note.
"""

from __future__ import annotations

import numpy as np
import pytest

from asymslip.codegen.cse import reduce_formula
from asymslip.codegen.emit import format_source, render_module
from asymslip.codegen.languages import LANGUAGES

from .synthetic import FORMULAS, SPECIAL, sample
from .toolchains import (
    build_c_library,
    build_fortran_library,
    call_each_point,
    octave_evaluate,
    relative_difference,
)

DOCS = {"synthetic": "Synthetic formulas for the printer tests."}
COUNT = 2000


@pytest.fixture(scope="module")
def rendered(tmp_path_factory):
    """Each language's files for the synthetic formulas, written to a scratch folder."""
    reduced = [reduce_formula(formula) for formula in (*FORMULAS, SPECIAL)]
    folders = {}
    for language in LANGUAGES:
        folder = tmp_path_factory.mktemp(language.folder)
        result = language.render(reduced, DOCS)
        for name, text in result.files.items():
            (folder / name).write_text(text)
        folders[language.name] = (folder, result)
    return folders


@pytest.fixture(scope="module")
def reference():
    source = format_source(render_module("synthetic", DOCS["synthetic"], FORMULAS))
    namespace: dict = {}
    exec(compile(source, "synthetic.py", "exec"), namespace)
    points = sample(COUNT)
    return points, {f.name: namespace[f.name](*points.values()) for f in FORMULAS}


@pytest.mark.parametrize("language", [language.name for language in LANGUAGES])
def test_a_special_function_no_target_has_is_left_out_with_a_note(language, rendered):
    folder, result = rendered[language]
    assert result.left_out == {
        "needs_zeta": "needs zeta (the Riemann zeta function), which "
        + {"C": "C99's <math.h>", "Fortran": "Fortran 2008", "MATLAB/Octave": "MATLAB/Octave"}[
            language
        ]
        + " does not provide"
    }
    assert "needs_zeta" not in result.functions
    text = "\n".join(path.read_text() for path in sorted(folder.iterdir()))
    flat = " ".join(text.replace("`", "").split())
    assert "asymslip_needs_zeta: needs zeta (the Riemann zeta function)" in flat
    assert "function asymslip_needs_zeta" not in text and "double asymslip_needs_zeta(" not in text


def _assert_close(values, reference):
    for name, expected in reference.items():
        assert np.all(np.isfinite(expected)), name
        assert relative_difference(values[name], expected).max() <= 1e-13, name


def test_synthetic_formulas_compiled_as_c_equal_numpy(rendered, reference):
    folder, _ = rendered["C"]
    library = build_c_library(folder, folder / "asymslip_gen.c")
    points, expected = reference
    _assert_close({name: call_each_point(library, name, points) for name in expected}, expected)


def test_synthetic_formulas_compiled_as_fortran_equal_numpy(rendered, reference):
    folder, _ = rendered["Fortran"]
    library = build_fortran_library(folder, folder / "asymslip_gen.f90")
    points, expected = reference
    _assert_close({name: call_each_point(library, name, points) for name in expected}, expected)


def test_synthetic_formulas_run_by_octave_equal_numpy(rendered, reference, tmp_path):
    folder, _ = rendered["MATLAB/Octave"]
    points, expected = reference
    values = octave_evaluate({name: points for name in expected}, tmp_path, folder)
    _assert_close(values, expected)
