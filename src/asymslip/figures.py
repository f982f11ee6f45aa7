"""The paper's figures, computed from the generated kernels (NumPy only at run time), and the
error map of every asymptotic estimate against the reference solver.

Fig. 5: the shear-traction difference q_diff = q2 - q1 (46) of a Hertzian contact, exact (47)
against the asymptotic corrective-slip solution (49), for the paper's illustrative values
R = E* = 1, mu = 0.1, lambda = 0.2, P1 = 100, dP = 5 (eta = 0).  The paper builds (49) on the
stick boundary b of (35); the curve for the consistent b of (17) is given as well.  The two
differ by the edge-singular term K (b - b17) / (2 sqrt(a2 - x)) (see ``asymslip_gen.tractions``).

The error map (:mod:`asymslip.solver.error_map`): the solver's stick boundary against every
estimate of ``slip_zone`` over a grid of laws, lambda, eta and a2/a1, written as
``error_map.csv`` (committed in ``generated/report/``, read by the derivation report) and drawn
as ``error_map.png`` from that CSV.

matplotlib (the ``plot`` extra) is imported only when a PNG is drawn.

Examples
--------
>>> from asymslip.figures import fig5_curves
>>> curves = fig5_curves(intervals=4)  # x = 0, a2/4, a2/2, 3 a2/4
>>> [round(float(value), 6) for value in (curves.a1, curves.b_paper, curves.b_consistent)]
[11.283792, 11.141852, 11.141884]
>>> [round(float(q), 4) for q in curves.exact]
[0.0281, 0.0291, 0.0327, 0.0438]
"""

from __future__ import annotations

import difflib
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from .cycle import LoadCycle
from .errors import InputError
from .files.atomic import atomic_write
from .laws.hertz import HertzLaw
from .slip_zones import slip_zone
from .solver import error_map as error_map_module
from .tractions import traction_difference

if TYPE_CHECKING:  # matplotlib is an extra (plot): imported only when a figure is drawn
    from matplotlib.figure import Figure

FloatArray = NDArray[np.float64]

__all__ = [
    "ERROR_MAP_CSV",
    "ERROR_MAP_PNG",
    "FIG5_PARAMETERS",
    "Fig5Curves",
    "Fig5Parameters",
    "fig5_curves",
    "stale_error_map_lines",
    "stale_fig5_lines",
    "write_error_map",
    "write_fig5",
]


@dataclass(frozen=True)
class Fig5Parameters:
    """The illustrative Hertzian cycle of the paper's Fig. 5 (Section 3.4)."""

    R: float = 1.0
    E_star: float = 1.0
    mu: float = 0.1
    lam: float = 0.2
    eta: float = 0.0
    P1: float = 100.0
    dP: float = 5.0


FIG5_PARAMETERS = Fig5Parameters()

#: Grid intervals on 0 <= x < a2: x = a2 * k / FIG5_INTERVALS for k = 0 .. FIG5_INTERVALS - 1.
#: The edge x = a2 itself is left out: (49) with b from (35) is singular there.
FIG5_INTERVALS = 2000


@dataclass(frozen=True)
class Fig5Curves:
    """The curves of Fig. 5 and the lengths that shape them.

    Attributes
    ----------
    x
        Positions 0 <= x < a2, measured from the contact centre.
    exact
        (47): mu (p(x, P2) + p(x, P1) - 2 p(x, P_K)).
    asymptotic
        (49) with b from (35), the paper's choice (dashed in the paper's figure).
    asymptotic_consistent
        (49) with b from (17), for which the density (15) solves (12).
    a1, a2
        Contact half-widths at load states 1 and 2.
    b_paper, b_consistent
        Stick boundary from (35) (exact for Hertz, = a(P_K)) and from (17).
    """

    x: FloatArray
    exact: FloatArray
    asymptotic: FloatArray
    asymptotic_consistent: FloatArray
    a1: float
    a2: float
    b_paper: float
    b_consistent: float


def fig5_curves(intervals: int = FIG5_INTERVALS) -> Fig5Curves:
    """Evaluate Fig. 5 on x = a2 k / intervals, k = 0 .. intervals - 1, through the API.

    The same evaluation as ``asymslip traction``: :func:`asymslip.tractions.traction_difference`
    with the paper's b (35) (= a(P_K), exact for Hertz) and with the consistent b (17).

    Parameters
    ----------
    intervals
        Number of grid intervals across 0 <= x <= a2 (an integer >= 2); the edge point is
        omitted.

    Returns
    -------
    Fig5Curves
    """
    if isinstance(intervals, bool) or not isinstance(intervals, int | np.integer):
        raise InputError("intervals", "must be an integer", intervals)
    if intervals < 2:
        raise InputError("intervals", "must be >= 2", intervals)
    p = FIG5_PARAMETERS
    law = HertzLaw(R=p.R, E_star=p.E_star)
    P2 = p.P1 + p.dP
    cycle = LoadCycle(P1=p.P1, Q1=0.0, P2=P2, Q2=p.lam * p.dP, sigma1=0.0, sigma2=p.eta * p.dP)
    summary = slip_zone(law, cycle, p.mu)
    x = summary.a2 * (np.arange(intervals, dtype=np.float64) / intervals)
    paper = traction_difference(law, cycle, p.mu, x, stick_boundary="exact")
    consistent = traction_difference(law, cycle, p.mu, x, stick_boundary="consistent")
    assert paper.q_diff_exact is not None  # Hertz has a pressure, and eta = 0
    return Fig5Curves(
        x=x,
        exact=np.array(paper.q_diff_exact),
        asymptotic=np.array(paper.q_diff),
        asymptotic_consistent=np.array(consistent.q_diff),
        a1=float(summary.a1),
        a2=float(summary.a2),
        b_paper=paper.b,
        b_consistent=consistent.b,
    )


CSV_COLUMNS = ("x", "q_exact", "q_asymptotic", "q_asymptotic_consistent")


def fig5_csv_text(curves: Fig5Curves) -> str:
    """The CSV of Fig. 5: comment lines, a header row, one '%.12e' row per grid point."""
    p = FIG5_PARAMETERS
    lines = [
        "# Fig. 5 of Moore, Hills et al., Theor. Appl. Fract. Mech. 2022, 103457: "
        f"Hertz, R = {p.R:g}, E* = {p.E_star:g}, mu = {p.mu:g}, lam = {p.lam:g}, "
        f"eta = {p.eta:g}, P1 = {p.P1:g}, dP = {p.dP:g}",
        "# q_exact: (47); q_asymptotic: (49) with b from (35); "
        "q_asymptotic_consistent: (49) with b from (17)",
        f"# a1 = {curves.a1:.12e}, a2 = {curves.a2:.12e}, b(35) = {curves.b_paper:.12e}, "
        f"b(17) = {curves.b_consistent:.12e}",
        ",".join(CSV_COLUMNS),
    ]
    columns = (curves.x, curves.exact, curves.asymptotic, curves.asymptotic_consistent)
    lines.extend(",".join(f"{value:.12e}" for value in row) for row in zip(*columns, strict=True))
    return "\n".join(lines) + "\n"


def figure_class() -> type[Figure]:
    """matplotlib's Figure (no pyplot), or an InputError naming the extra that provides it."""
    try:
        from matplotlib.figure import Figure
    except ImportError:
        raise InputError(
            "figure",
            "drawing a PNG needs matplotlib: install the 'plot' extra "
            "(pip install 'asymslip[plot]')",
        ) from None
    return Figure


def _draw_fig5(curves: Fig5Curves, path: Path) -> None:
    # Figure without pyplot: no global backend state, no GUI.
    figure = figure_class()(figsize=(6.4, 4.4))
    axes = figure.add_subplot()
    axes.plot(curves.x, curves.exact, "-", color="tab:blue", label="exact (47)")
    axes.plot(
        curves.x, curves.asymptotic, "--", color="tab:red", label="asymptotic (49), b from (35)"
    )
    axes.plot(
        curves.x,
        curves.asymptotic_consistent,
        ":",
        color="0.3",
        label="asymptotic (49), b from (17)",
    )
    for position, name, offset in ((curves.b_paper, "b", -9), (curves.a1, "$a_1$", 2)):
        axes.axvline(position, color="0.8", linewidth=0.8, zorder=0)
        axes.annotate(name, (position, 0), textcoords="offset points", xytext=(offset, 4))
    axes.set_xlim(0, curves.a2)
    axes.set_ylim(bottom=0)
    axes.set_xlabel("x")
    axes.set_ylabel(r"$q_{\rm diff}(x) = q_2(x) - q_1(x)$")
    p = FIG5_PARAMETERS
    axes.set_title(
        f"Hertz: R = E* = {p.R:g}, $\\mu$ = {p.mu:g}, $\\lambda$ = {p.lam:g}, "
        f"$P_1$ = {p.P1:g}, $\\Delta P$ = {p.dP:g}",
        fontsize="medium",
    )
    axes.legend(loc="upper left", frameon=False)
    figure.tight_layout()
    with atomic_write(path, "out") as handle:
        figure.savefig(handle, format="png", dpi=150, metadata={"Software": None})


def write_fig5(directory: Path) -> list[Path]:
    """Write ``fig5.csv`` and ``fig5.png`` (the paper's Fig. 5) into ``directory``.

    Each file is written beside its target and renamed when complete (never a truncated file).

    Parameters
    ----------
    directory
        Output folder; created if missing.

    Returns
    -------
    list of Path
        The CSV and the PNG, in that order.

    Raises
    ------
    InputError
        If ``directory`` exists and is not a folder or cannot be created, or matplotlib (the
        ``plot`` extra) is not installed (checked before anything is written).
    """
    figure_class()  # fail before writing anything
    directory = _output_folder(directory, "out")  # before the computing: fail at once
    curves = fig5_curves()
    csv_path = directory / "fig5.csv"
    png_path = directory / "fig5.png"
    with atomic_write(csv_path, "out", mode="w") as handle:
        handle.write(fig5_csv_text(curves))
    _draw_fig5(curves, png_path)
    return [csv_path, png_path]


def stale_fig5_lines(directory: Path) -> list[str]:
    """A unified diff of the committed ``fig5.csv`` against what :func:`write_fig5` writes now.

    Empty when fresh.  The PNG is not compared: its bytes depend on the matplotlib version.
    """
    committed = Path(directory) / "fig5.csv"
    old = committed.read_text().splitlines(keepends=True) if committed.exists() else []
    fresh = fig5_csv_text(fig5_curves()).splitlines(keepends=True)
    return list(
        difflib.unified_diff(old, fresh, f"committed/{committed.name}", "regenerated/fig5.csv")
    )


# --- the error map ------------------------------------------------------------------------------
ERROR_MAP_CSV = "error_map.csv"
ERROR_MAP_PNG = "error_map.png"

#: How the estimates are drawn: attribute -> (label, colour, marker).
_ESTIMATE_STYLE = {
    "b": ("b: second order b2 (headline)", "tab:green", "o"),
    "b_paper": ("b_paper: the paper's (22)", "tab:red", "s"),
    "b_first_order": ("b_first_order: (28)", "tab:orange", "^"),
    "b_corrective_stick": ("b_corrective_stick: (40)", "tab:purple", "v"),
    "b_exact": ("b_exact: a(P_K), exact without tension", "tab:blue", "D"),
}
#: |error| below this is drawn on the floor of the logarithmic axis.
_FLOOR = 0.01


def _output_folder(directory: Path, option: str) -> Path:
    """``directory``, created if missing; refused (naming ``option``) if it cannot be."""
    directory = Path(directory)
    if directory.exists() and not directory.is_dir():
        raise InputError(option, "must be a folder, not an existing file", str(directory))
    try:
        directory.mkdir(parents=True, exist_ok=True)
    except OSError as error:  # a file where a folder must be, no permission, a full disk
        raise InputError(
            option, f"cannot create the folder {directory}: {error.strerror or error}"
        ) from None
    return directory


def _draw_error_map(rows: list[dict[str, str]], path: Path) -> None:
    """|error| in elements against a2/a1, per estimate, without and with tension.

    Every slipping edge is a point (hollow where ``slip_zone`` gives a validity warning); the
    line joins each estimate's largest |error| at each a2/a1; the grey band is the solver's
    stated bound (its largest value in the panel).
    """
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    figure = figure_class()(figsize=(10.0, 5.0))
    axes_pair = figure.subplots(1, 2, sharey=True)
    ratios = sorted({float(row["a2_a1"]) for row in rows})
    positions = {ratio: index for index, ratio in enumerate(ratios)}
    names = list(_ESTIMATE_STYLE)
    handles: list[object] = []
    for axes, tension in zip(axes_pair, (False, True), strict=True):
        chosen = [
            row
            for row in rows
            if row["slip_direction"] != "0" and (float(row["tau"]) != 0) == tension
        ]
        bound = max(float(row["b_error_elements"]) for row in chosen)
        axes.axhspan(_FLOOR / 2, bound, color="0.9", zorder=0)
        for offset, name in enumerate(names):
            label, colour, marker = _ESTIMATE_STYLE[name]
            shift = (offset - (len(names) - 1) / 2) * 0.09
            largest = []
            for ratio in ratios:
                here = [
                    row
                    for row in chosen
                    if float(row["a2_a1"]) == ratio and row[f"{name}_elements"]
                ]
                if not here:
                    continue
                errors = np.array([abs(float(row[f"{name}_elements"])) for row in here])
                warned = np.array([row["validity_warning"] != "0" for row in here])
                shown = np.maximum(errors, _FLOOR)
                x = np.full(len(shown), positions[ratio] + shift)
                axes.scatter(
                    x[~warned],
                    shown[~warned],
                    s=10,
                    color=colour,
                    alpha=0.35,
                    marker=marker,
                    linewidths=0,
                )
                axes.scatter(
                    x[warned],
                    shown[warned],
                    s=12,
                    facecolors="none",
                    alpha=0.5,
                    edgecolors=colour,
                    marker=marker,
                    linewidths=0.7,
                )
                largest.append((positions[ratio] + shift, max(float(errors.max()), _FLOOR)))
            if largest:
                xs, ys = zip(*largest, strict=True)
                line = axes.plot(
                    xs, ys, "-", color=colour, marker=marker, markersize=5, label=label
                )
                if not tension:
                    handles.append(line[0])
        axes.set_yscale("log")
        axes.set_ylim(_FLOOR / 2, 300)
        axes.set_xticks(range(len(ratios)), [f"{ratio:.2f}" for ratio in ratios])
        axes.set_xlim(-0.5, len(ratios) - 0.5)
        axes.set_xlabel("$a_2/a_1$")
        axes.set_title(
            (
                "with bulk tension ($\\eta \\neq 0$)"
                if tension
                else "without bulk tension ($\\eta = 0$)"
            )
            + f": {len(chosen)} slipping edges, bound up to {bound:.2f}",
            fontsize="medium",
        )
        axes.grid(True, which="major", axis="y", color="0.8", linewidth=0.5)
    axes_pair[0].set_ylabel("|estimate - solver b| in solver elements")
    handles += [
        Patch(color="0.9", label="within the solver's bound"),
        Line2D(
            [],
            [],
            linestyle="none",
            marker="o",
            color="0.4",
            alpha=0.5,
            label="an edge, no validity warning",
        ),
        Line2D(
            [],
            [],
            linestyle="none",
            marker="o",
            markerfacecolor="none",
            markeredgecolor="0.4",
            label="an edge with a validity warning",
        ),
    ]
    figure.legend(handles=handles, loc="lower center", ncol=4, frameon=False, fontsize="small")
    module = error_map_module
    figure.suptitle(
        "Stick boundary: every estimate against the reference solver, largest error (line) and "
        f"each slipping edge (points)\nN = {module.ELEMENTS} elements, $\\mu$ = {module.MU:g}, "
        "Hertz, rounded flat, power law n = 1.5 and 3; errors below 0.01 drawn at 0.01",
        fontsize="medium",
    )
    figure.tight_layout(rect=(0, 0.1, 1, 1))
    with atomic_write(path, "out") as handle:
        figure.savefig(handle, format="png", dpi=130, metadata={"Software": None})


def write_error_map(
    directory: Path,
    data: Path | None = None,
    *,
    redraw: bool = False,
    progress: Callable[[int, int], None] | None = None,
) -> list[Path]:
    """Run the error map and write ``error_map.csv`` into ``data`` and ``error_map.png``.

    Parameters
    ----------
    directory
        Folder of the PNG; created if missing.
    data
        Folder of the CSV (default: ``directory``); created if missing.
    redraw
        Draw the PNG from the CSV already in ``data`` instead of running the solver.
    progress
        Called as ``progress(done, total)`` after each solver case.

    Returns
    -------
    list of Path
        The CSV (unless redrawn) and the PNG.

    Raises
    ------
    InputError
        If a folder is an existing file, matplotlib is missing (checked before the solver
        runs), or with ``redraw`` the CSV is missing or not an error map.
    """
    figure_class()  # fail before running the solver
    directory = _output_folder(directory, "out")
    if data is None:
        data = directory
    else:  # only read when redrawing: nothing to create
        data = Path(data) if redraw else _output_folder(data, "data")
    csv_path, png_path = data / ERROR_MAP_CSV, directory / ERROR_MAP_PNG
    written = []
    if redraw:
        if not csv_path.is_file():
            raise InputError(
                "data", f"has no {ERROR_MAP_CSV} to redraw: run the map first", str(data)
            )
        text = csv_path.read_text(encoding="utf-8")
    else:
        text = error_map_module.csv_text(error_map_module.error_map(progress=progress))
        with atomic_write(csv_path, "data", mode="w") as handle:
            handle.write(text)
        written.append(csv_path)
    _draw_error_map(error_map_module.read_csv(text), png_path)
    return [*written, png_path]


def stale_error_map_lines(data: Path, *, every_row: bool = False) -> list[str]:
    """What differs between the committed ``error_map.csv`` and a fresh solver run.

    By default only the check cases (``asymslip.solver.error_map.CHECK_CASES``, a few
    seconds) are recomputed, and the committed map must have the grid's number of rows;
    ``every_row`` recomputes the whole map.  Empty when fresh.  The PNG is not compared: its
    bytes depend on the matplotlib version.
    """
    path = Path(data) / ERROR_MAP_CSV
    if not path.is_file():
        return [f"{path}: missing"]
    cases = error_map_module.map_cases() if every_row else None
    return error_map_module.stale_rows(path.read_text(encoding="utf-8"), cases)
