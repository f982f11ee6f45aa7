"""CalculiX results (``.frd``, ASCII): nodes, elements' kinds and the nodal result blocks.

Only what the calibration and the FE model need is read: the node block (``2C``), whether the
elements are planar (``3C``: triangles and quadrilaterals with every node at z = 0 -- a
plane-strain, plane-stress or axisymmetric model) and every nodal result block (``100CL``)
with its step, increment and time (``1PSTEP``), name (``-4``), components (``-5``) and values
(``-1``).  Each problem is one :class:`~asymslip.errors.InputError` naming the file line.

CalculiX expands a planar model into one layer of 3-D elements and writes the contact results
at the expanded nodes, which the node block does not list: expanded node m of a model whose
largest node number is N belongs to node (m - N - 1) // 3 + 1 (three expanded nodes per node,
numbered in order after N).  :meth:`FrdFile.model_node` applies that rule.

Runtime needs NumPy only.

Examples
--------
A file with two nodes and one result block (the fixed columns CalculiX writes):

>>> import tempfile, pathlib
>>> e = "{:12.5E}".format
>>> text = chr(10).join(["    1C", f"    2C{2:30d}{'':37}1",
...     f" -1{1:10d}{e(0.0)}{e(0.0)}{e(0.0)}", f" -1{2:10d}{e(1.0)}{e(0.0)}{e(0.0)}", " -3",
...     f"    1PSTEP{1:25d}{1:12d}{3:12d}", f"  100CL  101{3.0:12.9f}{2:12d}{'':20} 0    1",
...     " -4  CONTACT     2    1", " -5  COPEN       1    4    1    1",
...     " -5  CPRESS      1    4    1    2",
...     f" -1{1:10d}{e(-1e-6)}{e(5.0)}", f" -1{2:10d}{e(1e-4)}{e(0.0)}", " -3", "9999"])
>>> path = pathlib.Path(tempfile.mkdtemp()) / "run.frd"
>>> _ = path.write_text(text + chr(10))
>>> frd = read_frd(path)
>>> block = frd.named("CONTACT")[0]
>>> block.step, block.increment, block.components, block.column("CPRESS").tolist()
(3, 1, ('COPEN', 'CPRESS'), [5.0, 0.0])
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from ..errors import InputError

FloatArray = NDArray[np.float64]
IntArray = NDArray[np.int64]

#: frd element types of surface-like (planar) elements: tr3, tr6, qu4, qu8.
PLANAR_TYPES = frozenset({7, 8, 9, 10})
#: Nodes expanded by CalculiX per node of a planar element.
EXPANDED_PER_NODE = 3


@dataclass(frozen=True)
class ResultBlock:
    """One nodal result block: ``values[k]`` holds the components at node ``nodes[k]``."""

    name: str
    step: int
    increment: int
    time: float
    components: tuple[str, ...]
    nodes: IntArray
    values: FloatArray
    line: int

    def column(self, component: str) -> FloatArray:
        """The values of one component (e.g. ``CPRESS``)."""
        return self.values[:, self.components.index(component)]


@dataclass(frozen=True)
class FrdFile:
    """The parts of an .frd file the calibration needs."""

    source: str
    node_numbers: IntArray
    coordinates: FloatArray
    planar: bool
    blocks: tuple[ResultBlock, ...]

    def model_node(self, numbers: IntArray) -> IntArray:
        """The model node of each result node (expanded nodes of a planar model mapped back)."""
        numbers = np.asarray(numbers, dtype=np.int64)
        largest = int(self.node_numbers.max())
        if self.planar:
            expanded = numbers > largest
            numbers = np.where(expanded, (numbers - largest - 1) // EXPANDED_PER_NODE + 1, numbers)
        return numbers

    def positions(self, numbers: IntArray) -> FloatArray:
        """(x, y, z) of model nodes; a node the file does not define is refused."""
        order = np.argsort(self.node_numbers)
        sorted_numbers = self.node_numbers[order]
        where = np.searchsorted(sorted_numbers, numbers)
        where = np.clip(where, 0, sorted_numbers.size - 1)
        missing = sorted_numbers[where] != numbers
        if missing.any():
            raise InputError(
                "traces",
                f"{self.source}: result node {int(numbers[np.argmax(missing)])} is not in "
                "the node block (nor an expanded node of a planar model)",
            )
        return self.coordinates[order[where]]

    def named(self, name: str) -> tuple[ResultBlock, ...]:
        return tuple(block for block in self.blocks if block.name == name)


def _fail(source: str, line: int, rule: str) -> InputError:
    return InputError("traces", f"{source}: line {line}: {rule}")


def _width(flag: str) -> int:
    """Node-number width of a block: format 0 (short) I5, 1 (long) I10."""
    return 5 if flag.strip() == "0" else 10


def read_frd(path: str | Path) -> FrdFile:
    """Read an ASCII .frd file (binary ones, format 2 or 3, are refused)."""
    path = Path(path)
    source = str(path)
    try:
        lines = path.read_text(encoding="ascii", errors="strict").splitlines()
    except UnicodeDecodeError:
        raise InputError(
            "traces",
            f"{source}: not an ASCII .frd file (a binary one? write it with *NODE FILE ... "
            "OUTPUT=ASCII or the default ASCII output)",
        ) from None
    except OSError as error:
        raise InputError("traces", f"cannot read {source}: {error.strerror}") from None
    numbers: list[int] = []
    coordinates: list[list[float]] = []
    element_types: set[int] = set()
    blocks: list[ResultBlock] = []
    step = increment = 0
    k = 0
    if not lines or not lines[0].lstrip().startswith("1C"):
        raise _fail(source, 1, "not a CalculiX .frd file (it must start with a '1C' record)")
    while k < len(lines):
        line = lines[k]
        key = line.split(maxsplit=1)[0] if line.strip() else ""
        if key == "2C":
            width = _width(line[-2:])
            k += 1
            while k < len(lines) and not lines[k].startswith(" -3"):
                row = lines[k]
                try:
                    numbers.append(int(row[3 : 3 + width]))
                    base = 3 + width
                    coordinates.append(
                        [float(row[base + 12 * j : base + 12 * (j + 1)]) for j in range(3)]
                    )
                except ValueError:
                    raise _fail(source, k + 1, "a node record that is not numbers") from None
                k += 1
        elif key == "3C":
            k += 1
            while k < len(lines) and not lines[k].startswith(" -3"):
                row = lines[k]
                if row.startswith(" -1"):
                    try:
                        element_types.add(int(row.split()[2]))
                    except (ValueError, IndexError):
                        raise _fail(source, k + 1, "an element record without its type") from None
                k += 1
        elif key == "1PSTEP":
            fields = line.split()
            try:
                increment, step = int(fields[2]), int(fields[3])
            except (ValueError, IndexError):
                raise _fail(source, k + 1, "a 1PSTEP record without step numbers") from None
        elif key == "100CL":
            header = k + 1
            try:
                time = float(line[12:24])
                width = _width(line[-2:])
                name = lines[k + 1].split()[1]
            except (ValueError, IndexError):
                raise _fail(source, header, "a result block header that cannot be read") from None
            k += 2
            components: list[str] = []
            while k < len(lines) and lines[k].startswith(" -5"):
                fields = lines[k].split()
                if len(fields) > 1 and fields[-1] != "1ALL" and fields[1] != "ALL":
                    components.append(fields[1])
                k += 1
            nodes: list[int] = []
            values: list[list[float]] = []
            while k < len(lines) and not lines[k].startswith(" -3"):
                row = lines[k]
                if row.startswith(" -1"):
                    base = 3 + width
                    try:
                        nodes.append(int(row[3:base]))
                        values.append(
                            [
                                float(row[base + 12 * j : base + 12 * (j + 1)])
                                for j in range((len(row.rstrip()) - base) // 12)
                            ]
                        )
                    except ValueError:
                        raise _fail(source, k + 1, f"a {name} value that is not a number") from None
                k += 1
            count = len(components)
            if any(len(row) < count for row in values):
                raise _fail(source, header, f"{name}: a node has fewer values than components")
            blocks.append(
                ResultBlock(
                    name=name,
                    step=step,
                    increment=increment,
                    time=time,
                    components=tuple(components),
                    nodes=np.array(nodes, dtype=np.int64),
                    values=np.array([row[:count] for row in values], dtype=np.float64).reshape(
                        len(values), count
                    ),
                    line=header,
                )
            )
        k += 1
    if not numbers:
        raise InputError("traces", f"{source}: no node block (2C) in the file")
    xyz = np.array(coordinates, dtype=np.float64)
    planar = bool(element_types) and element_types <= PLANAR_TYPES and bool(np.all(xyz[:, 2] == 0))
    return FrdFile(source, np.array(numbers, dtype=np.int64), xyz, planar, tuple(blocks))
