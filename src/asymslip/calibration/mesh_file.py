"""Pressure traces from a mesh file with a nodal pressure field, read through meshio.

Any format meshio reads (VTU, VTK, XDMF, Gmsh, MED, ...; the ``fe`` extra installs meshio).
The traces are the point-data fields named ``field`` or ``field`` followed by a separator and
a label (``CPRESS``, ``CPRESS_1``, ``CPRESS-step7``, ...), one state per field in the file's
order; their loads come from ``loads`` (one per field) or from labels that say them
(``CPRESS P=1000``).  The contact surface's nodes are the nodes of the file's line cells
(a surface exported as lines) or, without line cells, every point; their positions along the
surface follow :mod:`.surface`, and the rules of :mod:`.fe_traces` apply (negative pressures
clipped and counted, repeated loads).

Runtime needs NumPy and meshio.

Examples
--------
Which point-data fields are pressures, and the loads their names give:

>>> pressure_fields(["CPRESS_1", "CPRESS P=1000", "CPRESSURE", "S"], "CPRESS")
[('CPRESS_1', None), ('CPRESS P=1000', 1000.0)]
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from pathlib import Path

import numpy as np

from ..errors import InputError
from .fe_traces import FeState, FeTraces, assemble

#: The field name used when none is given.
DEFAULT_FIELD = "CPRESS"
_LOAD_IN_NAME = re.compile(r"P\s*=\s*([-+0-9.eE]+)")


def pressure_fields(keys: Sequence[str], name: str) -> list[tuple[str, float | None]]:
    """The fields named ``name`` or ``name`` and a label, with the load a label says."""
    pattern = re.compile(rf"^{re.escape(name)}(?:$|[\s_\-:.,(\[].*)")
    found = []
    for key in keys:
        if pattern.match(key):
            load = _LOAD_IN_NAME.search(key)
            found.append((key, float(load.group(1)) if load else None))
    return found


def mesh_traces(
    path: str | Path, loads: Sequence[float] | None, field: str | None = None
) -> FeTraces:
    """The traces of a mesh file's nodal pressure fields (module rules)."""
    try:
        import meshio
    except ImportError:
        raise InputError(
            "traces",
            "reading a mesh file needs meshio: pip install 'asymslip[fe]'",
        ) from None
    path = Path(path)
    name = field or DEFAULT_FIELD
    try:
        mesh = meshio.read(path)
    except Exception as error:  # meshio raises many kinds; the message is what matters
        reason = str(error).splitlines()[0] if str(error) else type(error).__name__
        raise InputError("traces", f"{path}: meshio cannot read it: {reason}") from None
    named = pressure_fields(list(mesh.point_data), name)
    fields = [key for key, _ in named]
    if not fields:
        raise InputError(
            "field",
            f"{path} has no point-data field named {name!r} (it has: "
            f"{', '.join(mesh.point_data) or 'none'})",
        )
    lines = [block.data for block in mesh.cells if block.type.startswith("line")]
    points = (
        np.unique(np.concatenate([cells.ravel() for cells in lines]))
        if lines
        else np.arange(mesh.points.shape[0])
    )
    named_loads = [load for _, load in named]
    if loads is not None and any(value is not None for value in named_loads):
        raise InputError(
            "loads", f"{path}: the fields' names give the loads: --loads is not needed"
        )
    states = []
    for key, load in zip(fields, named_loads, strict=True):
        values = np.asarray(mesh.point_data[key], dtype=np.float64)
        if values.ndim != 1:
            raise InputError("field", f"{path}: field {key!r} is not a scalar field")
        states.append(
            FeState(
                label=f"field {key}",
                load=load,
                nodes=points.astype(np.int64),
                pressure=values[points],
                opening=np.full(points.size, np.nan),
            )
        )
    coordinates = {int(k): mesh.points[k, :2].astype(np.float64) for k in points}
    if np.any(mesh.points[points, 2:] != 0) if mesh.points.shape[1] > 2 else False:
        raise InputError(
            "traces",
            f"{path}: the surface nodes do not lie in the plane z = 0 (a 2-D model is needed)",
        )
    return assemble(str(path), states, coordinates, loads)
