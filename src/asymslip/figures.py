"""The paper's figures, computed from the generated kernels (NumPy only at run time).

Fig. 5: the shear-traction difference q_diff = q2 - q1 (46) of a Hertzian contact, exact (47)
against the asymptotic corrective-slip solution (49), for the paper's illustrative values
R = E* = 1, mu = 0.1, lambda = 0.2, P1 = 100, dP = 5 (eta = 0).  The paper builds (49) on the
stick boundary b of (35); the curve for the consistent b of (17) is given as well.  The two
differ by the edge-singular term K (b - b17) / (2 sqrt(a2 - x)) (see ``asymslip_gen.tractions``).

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
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from .cycle import LoadCycle
from .errors import InputError
from .files.atomic import atomic_write
from .laws.hertz import HertzLaw
from .slip_zones import slip_zone
from .tractions import traction_difference

FloatArray = NDArray[np.float64]

__all__ = [
    "FIG5_PARAMETERS", "Fig5Curves", "Fig5Parameters", "fig5_curves", "stale_fig5_lines",
    "write_fig5",
]  # fmt: skip


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


def figure_class():
    """matplotlib's Figure (no pyplot), or an InputError naming the extra that provides it."""
    try:
        from matplotlib.figure import Figure
    except ImportError:
        raise InputError("figure", "drawing a PNG needs matplotlib: install the 'plot' extra "
                         "(pip install 'asymslip[plot]')") from None  # fmt: skip
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
    directory = Path(directory)
    if directory.exists() and not directory.is_dir():
        raise InputError("out", "must be a folder, not an existing file", str(directory))
    figure_class()  # fail before writing anything
    try:  # before the second of computing: an unusable folder fails at once
        directory.mkdir(parents=True, exist_ok=True)
    except OSError as error:  # a file where a folder must be, no permission, a full disk
        raise InputError("out", f"cannot create the folder {directory}: "
                         f"{error.strerror or error}") from None  # fmt: skip
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
    return list(difflib.unified_diff(old, fresh, f"committed/{committed.name}",
                                     "regenerated/fig5.csv"))  # fmt: skip
