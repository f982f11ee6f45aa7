"""Abaqus XY reports as Abaqus/CAE writes them: the layouts of published report files.

No file below is copied: each is written here, with our own numbers (Hertz traces of
tests/calibration/helpers.py against the true distance along a path), in the layout of report
files written by Abaqus/CAE and published in public repositories:

* *engineering* number format, XY data names wrapped over two header lines (a piece of each
  column per line, ``X`` on the second), decimal points aligned in 19-character columns:
  github.com/nalet/bme.Finite-Element-Analysis-I, files
  ``assignment4/appendix/fillet_friction_02_finite_sliding_surface_to_surface.rpt`` and
  ``assignment5/model_data1_withfriction.rpt``;
* *scientific* number format, one-line titles right-aligned over 16-character columns, a row
  repeated exactly: github.com/lcharleux/argiope, file
  ``doc/abq/abqpostproc/workdir/history.rpt``.

Both begin with a blank line, have a blank line between the titles and the rows, and end with
four blank lines.  The reference for the numbers is the Hertz law's own pressure and half-width
((29), (31)) printed to the digits each format keeps.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from asymslip import InputError
from asymslip.calibration import calibrate, read_fe_report, read_traces
from tests.calibration.helpers import LAWS, REFERENCE_LOAD

HERTZ = LAWS["hertz"]
LOADS = (90.0, 110.0)
A = float(HERTZ.half_width(REFERENCE_LOAD))
#: A path of surface nodes from x = -1.5 a to 1.5 a, X its true distance (0 at its start).
X = np.linspace(0.0, 3.0 * A, 61)


def engineering(value: float) -> str:
    """Abaqus's engineering format: 6 significant digits, exponent a multiple of 3, trailing
    zeros dropped (``0.``, ``62.5E-03``, ``-3.54027E+03``, ``1.E-03``, ``-150.508``)."""
    if value == 0:
        return "-0." if math.copysign(1.0, value) < 0 else "0."
    exponent = 3 * math.floor(math.log10(abs(value)) / 3)
    mantissa = f"{value / 10.0**exponent:.6g}"
    if float(mantissa) >= 1000 or "e" in mantissa:  # rounding carried into the next power
        exponent += 3
        mantissa = f"{value / 10.0**exponent:.6g}"
    if "." not in mantissa:
        mantissa += "."
    mantissa = mantissa.rstrip("0") if "." in mantissa else mantissa
    return mantissa if exponent == 0 else f"{mantissa}E{exponent:+03d}"


def _decimal_point_at(text: str, column: int, line: str) -> str:
    """``line`` extended with ``text`` placed so that its decimal point is at ``column``."""
    start = column - text.index(".")
    return line + " " * (start - len(line)) + text


def nalet_layout(names: list[str], columns: list[np.ndarray]) -> str:
    """Engineering format, names wrapped at 17 characters over two lines, 19-wide columns."""
    width = 19 * (len(names) + 1) + 8
    first, second = " " * 19, " " * 18 + "X"
    for k, name in enumerate(names, start=1):
        head, rest = name[:17], name[17:]
        first = first.ljust(10 + 19 * k) + head
        second = second.ljust(10 + 19 * k + (17 - len(rest) + 1) // 2) + rest
    lines = ["", first.ljust(width), second.ljust(width), ""]
    for row in zip(X, *columns, strict=True):
        line = ""
        for k, value in enumerate(row):
            line = _decimal_point_at(engineering(float(value)), 17 + 19 * k, line)
        lines.append(line.ljust(width))
    return "\n".join(lines + ["", "", "", "", ""])


def argiope_layout(names: list[str], columns: list[np.ndarray], repeat: int) -> str:
    """Scientific format, one-line titles; the row ``repeat`` written twice."""
    title = "X".rjust(24) + "".join(name.rjust(16) for name in names)
    lines = ["", title, ""]
    for index, row in enumerate(zip(X, *columns, strict=True)):
        cells = [f"{value:.7E}" for value in row]
        line = cells[0].rjust(24) + "".join(cell.rjust(16) for cell in cells[1:])
        lines += [line, line] if index == repeat else [line]
    return "\n".join(lines + ["", "", "", "", ""])


def _pressures() -> list[np.ndarray]:
    return [HERTZ.pressure(X - 1.5 * A, P) for P in LOADS]


def _write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "abaqus.rpt"
    path.write_text(text)
    return path


def test_the_engineering_format_prints_as_abaqus_does():
    """The numbers of the published file, printed back by our formatter."""
    printed = [62.5e-3, -150.508, -312.5e-6, -1.03516e-3, -3540.27, 1e-3, -10225.5, 1.0]
    assert [engineering(v) for v in printed] == [
        "62.5E-03",
        "-150.508",
        "-312.5E-06",
        "-1.03516E-03",
        "-3.54027E+03",
        "1.E-03",
        "-10.2255E+03",
        "1.",
    ]
    assert engineering(-0.0) == "-0."


def test_wrapped_titles_and_engineering_numbers_give_each_load_its_trace(tmp_path):
    names = ["CPRESS along Path-1, P=90", "CPRESS along Path-1, P=110"]
    text = nalet_layout(names, _pressures())
    # The layout of the published file: titles split at 17 characters, X on the second line.
    assert text.splitlines()[1].split("  ")[-1].strip() == "CPRESS along Path"
    assert text.splitlines()[2].split()[:3] == ["X", "-1,", "P=90"]
    traces = read_fe_report(_write(tmp_path, text))
    assert [trace.P for trace in traces.traces] == list(LOADS)
    for trace, p in zip(traces.traces, _pressures(), strict=True):
        np.testing.assert_allclose(trace.x, X, rtol=5e-6)
        np.testing.assert_allclose(trace.p, p, rtol=5e-6, atol=1e-9)
    assert traces.traces[0].rows[0] == 5  # blank, two title lines, blank: the rows from line 5


def test_a_load_split_by_the_wrap_is_read_whole(tmp_path):
    """'CPRESS, path-1, P' over '=110': the title is joined before its load is read."""
    names = ["CPRESS, path-1, P=90", "CPRESS, path-1, P=110"]
    text = nalet_layout(names, _pressures())
    assert text.splitlines()[2].split() == ["X", "=90", "=110"]
    assert [trace.P for trace in read_fe_report(_write(tmp_path, text)).traces] == list(LOADS)


def test_titles_without_loads_take_the_given_ones(tmp_path):
    names = ["_CPRESS PI: BLOCK-1 N: 12", "_CPRESS PI: BLOCK-1 N: 13"]
    path = _write(tmp_path, nalet_layout(names, _pressures()))
    with pytest.raises(InputError, match="line 5: the pressure columns do not say their load"):
        read_traces(path)
    assert [trace.P for trace in read_traces(path, loads=list(LOADS)).traces] == list(LOADS)


def test_scientific_numbers_and_a_repeated_row_are_read_once_with_a_note(tmp_path):
    path = _write(tmp_path, argiope_layout(["CPRESS_n1", "CPRESS_n4"], _pressures(), 30))
    traces = read_traces(path, loads=list(LOADS))
    assert [trace.x.size for trace in traces.traces] == [61, 61]
    np.testing.assert_allclose(traces.traces[1].p, _pressures()[1], rtol=1e-7, atol=1e-12)
    assert any("1 row repeated exactly, read once" in note for note in traces.notes)


@pytest.mark.parametrize("layout", ["engineering", "scientific"])
def test_a_published_layout_calibrates_to_the_hertz_edge_within_its_error(tmp_path, layout):
    """Six printed digits (engineering) or eight (scientific): the edge and L_I of (29), (31)."""
    names = ["CPRESS P=90", "CPRESS P=110"]
    if layout == "engineering":
        text = nalet_layout(names, _pressures())
    else:
        text = argiope_layout(names, _pressures(), 30)
    calibration = calibrate(read_fe_report(_write(tmp_path, text)))
    for right, left in zip(calibration.right, calibration.left, strict=True):
        a = float(HERTZ.half_width(right.P))
        assert abs(right.x_edge - (1.5 * A + a)) <= right.a_error
        assert abs(left.x_edge - (1.5 * A - a)) <= left.a_error
        assert abs(right.L_I - float(HERTZ.normal_multiplier(right.P))) <= right.L_I_error


def test_the_same_x_twice_with_different_pressures_is_refused_naming_the_line(tmp_path):
    """A history's step boundary (the published file repeats X = 300.E-03 with new values) is
    not a path: one line naming where x stops increasing."""
    text = argiope_layout(["CPRESS_n1", "CPRESS_n4"], _pressures(), 30)
    lines = text.splitlines()
    lines[34] = lines[34][:24] + f"{_pressures()[0][30] * 1.01:.7E}".rjust(16) + lines[34][40:]
    with pytest.raises(InputError) as refused:
        read_traces(_write(tmp_path, "\n".join(lines)), loads=list(LOADS))
    assert "\n" not in str(refused.value)
    assert "line 35" in str(refused.value), refused.value
