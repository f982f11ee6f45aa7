"""Reading traces: every data error is one line naming the file line (1-based) and the problem.

Each bad file below differs from a good one in one place, on a known line; the test asserts
that line number and the words of the problem.  The same data from Python name the array row.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from asymslip import InputError
from asymslip.calibration import Traces, calibrate, read_fe_report, read_traces
from tests.calibration.helpers import LAWS, REFERENCE_LOAD

LOADS = (90.0, 100.0, 110.0)
HERTZ = LAWS["hertz"]


def _x(nodes: int = 41) -> np.ndarray:
    a = float(HERTZ.half_width(REFERENCE_LOAD))
    return np.linspace(-1.5 * a, 1.5 * a, nodes)


def _rows(nodes: int = 41) -> list[list[str]]:
    """P, x, p rows of Hertz traces at LOADS (data rows only, as strings)."""
    x = _x(nodes)
    return [
        [repr(P), repr(float(xi)), repr(float(pi))]
        for P in LOADS
        for xi, pi in zip(x, HERTZ.pressure(x, P), strict=True)
    ]


def _write(
    tmp_path: Path, rows: list[list[str]], header: str = "P,x,p", comment: str = "# Hertz traces"
) -> Path:
    """File lines: 1 comment, 2 header, data from line 3 on (row k is line k + 3)."""
    path = tmp_path / "traces.csv"
    path.write_text("\n".join([comment, header, *(",".join(row) for row in rows)]) + "\n")
    return path


def _refused(path: Path, *words: str) -> str:
    with pytest.raises(InputError) as caught:
        calibrate(read_traces(path))
    message = str(caught.value)
    assert "\n" not in message
    for word in words:
        assert word in message, message
    return message


def test_a_good_file_reads_into_one_trace_per_load_and_calibrates(tmp_path):
    traces = read_traces(_write(tmp_path, _rows()))
    assert [trace.P for trace in traces.traces] == list(LOADS)
    assert all(trace.x.size == 41 for trace in traces.traces)
    assert traces.traces[1].rows[0] == 3 + 41  # the second load starts on line 44
    calibration = calibrate(traces)
    assert len(calibration.right) == len(calibration.left) == 3


def test_extra_columns_blank_lines_and_comments_are_ignored(tmp_path):
    rows = [[*row, "node-label"] for row in _rows()]
    path = _write(tmp_path, rows, header="P,x,p,label")
    path.write_text(path.read_text().replace("\n", "\n\n", 3))
    assert [t.P for t in read_traces(path).traces] == list(LOADS)


def test_one_load_only(tmp_path):
    rows = [row for row in _rows() if row[0] == repr(100.0)]
    _refused(_write(tmp_path, rows), "lines 3-43", "one load only")


def test_a_trace_with_no_contact(tmp_path):
    rows = _rows()
    for row in rows[41:82]:  # the second load, lines 44-84
        row[2] = "0.0"
    _refused(_write(tmp_path, rows), "lines 44-84", "P = 100", "no node is in contact")


def test_non_monotone_x_within_a_load(tmp_path):
    rows = _rows()
    rows[50][1], rows[51][1] = rows[51][1], rows[50][1]  # lines 53 and 54 swapped
    _refused(
        _write(tmp_path, rows),
        "line 54",
        "does not exceed",
        "line 53",
        "x must increase within a load",
    )


def test_a_repeated_x_within_a_load(tmp_path):
    rows = _rows()
    rows[60][1] = rows[59][1]
    _refused(_write(tmp_path, rows), "line 63", "does not exceed")


@pytest.mark.parametrize("value", ["nan", "NaN", "inf", "-inf"])
def test_a_non_finite_value(tmp_path, value):
    rows = _rows()
    rows[20][2] = value
    _refused(_write(tmp_path, rows), "line 23", "column p", "not a finite number")


def test_a_value_that_is_not_a_number(tmp_path):
    rows = _rows()
    rows[7][1] = "1.2.3"
    _refused(_write(tmp_path, rows), "line 10", "column x", "'1.2.3' is not a number")


def test_a_negative_pressure_beyond_the_noise(tmp_path):
    rows = _rows()
    rows[100][2] = repr(-0.2 * float(rows[102][2]))  # line 103: -20 % of a peak-ish pressure
    _refused(_write(tmp_path, rows), "line 103", "negative pressure beyond the noise")


def test_a_slightly_negative_pressure_at_an_open_node_is_accepted(tmp_path):
    rows = _rows()
    first_open = next(k for k in range(82, 123) if float(rows[k][2]) == 0.0)
    rows[first_open][2] = "-1e-6"  # penalty contact: a hair below zero where the gap opens
    read_traces(_write(tmp_path, rows))


def test_a_single_node_in_contact(tmp_path):
    rows = _rows()
    for k in range(0, 41):
        rows[k][2] = "0.0"
    rows[20][2] = "1.0"  # line 23: alone in contact
    _refused(_write(tmp_path, rows), "line 23", "the only node in contact")


def test_too_few_nodes_near_an_edge(tmp_path):
    """11 nodes across the contact: the message names the last node in contact of that load."""
    coarse = [
        [repr(P), repr(float(xi)), repr(float(pi))]
        for P in LOADS
        for xi, pi in zip(_x(17), HERTZ.pressure(_x(17), P), strict=True)
    ]
    last = max(k for k in range(17) if float(coarse[k][2]) > 0)  # first load, right edge
    _refused(
        _write(tmp_path, coarse), f"line {last + 3}", "right edge", "too few nodes near the edge"
    )


def test_a_contact_that_runs_off_the_trace(tmp_path):
    rows = [row for row in _rows() if float(row[1]) < 0.8 * float(HERTZ.half_width(90.0))]
    _refused(_write(tmp_path, rows), "right edge", "the edge is not in the data")


def test_a_header_without_the_pressure_column(tmp_path):
    message = _refused(_write(tmp_path, _rows(), header="P,x,CPRESS"), "line 2", "no column p")
    assert "found P, x, CPRESS" in message


def test_a_row_with_a_missing_field(tmp_path):
    rows = _rows()
    rows[30] = rows[30][:2]
    _refused(_write(tmp_path, rows), "line 33", "2 fields, the header has 3")


def test_a_non_positive_load(tmp_path):
    rows = _rows()
    rows[5][0] = "-90.0"
    _refused(_write(tmp_path, rows), "line 8", "the load must be > 0")


def test_a_side_column_must_say_right_or_left(tmp_path):
    rows = [[*row, "right"] for row in _rows()]
    rows[12][3] = "middle"
    _refused(_write(tmp_path, rows, header="P,x,p,side"), "line 15", "'middle'")


def test_a_side_column_gives_one_edge_per_trace(tmp_path):
    """Each load exported twice, once around each edge: both edges calibrate."""
    x = _x(81)
    rows = []
    for P in LOADS:
        p = HERTZ.pressure(x, P)
        rows += [
            [repr(P), repr(float(xi)), repr(float(pi)), "left"]
            for xi, pi in zip(x[x < 0], p[x < 0], strict=True)
        ]
        rows += [
            [repr(P), repr(float(xi)), repr(float(pi)), "right"]
            for xi, pi in zip(x[x > 0], p[x > 0], strict=True)
        ]
    calibration = calibrate(read_traces(_write(tmp_path, rows, header="P,x,p,side")))
    assert len(calibration.right) == len(calibration.left) == 3
    assert not calibration.symmetric_about_origin


def test_the_same_errors_from_arrays_name_the_row(tmp_path):
    x = np.tile(_x(), 3)
    P = np.repeat(LOADS, 41)
    p = np.concatenate([HERTZ.pressure(_x(), load) for load in LOADS])
    p[20] = np.nan
    with pytest.raises(InputError, match=r"arrays: row 20: column p: is not a finite number"):
        Traces.from_arrays(P, x, p)
    p[20] = 0.0
    x[50], x[51] = x[51], x[50]
    with pytest.raises(InputError, match=r"arrays: row 51 .*x must increase"):
        Traces.from_arrays(P, x, p)
    with pytest.raises(InputError, match="one length"):
        Traces.from_arrays(P[:-1], x, p)


# --- the FE report ---------------------------------------------------------------------------
def _report(x: np.ndarray, pressures: list[np.ndarray], header: str) -> str:
    """An XY-data report as Abaqus/CAE writes it: banner, a header, rows in E-notation."""
    lines = ["*" * 80, "", f"{header}", ""]
    for k, xi in enumerate(x):
        lines.append(
            "   " + "   ".join(f"{value:.6E}" for value in [xi] + [p[k] for p in pressures])
        )
    return "\n".join(lines) + "\n\n"


def test_an_fe_report_with_one_pressure_column_per_load(tmp_path):
    x = _x(61)
    pressures = [HERTZ.pressure(x, P) for P in LOADS]
    path = tmp_path / "cpress.rpt"
    path.write_text(
        _report(x, pressures, "        X        CPRESS-1        CPRESS-2        CPRESS-3")
    )
    traces = read_traces(path, loads=LOADS)
    assert [t.P for t in traces.traces] == list(LOADS)
    assert traces.traces[0].rows[0] == 5  # banner, blank, header, blank: data on line 5
    np.testing.assert_allclose(traces.traces[2].p, pressures[2], rtol=1e-6, atol=1e-12)
    fits = calibrate(traces).right
    assert abs(fits[1].x_edge - float(HERTZ.half_width(100.0))) <= fits[1].a_error


def test_an_fe_report_of_appended_blocks_names_its_loads_in_the_headers(tmp_path):
    x = _x(61)
    text = "".join(
        _report(x, [HERTZ.pressure(x, P)], f"        X        CPRESS  P={P:g}") for P in LOADS
    )
    path = tmp_path / "cpress.rpt"
    path.write_text(text)
    assert [t.P for t in read_fe_report(path).traces] == list(LOADS)


def test_an_fe_report_without_loads_is_refused_in_one_line(tmp_path):
    x = _x(61)
    path = tmp_path / "cpress.rpt"
    path.write_text(_report(x, [HERTZ.pressure(x, P) for P in LOADS], "   X   CPRESS"))
    with pytest.raises(InputError, match="line 5: the pressure columns do not say their load"):
        read_traces(path)
    with pytest.raises(InputError, match="3 pressure columns but 2 loads"):
        read_traces(path, loads=[1.0, 2.0])


# --- issue 17: the right cause for a BOM, semicolons, a load given twice; the load balance ----
def test_a_byte_order_mark_is_not_part_of_the_header(tmp_path):
    path = _write(tmp_path, _rows(), comment="# exported as CSV UTF-8")
    path.write_bytes(b"\xef\xbb\xbf" + path.read_bytes())
    assert [t.P for t in read_traces(path).traces] == list(LOADS)


def test_semicolons_between_fields_are_named_as_the_cause(tmp_path):
    path = _write(tmp_path, [[";".join(row)] for row in _rows()], header="P;x;p")
    with pytest.raises(InputError, match=r"the fields are separated by ';'"):
        read_traces(path)


def test_a_load_given_twice_in_two_places_is_named(tmp_path):
    rows = _rows()
    rows += rows[:41]  # P = 90 again after the other loads: lines 126-166
    _refused(_write(tmp_path, rows), "P = 90 is given twice", "lines 3-43", "from line 126")


def test_a_load_pasted_twice_in_a_row_is_named(tmp_path):
    rows = _rows()
    rows = rows[:41] + rows[:41] + rows[41:]  # P = 90 twice, one block after the other
    _refused(_write(tmp_path, rows), "line 44", "P = 90 is given twice", "start again")


def test_pressures_that_integrate_to_twice_the_load_are_refused(tmp_path):
    """(48) doubled: the integral of p dx is 2 P; the slip zone would be 13 times too narrow."""
    rows = [[P, x, repr(2 * float(p))] for P, x, p in _rows(121)]
    _refused(_write(tmp_path, rows), "the pressures integrate to 1.99", "times the load")


def test_a_load_balance_off_by_ten_percent_is_a_warning_in_the_calibration(tmp_path):
    rows = [[P, x, repr(1.1 * float(p))] for P, x, p in _rows(121)]
    calibration = calibrate(read_traces(_write(tmp_path, rows)))
    assert [round(ratio, 2) for _, ratio in calibration.load_balance] == [1.1, 1.1, 1.1]
    assert any("the pressures integrate to 1.1 times the load" in w for w in calibration.warnings)
    # The two edges' balance (AS6) sees it too, far beyond its error.
    assert any("the balance of the two edges (AS6) is 1.1" in w for w in calibration.warnings)
    assert calibration.to_dict()["warnings"] == list(calibration.warnings)


def test_consistent_traces_balance_to_one_within_a_thousandth(tmp_path):
    calibration = calibrate(read_traces(_write(tmp_path, _rows(121))))
    assert all(abs(ratio - 1) < 1e-3 for _, ratio in calibration.load_balance)
    assert not any("integrate" in w for w in calibration.warnings)


def test_a_smooth_trace_sampled_finely_keeps_every_point():
    """20,000 exact points of (48): none is taken for a path report's interpolated point."""
    from asymslip.calibration.edge_fit import nodal_points

    a = float(HERTZ.half_width(REFERENCE_LOAD))
    x = np.linspace(-1.5 * a, 1.5 * a, 20000)
    p = HERTZ.pressure(x, REFERENCE_LOAD)
    assert nodal_points(x, p)[p > 0].all()
