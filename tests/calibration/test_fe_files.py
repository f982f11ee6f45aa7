"""Finite-element result files read by calibrate: CalculiX .frd and .dat, and mesh files.

The files are written here in each format, by hand, from the Hertz pressure (48) (R = E* = 1)
on a row of surface nodes of a planar model: CalculiX writes a planar model's contact results
at its expanded nodes (two per node, numbered N + 3 (n - 1) + 1 and + 3 after the largest
node N), the base's reaction force in a FORC block, a slight tension (-1e-5 of the peak) at
open nodes next to the contact, and a cyclic run returns to the same loads.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from asymslip import InputError
from asymslip.calibration import Traces, calibrate, read_traces
from tests.calibration.helpers import LAWS

HERTZ = LAWS["hertz"]
#: Steps of a cyclic run: (step, load); 100 and 110 come back.
STEPS = ((2, 90.0), (3, 100.0), (4, 110.0), (5, 100.0), (6, 110.0))
SURFACE = np.linspace(-18.0, 18.0, 145)  # nodes 1..145 on y = 0 (spacing 0.25)
LARGEST_NODE = 400  # the model's other nodes (the bodies) are 146..400


def _expanded(node: int) -> tuple[int, int]:
    base = LARGEST_NODE + 3 * (node - 1)
    return base + 1, base + 3


def _pressure(P: float) -> np.ndarray:
    p = HERTZ.pressure(SURFACE, P)
    a = float(HERTZ.half_width(P))
    near = (p == 0) & (np.abs(SURFACE) < a + 1.0)  # open nodes with contact elements
    return np.where(near, -1e-5 * p.max(), p)


def _frd(path: Path, with_forces: bool = True, steps=STEPS) -> Path:
    e = "{:12.5E}".format
    lines = ["    1C", "    1UUSER"]
    lines.append(f"    2C{LARGEST_NODE:30d}{'':37}1")
    for node in range(1, LARGEST_NODE + 1):
        x = SURFACE[node - 1] if node <= SURFACE.size else 0.1 * node
        y = 0.0 if node <= SURFACE.size else -1.0
        lines.append(f" -1{node:10d}{e(x)}{e(y)}{e(0.0)}")
    lines += [
        " -3",
        f"    3C{1:30d}{'':37}1",
        " -1         1    9    0    1",
        " -2         1         2       147       146",
        " -3",
    ]
    for number, (step, P) in enumerate(steps, start=1):
        if with_forces:
            lines += [
                f"    1PSTEP{number:25d}{4:12d}{step:12d}",
                f"  100CL  1{number:02d}{float(step):12.9f}{3:12d}{'':20} 0{number:5d}{'':10} 1",
                " -4  FORC        4    1",
                " -5  F1          1    2    1    0",
                " -5  F2          1    2    2    0",
                " -5  F3          1    2    3    0",
                " -5  ALL         1    2    0    0    1ALL",
            ]
            for node, share in ((146, 0.25), (147, 0.5), (148, 0.25)):
                lines.append(f" -1{node:10d}{e(0.0)}{e(share * P)}{e(0.0)}")
            lines.append(" -3")
        p = _pressure(P)
        listed = np.flatnonzero(np.abs(SURFACE) < float(HERTZ.half_width(P)) + 1.0)
        lines += [
            f"    1PSTEP{number:25d}{4:12d}{step:12d}",
            f"  100CL  2{number:02d}{float(step):12.9f}{2 * listed.size:12d}{'':20} 0"
            f"{number:5d}{'':10} 1",
            " -4  CONTACT     6    1",
            *(
                f" -5  {name:8}    1    4    1    1"
                for name in ("COPEN", "CSLIP1", "CSLIP2", "CPRESS", "CSHEAR1", "CSHEAR2")
            ),
        ]
        for k in listed:
            opening = -p[k] / 1e6 if p[k] > 0 else 1e-4
            for expanded in _expanded(int(k) + 1):
                values = (opening, 0.0, 0.0, p[k], 0.0, 0.0)
                lines.append(f" -1{expanded:10d}" + "".join(e(v) for v in values))
        lines.append(" -3")
    lines.append("9999")
    path.write_text("\n".join(lines) + "\n")
    return path


def test_an_frd_gives_one_trace_per_load_with_loads_from_the_reaction_forces(tmp_path):
    traces = read_traces(_frd(tmp_path / "run.frd"))
    assert [trace.P for trace in traces.traces] == [90.0, 100.0, 110.0]
    assert [trace.label for trace in traces.traces] == ["step 2", "step 5", "step 6"]
    assert traces.notes[0] == "steps used: step 2 (P = 90), step 5 (P = 100), step 6 (P = 110)"
    assert "P = 100 at step 3, step 5: the last, step 5, used" in traces.notes
    # The nodes with contact results in any used step; open ones at 0 where not listed.
    listed = SURFACE[np.abs(SURFACE) < float(HERTZ.half_width(110.0)) + 1.0]
    np.testing.assert_array_equal(traces.traces[0].x, listed)


def test_negative_pressures_beyond_the_edge_are_clipped_and_counted(tmp_path):
    traces = read_traces(_frd(tmp_path / "run.frd"))
    expected = sum(int(np.sum(_pressure(P) < 0)) for _, P in ((2, 90.0), (5, 100.0), (6, 110.0)))
    assert expected > 0
    assert any(note.startswith(f"{expected} negative pressures") for note in traces.notes)
    assert all((trace.p >= 0).all() for trace in traces.traces)


def test_an_frd_calibrates_to_hertz(tmp_path):
    calibration = calibrate(read_traces(_frd(tmp_path / "run.frd")), origin=0.0)
    for fit in calibration.right + calibration.left:
        assert abs(fit.position(0.0) - float(HERTZ.half_width(fit.P))) <= fit.a_error
        assert abs(fit.L_I - float(HERTZ.normal_multiplier(fit.P))) <= fit.L_I_error
    assert calibration.notes[0].startswith("steps used: step 2")
    assert [P for P, _ in calibration.load_balance] == [90.0, 100.0, 110.0]


def _long(traces: Traces) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The traces as the long-format columns P, x, p of a CSV (no FE node marks)."""
    return (
        np.concatenate([np.full(t.x.size, t.P) for t in traces.traces]),
        np.concatenate([t.x for t in traces.traces]),
        np.concatenate([t.p for t in traces.traces]),
    )


def test_fits_to_fe_nodes_state_the_fe_allowance_and_carry_it(tmp_path):
    """The rule for an FE solution's own error is printed with the result, and each a_error of
    the fits holds at least 0.17 element at its edge (the nodes' spacing there) where the fit
    stands between two nodes, and 0.1 element where it was moved to the last node in contact."""
    calibration = calibrate(read_traces(_frd(tmp_path / "run.frd")), origin=0.0)
    assert any(
        note.startswith("FE nodal pressures:")
        and "0.17 element at the edge in quadrature" in note
        and "the larger of the distance moved and 0.1 element" in note
        for note in calibration.notes
    )
    traces = read_traces(_frd(tmp_path / "run.frd"))
    for trace in traces.traces:
        fit = next(f for f in calibration.right if f.P == trace.P)
        beyond = trace.x[trace.x > fit.x_edge][0]
        inside = trace.x[trace.x <= fit.x_edge][-1]
        allowance = 0.1 if inside == fit.x_edge else 0.17
        assert fit.a_error >= allowance * (beyond - inside) * (1 - 1e-12)
    csv = calibrate(Traces.from_arrays(*_long(traces)), origin=0.0)
    assert not any(note.startswith("FE nodal pressures:") for note in csv.notes)


def test_an_frd_without_forces_takes_one_load_per_step_from_loads(tmp_path):
    path = _frd(tmp_path / "run.frd", with_forces=False)
    with pytest.raises(InputError, match=r"does not give the loads of its 5 steps .*--loads"):
        read_traces(path)
    with pytest.raises(InputError, match=r"loads: 2 loads given for 5 steps"):
        read_traces(path, loads=[90.0, 100.0])
    traces = read_traces(path, loads=[P for _, P in STEPS])
    assert [trace.P for trace in traces.traces] == [90.0, 100.0, 110.0]


def test_loads_given_for_an_frd_that_has_them_are_refused(tmp_path):
    with pytest.raises(InputError, match=r"loads: .* gives each step's load"):
        read_traces(_frd(tmp_path / "run.frd"), loads=[1.0, 2.0, 3.0, 4.0, 5.0])


def _dat(path: Path) -> Path:
    lines = []
    for step, P in STEPS:
        time = f"{float(step):.7E}"
        lines += [
            "",
            f" total force (fx,fy,fz) for set BASE and time  {time}",
            "",
            f"        0.000000E+00  {P:.6E}  0.000000E+00",
            "",
        ]
        p = _pressure(P)
        listed = np.flatnonzero(np.abs(SURFACE) < float(HERTZ.half_width(P)) + 1.0)
        lines += [
            f" contact stress (slave node,press,tang1,tang2) for all contact elements "
            f"and time {time}",
            "",
        ]
        for k in listed:
            for expanded in _expanded(int(k) + 1):
                lines.append(f"      {expanded}  {p[k]:.6E}  0.000000E+00  0.000000E+00")
    path.write_text("\n".join(lines) + "\n")
    return path


def test_a_dat_is_read_with_the_coordinates_of_its_frd(tmp_path):
    _frd(tmp_path / "run.frd")
    traces = read_traces(_dat(tmp_path / "run.dat"))
    assert [trace.P for trace in traces.traces] == [90.0, 100.0, 110.0]
    frd = read_traces(tmp_path / "run.frd")
    for from_dat, from_frd in zip(traces.traces, frd.traces, strict=True):
        np.testing.assert_array_equal(from_dat.x, from_frd.x)
        np.testing.assert_allclose(from_dat.p, from_frd.p, rtol=2e-5, atol=1e-9)  # 6 digits each


def test_a_dat_without_its_frd_or_inp_is_refused_naming_them(tmp_path):
    with pytest.raises(InputError, match=r"run.frd or run.inp must be beside it"):
        read_traces(_dat(tmp_path / "run.dat"))


def test_a_dat_with_an_inp_beside_it(tmp_path):
    nodes = "\n".join(f"{k + 1}, {float(x)!r}, 0.0" for k, x in enumerate(SURFACE))
    extra = "\n".join(f"{n}, {0.1 * n!r}, -1.0" for n in range(SURFACE.size + 1, LARGEST_NODE + 1))
    (tmp_path / "run.inp").write_text(
        f"*NODE\n{nodes}\n{extra}\n*ELEMENT, TYPE=CPE4, ELSET=B\n1, 1, 2, 147, 146\n"
    )
    traces = read_traces(_dat(tmp_path / "run.dat"))
    listed = SURFACE[np.abs(SURFACE) < float(HERTZ.half_width(110.0)) + 1.0]
    np.testing.assert_array_equal(traces.traces[0].x, listed)


def test_a_mesh_file_with_a_named_pressure_field(tmp_path):
    meshio = pytest.importorskip("meshio")
    points = np.column_stack([SURFACE, np.zeros_like(SURFACE), np.zeros_like(SURFACE)])
    cells = [("line", np.column_stack([np.arange(SURFACE.size - 1), np.arange(1, SURFACE.size)]))]
    fields = {f"CPRESS_{k}": _pressure(P) for k, (_, P) in enumerate(STEPS[:3])}
    fields["S_MISES"] = np.ones(SURFACE.size)
    path = tmp_path / "surface.vtu"
    meshio.write(path, meshio.Mesh(points, cells, point_data=fields))
    with pytest.raises(InputError, match=r"does not give the loads of its 3 steps"):
        read_traces(path)
    traces = read_traces(path, loads=[90.0, 100.0, 110.0])
    assert [trace.P for trace in traces.traces] == [90.0, 100.0, 110.0]
    calibration = calibrate(traces, origin=0.0)
    fit = calibration.right[1]
    assert abs(fit.x_edge - float(HERTZ.half_width(100.0))) <= fit.a_error
    with pytest.raises(InputError, match=r"field: .* no point-data field named 'CP'"):
        read_traces(path, loads=[1.0], field="CP")


def test_field_is_for_mesh_files_only(tmp_path):
    path = tmp_path / "traces.csv"
    path.write_text("P,x,p\n")
    with pytest.raises(InputError, match=r"field: is for mesh files"):
        read_traces(path, field="CPRESS")


def test_the_frd_reader_refuses_a_file_that_is_not_one(tmp_path):
    path = tmp_path / "run.frd"
    path.write_text("hello\n")
    with pytest.raises(InputError, match=r"run.frd: line 1: not a CalculiX .frd file"):
        read_traces(path)
    assert math.isfinite(1.0)
