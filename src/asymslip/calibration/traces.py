"""Contact-pressure traces: nodal pressures p at positions x, one trace per load P.

Read from a long-format CSV (``read_traces``), from the tabular report a finite-element package
writes for a surface path (``read_fe_report``: e.g. an Abaqus ``.rpt`` of XY data, one pressure
column per load), or given from Python (:meth:`Traces.from_arrays`).  Every data error is one
:class:`~asymslip.errors.InputError` naming where the bad value is -- the file line (1-based)
for a file, the row (0-based) for arrays -- and what is wrong with it.

Long format
-----------
A header row naming the columns ``P``, ``x`` and ``p`` (any order, other columns ignored), then
one row per node per load.  Within a load the rows must come in increasing x (the order an FE
path is written in).  An optional ``side`` column (``right`` or ``left``) marks traces that hold
only the part of the contact next to that edge, when only one edge was exported; without it
each load's trace spans the whole contact and gives both edges.  Blank lines and lines starting
with ``#`` are skipped.

Runtime needs NumPy only.

Examples
--------
>>> import numpy as np
>>> from asymslip.calibration.traces import Traces
>>> x = np.linspace(-2, 2, 9)
>>> p = np.concatenate([np.maximum(1 - x**2, 0), np.maximum(2 - x**2, 0)])
>>> traces = Traces.from_arrays(P=np.repeat([1.0, 2.0], 9), x=np.tile(x, 2), p=p)
>>> [(trace.P, trace.x.size, int(trace.rows[0])) for trace in traces.traces]
[(1.0, 9, 0), (2.0, 9, 9)]
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..errors import InputError
from .noise import pressure_noise
from .xy_report import parse_xy_report

FloatArray = NDArray[np.float64]
Side = Literal["right", "left"]
SIDES: tuple[Side, Side] = ("right", "left")

#: The columns a long-format file must have.
COLUMNS = ("P", "x", "p")
#: A pressure below -max(this many noise standard deviations, NEGATIVE_FRACTION of the peak
#: pressure of its load) is refused: finite-element results may dip slightly below zero at
#: open nodes, but not by more than their scatter.
NEGATIVE_NOISE = 5.0
NEGATIVE_FRACTION = 0.01
#: Fewer nodes than this in one trace cannot hold an edge with nodes on both sides.
MIN_NODES = 3


@dataclass(frozen=True)
class Trace:
    """The nodal pressures of one load (one edge's part of the contact when ``side`` is set).

    ``rows`` gives, for each node, the file line (1-based) it came from, or its row in the
    arrays (0-based); ``source`` names the file or says ``arrays``.
    """

    P: float
    x: FloatArray
    p: FloatArray
    side: Side | None
    rows: NDArray[np.intp]
    source: str
    label: str = ""
    unit: str = ""

    @property
    def from_file(self) -> bool:
        return self.source != ARRAYS

    def where(self, node: int | None = None) -> str:
        """``traces.csv: line 17`` (or ``lines 2-41`` for the whole trace), the array rows, or
        for an FE result its step and node (``run.frd: step 7: node 57``)."""
        word = self.unit or ("line" if self.from_file else "row")
        if node is None:
            span = f"{word}s {self.rows.min()}-{self.rows.max()}"
        else:
            span = f"{word} {self.rows[node]}"
        label = f"{self.label}: " if self.label else ""
        return f"{self.source}: {label}{span} (P = {self.P:.6g}{self._side_text()})"

    def _side_text(self) -> str:
        return f", side {self.side}" if self.side else ""

    def sides(self) -> tuple[Side, ...]:
        """The edges this trace holds."""
        return (self.side,) if self.side else SIDES


ARRAYS = "arrays"


@dataclass(frozen=True)
class Traces:
    """All traces of one data set, ordered by load (then side)."""

    traces: tuple[Trace, ...]
    source: str
    #: What the reader did to the data (FE results: the steps used, clipped pressures ...).
    notes: tuple[str, ...] = ()

    @property
    def loads(self) -> FloatArray:
        """The distinct loads, increasing."""
        return np.unique([trace.P for trace in self.traces])

    def __len__(self) -> int:
        return len(self.traces)

    @classmethod
    def from_arrays(
        cls,
        P: ArrayLike,
        x: ArrayLike,
        p: ArrayLike,
        side: Sequence[str] | None = None,
    ) -> Traces:
        """Long-format data from Python: one entry per node per load (rows as in the file).

        Parameters
        ----------
        P, x, p
            Loads, node positions and pressures, 1-D and of one length.
        side
            Optional ``"right"``/``"left"`` per row, when a trace holds only one edge.
        """
        columns = {}
        for name, values in (("P", P), ("x", x), ("p", p)):
            try:
                array = np.asarray(values, dtype=np.float64)
            except (TypeError, ValueError):
                raise InputError("traces", f"{name} must be an array of numbers") from None
            if array.ndim != 1:
                raise InputError(
                    "traces", f"{name} must be 1-D (one entry per node per load)", array.shape
                )
            columns[name] = array
        sizes = {name: array.size for name, array in columns.items()}
        if side is not None:
            side = list(side)
            sizes["side"] = len(side)
        if len(set(sizes.values())) != 1:
            raise InputError(
                "traces", f"P, x, p{', side' if side else ''} must have one length", sizes
            )
        rows = np.arange(columns["P"].size)
        return _assemble(columns["P"], columns["x"], columns["p"], side, rows, ARRAYS)


# --- reading -------------------------------------------------------------------------------------
#: Suffixes read as CalculiX results; everything meshio reads is tried as a mesh file.
CALCULIX_RESULTS = (".frd",)
CALCULIX_PRINTOUT = (".dat",)
MESH_SUFFIXES = (".vtu", ".vtk", ".xdmf", ".xmf", ".msh", ".med", ".h5m", ".mdpa", ".ply")


def read_traces(
    path: str | Path, *, loads: Sequence[float] | None = None, field: str | None = None
) -> Traces:
    """Read pressure traces from a long-format CSV, an FE report, or FE results.

    By suffix: ``.frd`` CalculiX results and ``.dat`` its printout (:mod:`.fe_traces`), a mesh
    file meshio reads (``.vtu``, ``.vtk``, ``.xdmf``, ...; :mod:`.mesh_file`, the pressure
    field named ``field``, CPRESS by default); otherwise text: a file whose first data line
    has commas is read as CSV (columns ``P, x, p``, optional ``side``), one with spaces as a
    whitespace-separated FE report (:func:`read_fe_report`), which needs ``loads`` unless its
    column headers name them.
    """
    path = Path(path)
    suffix = path.suffix.lower()
    if field is not None and suffix not in MESH_SUFFIXES:
        raise InputError(
            "field", f"is for mesh files ({', '.join(MESH_SUFFIXES)}), not {path.name}"
        )
    if suffix in CALCULIX_RESULTS + CALCULIX_PRINTOUT + MESH_SUFFIXES:
        from . import fe_traces, mesh_file  # the FE readers load only for FE files

        if not path.is_file():
            raise InputError("traces", f"cannot read {path}: no such file")
        if suffix in CALCULIX_RESULTS:
            found = fe_traces.frd_traces(path, loads)
        elif suffix in CALCULIX_PRINTOUT:
            found = fe_traces.dat_traces(path, loads)
        else:
            found = mesh_file.mesh_traces(path, loads, field)
        return _from_fe(found)
    text = _read_text(path)
    first = next(
        (
            line
            for line in text.splitlines()
            if line.strip() and not line.lstrip().startswith(("#", "*"))
        ),
        "",
    )
    if ";" in first and "," not in first:
        raise InputError(
            "traces",
            f"{path}: the fields are separated by ';' (a spreadsheet in a locale with decimal "
            "commas writes that): write the CSV with ',' between fields and '.' in numbers",
        )
    if "," in first:
        if loads is not None:  # given for nothing would let a wrong guess pass unnoticed
            raise InputError(
                "loads",
                f"{path} is a CSV whose column P gives the loads: "
                "--loads is for an FE report without them",
            )
        return _read_csv(path, text)
    return _read_report(path, text, loads)


def _from_fe(found: object) -> Traces:
    """Traces of an FE result (:class:`.fe_traces.FeTraces`): one per used step."""
    from .fe_traces import FeTraces

    assert isinstance(found, FeTraces)
    count = found.x.size
    P = np.repeat(found.loads, count)
    x = np.tile(found.x, found.loads.size)
    p = found.pressure.ravel()
    rows = np.tile(found.nodes, found.loads.size)
    traces = _assemble(P, x, p, None, rows, found.source, unit="node", labels=found.labels)
    return Traces(traces.traces, traces.source, found.notes)


def read_fe_report(path: str | Path, loads: Sequence[float] | None = None) -> Traces:
    """Read the XY report an FE package writes for a surface path (Abaqus: Report > XY).

    The first column is the position along the path (X: a coordinate or the true distance),
    each further column the contact pressure (CPRESS) at one load, in one table or several
    (see :mod:`asymslip.calibration.xy_report` for the layout Abaqus writes: headers, blank
    lines, ``NoValue`` cells, repeated rows, appended reports).  The loads are given in the
    order of the pressure columns, or read from headers that contain ``P=<number>``.
    """
    path = Path(path)
    return _read_report(path, _read_text(path), loads)


def _read_text(path: Path) -> str:
    try:
        # A spreadsheet's "CSV UTF-8" starts with a byte-order mark: not part of the header.
        return path.read_text(encoding="utf-8-sig")
    except UnicodeDecodeError as error:
        raise InputError(
            "traces", f"{path}: not UTF-8 text (byte {error.start}): save it as UTF-8 CSV"
        ) from None
    except OSError as error:
        raise InputError("traces", f"cannot read {path}: {error}") from None


def _read_csv(path: Path, text: str) -> Traces:
    header: list[str] | None = None
    index: dict[str, int] = {}
    values: dict[str, list[float]] = {name: [] for name in COLUMNS}
    sides: list[str] | None = None
    rows: list[int] = []
    for number, line in enumerate(text.splitlines(), start=1):
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        fields = [field.strip() for field in line.split(",")]
        if header is None:
            header = fields
            missing = [name for name in COLUMNS if name not in header]
            if missing:
                raise InputError(
                    "traces",
                    f"{path}: line {number}: the header has no column {' or '.join(missing)} "
                    f"(it must name the columns P, x and p; found {', '.join(header)})",
                )
            index = {name: header.index(name) for name in COLUMNS}
            if "side" in header:
                index["side"] = header.index("side")
                sides = []
            continue
        if len(fields) != len(header):
            raise InputError(
                "traces",
                f"{path}: line {number}: {len(fields)} fields, the header has {len(header)}",
            )
        for name in COLUMNS:
            field = fields[index[name]]
            try:
                value = float(field)
            except ValueError:
                raise InputError(
                    "traces", f"{path}: line {number}: column {name}: {field!r} is not a number"
                ) from None
            values[name].append(value)
        if sides is not None:
            sides.append(fields[index["side"]])
        rows.append(number)
    if header is None:
        raise InputError("traces", f"{path}: no header row (columns P, x and p)")
    if not rows:
        raise InputError("traces", f"{path}: no data rows after the header")
    return _assemble(
        np.array(values["P"]),
        np.array(values["x"]),
        np.array(values["p"]),
        sides,
        np.array(rows),
        str(path),
    )


def _read_report(path: Path, text: str, loads: Sequence[float] | None) -> Traces:
    """An XY report's tables (:mod:`.xy_report`), each pressure column one load's trace."""
    table = parse_xy_report(str(path), text, loads)
    traces = _assemble(table.P, table.x, table.p, None, table.rows, str(path))
    return Traces(traces.traces, traces.source, table.notes)


# --- checks --------------------------------------------------------------------------------------
def _assemble(
    P: FloatArray,
    x: FloatArray,
    p: FloatArray,
    side: Sequence[str] | None,
    rows: NDArray[np.intp],
    source: str,
    *,
    unit: str = "",
    labels: Sequence[str] = (),
) -> Traces:
    """Group rows into traces by (P, side), checking every value where it stands.

    ``unit`` and ``labels`` name the rows of an FE result (``node`` and each load's step).
    """
    word = unit or ("line" if source != ARRAYS else "row")

    def at(row: int) -> str:
        return f"{source}: {word} {rows[row]}"

    for name, column in (("P", P), ("x", x), ("p", p)):
        bad = ~np.isfinite(column)
        if bad.any():
            row = int(np.flatnonzero(bad)[0])
            raise InputError(
                "traces",
                f"{at(row)}: column {name}: is not a finite number",  # none printed
            )
    if (P <= 0).any():
        row = int(np.flatnonzero(P <= 0)[0])
        raise InputError("traces", f"{at(row)}: P = {P[row]:.6g}: the load must be > 0")
    if side is not None:
        for row, value in enumerate(side):
            if value not in SIDES:
                raise InputError("traces", f"{at(row)}: side {value!r}: must be 'right' or 'left'")
    groups: dict[tuple[float, str | None], list[int]] = {}
    for row in range(P.size):
        groups.setdefault((float(P[row]), side[row] if side is not None else None), []).append(row)
    label_of = dict(zip(np.unique(P).tolist(), labels, strict=False)) if labels else {}
    traces = []
    for (load, which), members in sorted(
        groups.items(), key=lambda item: (item[0][0], str(item[0][1]))
    ):
        members_ = np.array(members)
        _check_given_once(load, which, members_, x, rows, source, word)
        trace = Trace(
            P=load,
            x=x[members_],
            p=p[members_],
            side=which,  # type: ignore[arg-type]
            rows=rows[members_],
            source=source,
            label=label_of.get(load, ""),
            unit=unit,
        )
        _check_trace(trace)
        traces.append(trace)
    if len({trace.P for trace in traces}) < 2:
        only = traces[0]
        raise InputError(
            "traces",
            f"{only.where()}: the data hold one load only; the contact "
            "law a(P) needs traces at two or more loads",
        )
    return Traces(tuple(traces), source)


def _check_given_once(
    load: float,
    side: str | None,
    members: NDArray[np.intp],
    x: FloatArray,
    rows: NDArray[np.intp],
    source: str,
    word: str,
) -> None:
    """Refuse a load whose rows come twice: in two separate runs, or restarting in x."""
    what = f"P = {load:.6g}" + (f", side {side}" if side else "")
    # Arrays from Python may come in any order of rows; a file's rows are in file order.
    gaps = np.flatnonzero(np.diff(members) > 1) if source != ARRAYS else np.array([], int)
    if gaps.size:
        first_end, second_start = members[gaps[0]], members[gaps[0] + 1]
        raise InputError(
            "traces",
            f"{source}: {what} is given twice: {word}s {rows[members[0]]}-{rows[first_end]} and "
            f"again from {word} {rows[second_start]}: give each load once",
        )
    xs = x[members]
    restart = np.flatnonzero((np.diff(xs) <= 0) & (xs[1:] <= xs[0]))
    if restart.size:
        again = members[restart[0] + 1]
        raise InputError(
            "traces",
            f"{source}: {word} {rows[again]}: {what} is given twice: its nodes start again "
            f"at x = {x[again]:.6g} after {word} {rows[again - 1]}: give each load once",
        )


def _check_trace(trace: Trace) -> None:
    x, p = trace.x, trace.p
    if x.size < MIN_NODES:
        raise InputError(
            "traces", f"{trace.where()}: {x.size} nodes; a trace needs at least {MIN_NODES}"
        )
    step = np.diff(x)
    if not (step > 0).all():
        node = int(np.flatnonzero(~(step > 0))[0]) + 1
        raise InputError(
            "traces",
            f"{trace.where(node)}: x = {x[node]:.6g} does not exceed x = {x[node - 1]:.6g} of the "
            f"node before it ({_word(trace)} {trace.rows[node - 1]}): x must increase within a "
            "load (write each load's nodes in order along the surface)",
        )
    peak = float(p.max())
    if not peak > 0:
        raise InputError("traces", f"{trace.where()}: no node is in contact (no positive pressure)")
    limit = max(NEGATIVE_NOISE * pressure_noise(x, p), NEGATIVE_FRACTION * peak)
    if (p < -limit).any():
        node = int(np.argmin(p))
        raise InputError(
            "traces",
            f"{trace.where(node)}: p = {p[node]:.6g} at x = {x[node]:.6g}: a negative pressure "
            f"beyond the noise of this trace (more negative than -{limit:.3g}); a contact "
            "pressure cannot pull",
        )
    if int(np.sum(p > 0)) == 1:
        node = int(np.argmax(p))
        raise InputError(
            "traces",
            f"{trace.where(node)}: the only node in contact; an edge "
            "needs several nodes in contact next to it",
        )


def _word(trace: Trace) -> str:
    return "line" if trace.from_file else "row"
