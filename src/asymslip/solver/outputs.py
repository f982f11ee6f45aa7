"""Write a solver result as CSV curves and a PNG: tractions, slip and frictional energy.

Files (each written beside and renamed into place by :func:`asymslip.files.atomic.atomic_write`,
so an interrupted run leaves no truncated file):

``tractions.csv``
    x, then for each path point k: ``p_k`` (pressure), ``q_k`` (shear traction exerted on the
    indenter by the lower body, along +x), ``state_k`` (0 stick, +1/-1 slipping with q_k =
    +mu p_k / -mu p_k, blank out of contact); for the paper's cycle also ``q_diff`` = q_2 - q_1
    (46).
``slip.csv``
    x, ``slip_k`` (the change of u_x(indenter) - u_x(lower body) since point 1 of the steady
    period: for the paper's cycle ``slip_2`` is the slip delta from state 1 to state 2, of the
    sign opposite to q_2 - q_1 in a slip zone), ``slip_range`` (peak to peak over the period) and
    ``slip_amplitude`` (half of it).
``energy.csv``
    x, ``energy``: frictional energy dissipated per period per unit area, -int q d(delta).
``solver.png``
    the three, one panel each (matplotlib, the ``plot`` extra, imported only here).

Values are written with 17 significant digits (they read back exactly).  Every file's comment
lines state the conventions in the words of :mod:`asymslip.solver.conventions`.

Examples
--------
>>> from asymslip import HertzLaw, LoadCycle
>>> from asymslip.solver import solve
>>> from asymslip.solver.outputs import csv_texts
>>> texts = csv_texts(solve(HertzLaw(R=1, E_star=1), LoadCycle(100, 0, 105, 1), mu=0.1,
...                         elements=200))
>>> sorted(texts)
['energy.csv', 'slip.csv', 'tractions.csv']
>>> [line for line in texts["tractions.csv"].splitlines() if not line.startswith("#")][0]
'x,p_1,q_1,state_1,p_2,q_2,state_2,q_diff'
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from ..errors import InputError
from ..files.atomic import atomic_write
from .conventions import comment_line
from .result import Edge, SolverResult

#: The files :func:`write_outputs` writes into its folder (the PNG unless ``png=False``).
FILES = ("tractions.csv", "slip.csv", "energy.csv", "solver.png")


def _figure_class() -> Any:
    try:
        from matplotlib.figure import Figure
    except ImportError:
        raise InputError(
            "out",
            "drawing solver.png needs matplotlib: install the 'plot' extra, e.g. "
            "pip install 'asymslip[plot]', or write the CSV files only (png=False; on the "
            "command line --no-plot)",
        ) from None
    return Figure


def _csv_text(header: list[str], columns: list[np.ndarray], comments: list[str]) -> str:
    lines = [f"# {line}" for line in comments] + [",".join(header)]
    for row in zip(*columns, strict=True):
        lines.append(",".join("" if np.isnan(v) else f"{v:.17g}" for v in row))
    return "\n".join(lines) + "\n"


def _comments(result: SolverResult) -> list[str]:
    loads = "; ".join(
        f"{s.label}: P={s.P:.17g} Q={s.Q:.17g} sigma={s.sigma:.17g} M={s.M:.17g}"
        for s in result.states
    )
    profile = ", ".join(f"{k} = {v}" for k, v in result.profile.items())
    # Three comment lines, always: readers skip them by count.
    return [
        f"asymslip reference solver: {profile}; mu = {result.mu:.17g}, E* = {result.E_star:.17g}; "
        f"{result.elements} elements of {result.element_size:.17g} on "
        f"[{result.grid.start:.17g}, {result.grid.end:.17g}]; {result.steps} steps per segment; "
        f"steady = {result.steady} after {result.cycles} periods",
        f"points: {loads}",
        comment_line(),
    ]


def csv_texts(result: SolverResult) -> dict[str, str]:
    """File name -> text of the three CSV files."""
    comments = _comments(result)
    x = result.x
    header, columns = ["x"], [x]
    for state in result.states:
        kind = np.where(state.contact, state.slip_sign.astype(float), np.nan)
        header += [f"p_{state.label}", f"q_{state.label}", f"state_{state.label}"]
        columns += [state.pressure, state.shear, kind]
    if result.is_cycle:
        header.append("q_diff")
        columns.append(result.q_diff)
    slip_header = ["x"] + [f"slip_{s.label}" for s in result.states]
    slip_columns = [x] + [s.slip for s in result.states]
    slip_header += ["slip_range", "slip_amplitude"]
    slip_columns += [result.slip_range, result.slip_amplitude]
    return {
        "tractions.csv": _csv_text(header, columns, comments),
        "slip.csv": _csv_text(slip_header, slip_columns, comments),
        "energy.csv": _csv_text(["x", "energy"], [x, result.energy], comments),
    }


def _draw(result: SolverResult, target: Any) -> None:
    figure = _figure_class()(figsize=(7.0, 8.4))
    traction, slip, energy = figure.subplots(3, 1, sharex=True)
    x = result.x
    for state in result.states:
        (line,) = traction.plot(x, state.shear, label=f"q at {state.label}")
        traction.plot(
            x,
            result.mu * state.pressure,
            ":",
            color=line.get_color(),
            linewidth=0.8,
            label=f"$\\mu$ p at {state.label}",
        )
        slip.plot(x, state.slip, color=line.get_color(), label=f"slip at {state.label}")
    if result.is_cycle:
        traction.plot(x, result.q_diff, "k--", linewidth=1.0, label="$q_{diff} = q_2 - q_1$")
    slip.plot(x, result.slip_amplitude, "k-", linewidth=1.0, label="slip amplitude")
    energy.plot(x, result.energy, "k-")
    sides: tuple[Edge, Edge] = ("right", "left")
    for side in sides:
        edge = result.edge(side)
        if edge.b is not None:
            position = edge.b if side == "right" else -edge.b
            for axes in (traction, slip, energy):
                axes.axvline(position, color="0.8", linewidth=0.8, zorder=0)
    traction.set_ylabel("q: on the indenter")
    slip.set_ylabel("slip: u_x(indenter) - u_x(lower)")
    energy.set_ylabel("energy per period")
    energy.set_xlabel(
        "x from the contact centre (grey: permanent stick boundaries); slip since point 1, "
        "opposite in sign to q2 - q1 in a slip zone",
        fontsize="small",
    )
    traction.legend(fontsize="small", frameon=False, ncol=2)
    slip.legend(fontsize="small", frameon=False)
    traction.set_title(
        f"{result.profile.get('profile', '')}, $\\mu$ = {result.mu:g}, {result.elements} elements",
        fontsize="medium",
    )
    figure.tight_layout()
    figure.savefig(target, format="png", dpi=130, metadata={"Software": None})


def write_outputs(result: SolverResult, out_dir: str | Path, *, png: bool = True) -> list[Path]:
    """Write the traction, slip and energy curves (CSV) and, unless ``png`` is False, a PNG.

    Parameters
    ----------
    result
        A solver result.
    out_dir
        Folder to write into; created if missing.
    png
        Draw ``solver.png`` (needs matplotlib, the ``plot`` extra).

    Returns
    -------
    list of Path
        The files written.

    Raises
    ------
    InputError
        (``out``) if the folder cannot be written, is an existing file, or matplotlib is
        missing for the PNG -- checked before anything is written.
    """
    folder = Path(out_dir)
    if folder.exists() and not folder.is_dir():
        raise InputError("out", "must be a folder, not an existing file", str(folder))
    if png:
        _figure_class()  # fail before writing anything
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        raise InputError("out", f"cannot create {folder}: {error.strerror}") from None
    written = []
    for name, text in csv_texts(result).items():
        path = folder / name
        with atomic_write(path, "out", "w") as handle:
            handle.write(text)
        written.append(path)
    if png:
        path = folder / "solver.png"
        with atomic_write(path, "out", "wb") as handle:
            _draw(result, handle)
        written.append(path)
    return written
