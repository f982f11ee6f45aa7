"""Pressure traces from finite-element results: CalculiX .frd and .dat, and mesh files.

The rules, each reported in the traces' notes (what ``asymslip calibrate`` prints and saves):

* **Steps.**  Each step's last increment that has contact pressures is one state.  Its load
  is taken from the file where the file has it -- the total reaction force of a node set
  (``*NODE FILE, NSET=...`` RF in the .frd, ``*NODE PRINT, NSET=..., TOTALS=ONLY`` RF in the
  .dat), its component along the contact normal, in magnitude -- and otherwise from
  ``loads``, one per step in order.  Steps whose loads agree to 1e-6 are one load: the last of
  them is used (a cyclic analysis returns to its states).  The steps used are listed.
* **Nodes.**  The contact nodes are every node with contact results in a used step; a node
  without results in a step is open there (p = 0).  A planar model's expanded nodes (CalculiX
  writes two per node) are averaged; a pair that disagrees by more than 1e-3 of the peak
  pressure is named.  Positions along the surface come from the nodes' coordinates
  (:mod:`.surface`).
* **Negative pressures** (penalty contact pulls a little at open nodes next to the edge) are
  clipped to 0 and counted, when they are within ``NEGATIVE_CLIP`` of the step's peak pressure;
  beyond that they are refused as for any trace.
* **Penetration.**  Where the file gives the opening (COPEN), a node that carries pressure
  while open, or is overclosed by more than a tenth of the node spacing, is named: the penalty
  method's overclosure moves the edge by about that much.

Runtime needs NumPy only; mesh files need meshio (the ``fe`` extra).

Examples
--------
Two steps of a cyclic run at the same load and one at another, on four nodes along y = 0:

>>> import numpy as np
>>> nodes = np.array([1, 2, 3, 4])
>>> coordinates = {n: np.array([float(n), 0.0]) for n in (1, 2, 3, 4)}
>>> def state(label, load, p):
...     return FeState(label, load, nodes, np.array(p), np.full(4, np.nan))
>>> found = assemble("run.frd", [state("step 2", 10.0, [0, 1, 2, -1e-4]),
...                              state("step 3", 20.0, [1, 2, 3, 0]),
...                              state("step 4", 10.0, [0, 1, 2, -1e-4])], coordinates, None)
>>> found.loads.tolist(), found.labels
([10.0, 20.0], ('step 4', 'step 3'))
>>> for note in found.notes:
...     print(note)
steps used: step 4 (P = 10), step 3 (P = 20)
loads from the file's reaction forces (their component along the normal)
P = 10 at step 2, step 4: the last, step 4, used
1 negative pressures (down to 5e-05 of the peak) at nodes beyond the edge clipped to 0
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from ..errors import InputError
from .frd import FrdFile, read_frd
from .surface import surface_positions

FloatArray = NDArray[np.float64]
IntArray = NDArray[np.int64]

#: Loads that agree to this relative tolerance are one load.
SAME_LOAD = 1e-6
#: Negative pressures down to this fraction of the step's peak pressure are clipped to 0.
NEGATIVE_CLIP = 0.01
#: Expanded node pairs that differ by more than this fraction of the peak pressure are named.
PAIR_MISMATCH = 1e-3
#: Overclosure beyond this fraction of the node spacing is named.
PENETRATION = 0.1


@dataclass(frozen=True)
class FeState:
    """One step's contact results: model nodes, pressure, opening (NaN where not given)."""

    label: str
    load: float | None
    nodes: IntArray
    pressure: FloatArray
    opening: FloatArray
    mismatch: list[str] = field(default_factory=list)


@dataclass(frozen=True)
class FeTraces:
    """Everything the traces need: loads, node positions and pressures per used state."""

    source: str
    loads: FloatArray
    labels: tuple[str, ...]
    nodes: IntArray
    x: FloatArray
    pressure: FloatArray  # (states, nodes), clipped
    notes: tuple[str, ...]


def _pairs(nodes: IntArray, values: FloatArray) -> tuple[IntArray, FloatArray, FloatArray]:
    """Average the values of repeated nodes: (unique nodes, means, largest spread)."""
    unique, inverse = np.unique(nodes, return_inverse=True)
    counts = np.bincount(inverse).astype(np.float64)
    means = np.stack(
        [np.bincount(inverse, weights=values[:, j]) / counts for j in range(values.shape[1])],
        axis=1,
    )
    spread = np.zeros_like(means)
    np.maximum.at(spread, inverse, np.abs(values - means[inverse]))
    return unique, means, spread


def assemble(
    source: str,
    states: Sequence[FeState],
    coordinates: dict[int, FloatArray],
    loads: Sequence[float] | None,
) -> FeTraces:
    """Apply the module's rules to the states of one file."""
    if not states:
        raise InputError("traces", f"{source}: no contact pressures (CPRESS) in any step")
    given = [state.load for state in states]
    notes: list[str] = []
    if all(load is not None for load in given):
        if loads is not None:
            raise InputError(
                "loads",
                f"{source} gives each step's load (the reaction force of a node set): "
                "--loads is for a file without them",
            )
        values = [float(load) for load in given]  # type: ignore[arg-type]
        notes.append("loads from the file's reaction forces (their component along the normal)")
    else:
        if loads is None:
            raise InputError(
                "traces",
                f"{source}: the file does not give the loads of its {len(states)} steps with "
                f"contact pressures ({', '.join(s.label for s in states)}): give them with "
                "--loads, one per step in this order",
            )
        loads = list(loads)
        if len(loads) != len(states):
            raise InputError(
                "loads",
                f"{len(loads)} loads given for {len(states)} steps with contact pressures "
                f"in {source} ({', '.join(s.label for s in states)}): give one per step",
            )
        values = [float(load) for load in loads]
    used: dict[int, int] = {}  # group -> index of the state used
    groups: list[list[int]] = []
    for k, load in enumerate(values):
        for g, members in enumerate(groups):
            if abs(values[members[0]] - load) <= SAME_LOAD * max(abs(load), 1e-300):
                members.append(k)
                used[g] = k
                break
        else:
            groups.append([k])
            used[len(groups) - 1] = k
    for members in groups:
        if len(members) > 1:
            labels = ", ".join(states[k].label for k in members)
            notes.append(
                f"P = {values[members[0]]:.6g} at {labels}: the last, "
                f"{states[members[-1]].label}, used"
            )
    chosen = sorted((used[g] for g in range(len(groups))), key=lambda k: values[k])
    nodes = np.unique(np.concatenate([states[k].nodes for k in chosen]))
    points = np.array([coordinates[int(n)] for n in nodes])
    along = surface_positions(points)
    if along.curved:
        notes.append("the contact surface is curved: x is the arc length along its nodes")
    order = np.argsort(along.x)
    nodes, x = nodes[order], along.x[order]
    spacing = float(np.median(np.diff(x))) if x.size > 1 else 0.0
    pressure = np.zeros((len(chosen), nodes.size))
    clipped, deepest = 0, 0.0
    for row, k in enumerate(chosen):
        state = states[k]
        where = np.searchsorted(nodes, state.nodes)
        p = np.zeros(nodes.size)
        p[where] = state.pressure
        peak = float(p.max()) if p.size else 0.0
        negative = (p < 0) & (p >= -NEGATIVE_CLIP * peak)
        if negative.any():
            clipped += int(negative.sum())
            deepest = max(deepest, float(-p[negative].min() / peak))
            p[negative] = 0.0
        pressure[row] = p
        notes += state.mismatch
        opening = np.full(nodes.size, np.nan)
        opening[where] = state.opening
        open_loaded = np.flatnonzero((p > 0) & (opening > 0))
        if open_loaded.size:
            node = int(nodes[open_loaded[0]])
            notes.append(
                f"{state.label}: {open_loaded.size} node(s) carry pressure while open "
                f"(first: node {node}, x = {x[open_loaded[0]]:.6g}): the file's pressure and "
                "opening disagree there"
            )
        deep = np.flatnonzero(opening < -PENETRATION * spacing)
        if deep.size:
            k_deep = int(deep[np.argmin(opening[deep])])
            notes.append(
                f"{state.label}: penetration {-opening[k_deep]:.3g} at node {int(nodes[k_deep])} "
                f"(x = {x[k_deep]:.6g}), more than a tenth of the node spacing: the penalty "
                "contact's edge is uncertain by about that much"
            )
    if clipped:
        notes.append(
            f"{clipped} negative pressures (down to {deepest:.2g} of the peak) at nodes "
            "beyond the edge clipped to 0"
        )
    notes.insert(
        0,
        "steps used: " + ", ".join(f"{states[k].label} (P = {values[k]:.6g})" for k in chosen),
    )
    return FeTraces(
        source=source,
        loads=np.array([values[k] for k in chosen]),
        labels=tuple(states[k].label for k in chosen),
        nodes=nodes,
        x=x,
        pressure=pressure,
        notes=tuple(notes),
    )


# --- CalculiX .frd -------------------------------------------------------------------------------
def _state_of(frd: FrdFile, block_index: int, label: str, load: float | None) -> FeState:
    block = frd.blocks[block_index]
    if "CPRESS" not in block.components:
        raise InputError("traces", f"{frd.source}: line {block.line}: no CPRESS in {block.name}")
    columns = [block.column("CPRESS")]
    columns.append(
        block.column("COPEN") if "COPEN" in block.components else np.full(block.nodes.size, np.nan)
    )
    nodes, means, spread = _pairs(frd.model_node(block.nodes), np.column_stack(columns))
    mismatch = []
    peak = float(np.max(means[:, 0])) if means.size else 0.0
    if peak > 0 and np.max(spread[:, 0]) > PAIR_MISMATCH * peak:
        k = int(np.argmax(spread[:, 0]))
        mismatch.append(
            f"{label}: the two expanded nodes of node {int(nodes[k])} differ in pressure by "
            f"{2 * spread[k, 0]:.3g} ({2 * spread[k, 0] / peak:.2g} of the peak): averaged"
        )
    return FeState(label, load, nodes, means[:, 0], means[:, 1], mismatch)


def frd_traces(path: str | Path, loads: Sequence[float] | None) -> FeTraces:
    """The traces of a CalculiX .frd: CPRESS of each step's last increment (module rules)."""
    frd = read_frd(path)
    last: dict[int, int] = {}
    for index, block in enumerate(frd.blocks):
        if block.name == "CONTACT":
            if block.step not in last or block.increment >= frd.blocks[last[block.step]].increment:
                last[block.step] = index
    forces: dict[tuple[int, int], FloatArray] = {}
    for block in frd.named("FORC"):
        forces[(block.step, block.increment)] = block.values[:, :2].sum(axis=0)
    states = []
    for step, index in sorted(last.items()):
        block = frd.blocks[index]
        states.append((step, index, forces.get((step, block.increment))))
    if not states:
        raise InputError(
            "traces",
            f"{frd.source}: no CONTACT results (ask CalculiX for them with *CONTACT FILE, CSTR)",
        )
    coordinates = {int(n): xyz for n, xyz in zip(frd.node_numbers, frd.coordinates, strict=True)}
    built = [_state_of(frd, index, f"step {step}", None) for step, index, _ in states]
    # The normal of the surface is needed for the loads: from the contact nodes themselves.
    nodes = np.unique(np.concatenate([state.nodes for state in built]))
    normal = surface_positions(np.array([coordinates[int(n)] for n in nodes])).normal
    with_loads = []
    for state, (_, _, force) in zip(built, states, strict=True):
        load = None if force is None else float(abs(force @ normal))
        with_loads.append(
            FeState(state.label, load, state.nodes, state.pressure, state.opening, state.mismatch)
        )
    return assemble(frd.source, with_loads, {k: v[:2] for k, v in coordinates.items()}, loads)


# --- CalculiX .dat -------------------------------------------------------------------------------
_TOTAL = re.compile(r"total force \(fx,fy,fz\) for set (\S+) and time\s+(\S+)")
_STRESS = re.compile(r"contact stress \(slave node,press,tang1,tang2\).*time\s+(\S+)")
_OPENING = re.compile(
    r"relative contact displacement \(slave node,normal,tang1,tang2\).*time\s+(\S+)"
)


def _dat_tables(
    path: Path,
) -> tuple[dict[float, FloatArray], dict[float, FloatArray], dict[float, FloatArray]]:
    """(totals, stresses, openings) by time; stresses/openings: rows (node, value, ...)."""
    try:
        lines = path.read_text(errors="strict").splitlines()
    except (OSError, UnicodeDecodeError) as error:
        raise InputError("traces", f"cannot read {path}: {error}") from None
    totals: dict[float, FloatArray] = {}
    stresses: dict[float, FloatArray] = {}
    openings: dict[float, FloatArray] = {}
    k = 0
    while k < len(lines):
        line = lines[k]
        for pattern, table in ((_TOTAL, totals), (_STRESS, stresses), (_OPENING, openings)):
            found = pattern.search(line)
            if not found:
                continue
            time = float(found.group(found.lastindex or 0))
            rows = []
            k += 1
            while k < len(lines) and not lines[k].strip():
                k += 1
            while k < len(lines) and lines[k].strip():
                try:
                    rows.append([float(v) for v in lines[k].split()])
                except ValueError:
                    raise InputError(
                        "traces", f"{path}: line {k + 1}: a row that is not numbers"
                    ) from None
                k += 1
            values = np.array(rows, dtype=np.float64)
            table[time] = values[0] if table is totals else values  # a total is one row
            break
        else:
            k += 1
    return totals, stresses, openings


def _inp_nodes(path: Path) -> tuple[dict[int, FloatArray], bool]:
    """*NODE coordinates of a CalculiX/Abaqus deck and whether its elements are planar."""
    nodes: dict[int, FloatArray] = {}
    planar_types, other = False, False
    reading = False
    for number, line in enumerate(path.read_text(errors="replace").splitlines(), start=1):
        stripped = line.strip()
        if not stripped or stripped.startswith("**"):
            continue
        if stripped.startswith("*"):
            keyword = stripped.split(",")[0].upper()
            reading = keyword == "*NODE"
            if keyword == "*INCLUDE":
                raise InputError(
                    "traces", f"{path}: line {number}: *INCLUDE is not followed: give the .frd"
                )
            if keyword == "*ELEMENT":
                kind = re.search(r"TYPE\s*=\s*(\w+)", stripped.upper())
                if kind and kind.group(1).startswith(("CPE", "CPS", "CAX")):
                    planar_types = True
                else:
                    other = True
            continue
        if reading:
            fields = [f for f in stripped.split(",") if f.strip()]
            try:
                nodes[int(fields[0])] = np.array([float(v) for v in fields[1:3]] + [0.0])[:3]
            except (ValueError, IndexError):
                raise InputError(
                    "traces", f"{path}: line {number}: a *NODE line that is not numbers"
                ) from None
    return nodes, planar_types and not other


def dat_traces(path: str | Path, loads: Sequence[float] | None) -> FeTraces:
    """The traces of a CalculiX .dat (``*CONTACT PRINT``): one state per output time.

    The .dat has no coordinates: they are read from the job's .frd beside it, or its .inp.
    """
    path = Path(path)
    totals, stresses, openings = _dat_tables(path)
    if not stresses:
        raise InputError(
            "traces",
            f"{path}: no contact stresses (ask CalculiX for them with *CONTACT PRINT, CSTR)",
        )
    frd_path, inp_path = path.with_suffix(".frd"), path.with_suffix(".inp")
    if frd_path.is_file():
        frd = read_frd(frd_path)
        coordinates = {
            int(n): xyz for n, xyz in zip(frd.node_numbers, frd.coordinates, strict=True)
        }
        planar = frd.planar
    elif inp_path.is_file():
        coordinates, planar = _inp_nodes(inp_path)
    else:
        raise InputError(
            "traces",
            f"{path}: a .dat holds no node coordinates: the job's {frd_path.name} or "
            f"{inp_path.name} must be beside it",
        )
    largest = max(coordinates)
    times = sorted(stresses)
    per_set = {}
    if totals:
        names = sorted(set(_set_names(path)))
        if len(names) > 1:
            raise InputError(
                "traces",
                f"{path}: totals of several node sets ({', '.join(names)}) are printed: "
                "keep only the one whose reaction force is the normal load",
            )
        per_set = totals
    rows: list[tuple[str, FloatArray | None, IntArray, FloatArray, FloatArray]] = []
    model_nodes_all = []
    for time in times:
        table = stresses[time]
        nodes = table[:, 0].astype(np.int64)
        if planar:
            nodes = np.where(nodes > largest, (nodes - largest - 1) // 3 + 1, nodes)
        opening_table = openings.get(time)
        opening = np.full(nodes.size, np.nan)
        if opening_table is not None and opening_table.shape[0] == table.shape[0]:
            opening = opening_table[:, 1]
        unique, means, _ = _pairs(nodes, np.column_stack([table[:, 1], opening]))
        model_nodes_all.append(unique)
        rows.append((f"time {time:g}", per_set.get(time), unique, means[:, 0], means[:, 1]))
    nodes = np.unique(np.concatenate(model_nodes_all))
    missing = [int(n) for n in nodes if int(n) not in coordinates]
    if missing:
        raise InputError("traces", f"{path}: contact node {missing[0]} has no coordinates")
    normal = surface_positions(np.array([coordinates[int(n)][:2] for n in nodes])).normal
    built = [
        FeState(label, None if total is None else float(abs(total[:2] @ normal)), n, p, o)
        for label, total, n, p, o in rows
    ]
    return assemble(str(path), built, {k: v[:2] for k, v in coordinates.items()}, loads)


def _set_names(path: Path) -> list[str]:
    return [found.group(1) for found in _TOTAL.finditer(path.read_text(errors="replace"))]
