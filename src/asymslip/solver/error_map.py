"""The error map: every asymptotic estimate of the stick boundary against the reference solver.

The solver is run over a fixed grid of the paper's two-state cycle -- four contact laws, the
contact growth a2/a1, the shear slope lambda/mu and the tension slope tau = pi eta a1/(4 mu)
(18) -- and for each edge of each cycle the solver's permanent stick boundary b (with its error
bound) is set beside every estimate of :func:`asymslip.slip_zone`: ``b`` (the headline, the
second-order b2), ``b_paper`` (22), ``b_first_order`` (28), ``b_corrective_stick`` (40) and
``b_exact`` (a(P_K), only without tension).  Each estimate's error is given in solver elements
and as a fraction of the slip-zone width a1 - b (the solver's b).  The rows are written as a
CSV with fixed formatting, committed as ``generated/report/error_map.csv``, summarised in the
derivation report and drawn by :func:`asymslip.figures.write_error_map`.

The grid
--------
Every law is set to a1 = 2 at state 1 (P1 = P(a1)) and P2 = P(a2) for a2/a1 in ``RATIOS``;
mu = 0.3, Q1 = sigma1 = 0, Q2 = lambda dP, sigma2 = eta dP.  The right edge slips forward
where lambda/mu + tau > 1, and the left edge (which sees lambda -> -lambda, eta -> eta) slips
the same way in the global frame where lambda/mu - tau > 1, the opposite way where
tau - lambda/mu > 1, and not at all in between.  A pair (lambda/mu, tau) of the axes is kept
when the right edge slips forward by a margin (lambda/mu + tau >= 1 + ``MARGIN``) and the left
edge is at least ``MARGIN`` from its own threshold (| |tau - lambda/mu| - 1 | >= ``MARGIN``):
a case at a threshold belongs to neither branch.  That leaves 15 pairs: the other edge slips
the same way (9, 3 of them without tension), the opposite way (2) or sticks (4).  The tension
axis holds tau >= 0 only: by mirror symmetry the left edge of (lambda/mu, tau) is the right
edge of (lambda/mu, -tau), so each cycle's two edges cover both signs (the columns
``edge_lam_mu`` and ``edge_tau`` give each edge's own forward-frame slopes, and
``tests/test_error_map.py`` checks the mirror against fresh solver runs).

The number of elements and load steps
-------------------------------------
N = ``ELEMENTS`` = 4000, chosen by measurement (16 cycles: the four laws at a2/a1 = 1.02 with
lambda/mu = 1.5, and at 1.10 with the other edge slipping the same way, the opposite way and
not at all; N = 2000, 4000, 8000 against N = 16000): at N = 4000 both edges' boundaries lie
within 0.07 element of N = 16000 (0.19 at N = 2000), and without tension a(P_K) lies within
0.09 element of the solver everywhere in the map, so the stated bound (one element, at least)
is conservative by a factor of about ten.  At N = 4000 the narrowest slip zone of the map spans
5.6 elements (all estimates agree within the bound there), the widest 270; per law the largest
error of (22) with tension is 48-167 elements and of (28) 8-43 elements (the bound is at most
1.22 elements), while the whole map (180 cycles, 228 solver runs) takes about 1.5 minutes on
the two-core development machine.
N = 8000 would double the time and every error in elements without changing a conclusion;
N = 16000 costs 10-80 s a run.

One load step per half-cycle (``STEPS``) where both edges slip: every element entering the
contact then slips at once, and the boundaries do not depend on the steps (measured: the same
to 1e-3 element with 8 steps, in 12 cycles).  Where an edge does not slip, the elements
entering its contact lock in the history of their entry, and the boundaries converge like
1/steps (measured: up to 0.35 element from 1 step to the limit): such a cycle is run again with
2 steps, b is extrapolated (Richardson, first order) and the change is added to the bound (the
extrapolated b was within 0.06 element of 32-step runs in 10 cycles).
"""

from __future__ import annotations

import csv
import io
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass
from typing import Any

from asymslip_gen.edge_drive import tension_share, tension_slope_for_share

from ..cycle import LoadCycle
from ..edge_flags import VALIDITY_THRESHOLD
from ..errors import InputError
from ..laws import FlatRoundedLaw, HertzLaw, PowerLaw
from ..slip_zones import slip_zone
from .run import solve
from .toeplitz import SolverError

#: The contact laws of the map: name -> (law, description).  Each is set to a1 = A1.
LAWS: dict[str, tuple[Any, str]] = {
    "hertz": (HertzLaw(R=1.0, E_star=1.0), "Hertz (cylinder), R = E* = 1"),
    "flat-rounded": (
        FlatRoundedLaw(c=1.0, R=10.0, E_star=1.0),
        "flat punch with rounded corners, c = 1, R = 10, E* = 1 (c/a1 = 0.5)",
    ),
    "power-1.5": (PowerLaw(A=0.3, n=1.5, E_star=1.0), "power law h = 0.3 |x|^1.5, E* = 1"),
    "power-3": (PowerLaw(A=0.05, n=3.0, E_star=1.0), "power law h = 0.05 |x|^3, E* = 1"),
}
#: Coefficient of friction and the state-1 contact half-width of every cycle.
MU = 0.3
A1 = 2.0
#: Contact growth a2/a1 of the cycles.
RATIOS = (1.02, 1.05, 1.10)
#: lambda/mu and tau = pi eta a1/(4 mu) axes; pairs are kept by :func:`kept`.
SHEAR_SLOPES = (0.0, 0.5, 1.5, 2.0, 3.0)
TENSION_SLOPES = (0.0, 0.2, 0.5, 1.0, 2.0)
#: Distance from a slip threshold (in units of mu) a kept pair keeps at both edges.
MARGIN = 0.25
#: Solver elements and load steps per half-cycle (see the module docstring for the choice).
ELEMENTS = 4000
STEPS = 1

#: The estimates of ``slip_zone`` compared, by attribute name (as ``compare.ESTIMATES``).
ESTIMATES = ("b", "b_paper", "b_first_order", "b_corrective_stick", "b_exact")

#: Columns of the CSV, in order, with the format of their numbers.
COLUMNS: dict[str, str] = {
    "law": "s",
    "a2_a1": ".2f",
    "lam_mu": ".2f",
    "tau": ".2f",
    "edge": "s",
    "other_edge": "s",
    "slip_direction": "d",
    "solver_slip_direction": "d",
    "edge_lam_mu": ".2f",
    "edge_tau": ".2f",
    "elements": "d",
    "element": ".6e",
    "a1": ".10f",
    "b_solver": ".10f",
    "b_error_elements": ".3f",
    "steps_change_elements": ".3f",
    "width_elements": ".3f",
    "b_accuracy_elements": ".3f",
    "eq24": ".5f",
    "eq25": ".5f",
    "eq26": ".5f",
    "eq27": ".5f",
    "validity_warning": "d",
    **{
        f"{name}_{unit}": fmt
        for name in ESTIMATES
        for unit, fmt in (("elements", ".3f"), ("fraction", ".5f"))
    },
}

#: The runs the quick freshness check recomputes: one per law, each branch of the other edge,
#: with and without tension, the largest errors of the map among them.
CHECK_CASES: tuple[tuple[str, float, float, float], ...] = (
    ("hertz", 1.10, 2.0, 0.5),
    ("power-3", 1.10, 3.0, 0.0),
    ("flat-rounded", 1.05, 0.5, 2.0),
    ("power-1.5", 1.02, 1.5, 1.0),
)


def kept(lam_mu: float, tau: float, margin: float = MARGIN) -> bool:
    """Whether the pair (lambda/mu, tau) is in the map (see the module docstring)."""
    return lam_mu + tau >= 1 + margin and abs(abs(tau - lam_mu) - 1) >= margin


@dataclass(frozen=True)
class MapCase:
    """One cycle of the map: the law's name, a2/a1, lambda/mu and tau = pi eta a1/(4 mu)."""

    law: str
    ratio: float
    lam_mu: float
    tau: float

    def __post_init__(self) -> None:
        if self.law not in LAWS:
            raise InputError("law", f"must be one of {', '.join(LAWS)}", self.law)

    @property
    def contact_law(self) -> Any:
        return LAWS[self.law][0]

    def cycle(self) -> LoadCycle:
        """The cycle: P1 = P(a1), P2 = P(a2), Q1 = sigma1 = 0, Q2 = lambda dP, sigma2 = eta dP."""
        law = self.contact_law
        P1, P2 = float(law.load(A1)), float(law.load(self.ratio * A1))
        dP = P2 - P1
        lam = self.lam_mu * MU
        eta = float(tension_slope_for_share(self.tau, A1, MU))
        return LoadCycle(P1, 0.0, P2, lam * dP, 0.0, eta * dP)


def map_cases(laws: Iterable[str] = LAWS) -> tuple[MapCase, ...]:
    """The map's cycles in their fixed order: law, a2/a1, lambda/mu, tau."""
    return tuple(
        MapCase(law, ratio, lam_mu, tau)
        for law in laws
        for ratio in RATIOS
        for lam_mu in SHEAR_SLOPES
        for tau in TENSION_SLOPES
        if kept(lam_mu, tau)
    )


def _other_edge(direction: int, other: int) -> str:
    """How the other edge slips in the global frame: the own frames of the two edges are
    mirror images, so the same global way means opposite own-frame directions."""
    if other == 0:
        return "none"
    if direction == 0:
        return "slips"
    return "same" if direction == -other else "opposite"


def _fraction(difference: float, width: float) -> float | None:
    return difference / width if width > 0 else None


SIDES = ("right", "left")


@dataclass(frozen=True)
class SolvedBoundary:
    """The solver's permanent stick boundary of one edge, as the map uses it."""

    b: float
    bound: float  # the solver's bound, plus the load-step change where extrapolated
    steps_change: float | None  # b(2 STEPS) - b(STEPS) where extrapolated, else None
    slip_direction: int


def _solved(case: MapCase, steps: int, elements: int) -> tuple[float, dict[str, SolvedBoundary]]:
    """One solver run: the element width and each edge's boundary.

    Refused (SolverError) unless steady, free of warnings and with a permanent stick zone.
    """
    result = solve(case.contact_law, case.cycle(), MU, elements=elements, steps=steps)
    if not result.steady or result.warnings:
        raise SolverError(
            f"error map, {case}: the solver's result is not usable: "
            + "; ".join(result.warnings or ("not steady",))
        )
    edges = {}
    for side in SIDES:
        edge = result.right if side == "right" else result.left
        if edge.b is None or edge.b_error is None:
            raise SolverError(f"error map, {case}: no permanent stick zone")
        edges[side] = SolvedBoundary(edge.b, edge.b_error, None, edge.slip_direction)
    return result.element_size, edges


def solver_boundaries(
    case: MapCase, *, elements: int = ELEMENTS
) -> tuple[float, dict[str, SolvedBoundary]]:
    """The element width and, per edge, the solver's b and its bound.

    One load step per half-cycle where both edges slip; where one does not, extrapolated from
    one and two steps, the change added to the bound (see the module docstring).
    """
    h, coarse = _solved(case, STEPS, elements)
    if all(edge.slip_direction for edge in coarse.values()):
        return h, coarse
    _, fine = _solved(case, 2 * STEPS, elements)
    out = {}
    for side in SIDES:
        change = fine[side].b - coarse[side].b
        out[side] = SolvedBoundary(
            fine[side].b + change,
            fine[side].bound + abs(change),
            change,
            coarse[side].slip_direction,
        )
    return h, out


def solve_case(case: MapCase, *, elements: int = ELEMENTS) -> list[dict[str, Any]]:
    """The two rows (right edge, left edge) of one cycle: the solver's b and every estimate.

    Raises
    ------
    SolverError
        If the solver does not reach a steady state or warns about its result: the map holds
        only results the solver stands behind.
    """
    h, boundaries = solver_boundaries(case, elements=elements)
    estimates = slip_zone(case.contact_law, case.cycle(), MU, edge="both")
    left = estimates.left
    assert left is not None  # edge="both" gives the left edge
    rows = []
    sides = (("right", estimates, left), ("left", left, estimates))
    for side, estimate, other in sides:
        solved = boundaries[side]
        b = solved.b
        direction = int(estimate.slip_direction)
        orientation = direction if direction else 1
        width = float(estimate.a1) - b
        slipping = direction != 0
        row: dict[str, Any] = {
            "law": case.law,
            "a2_a1": case.ratio,
            "lam_mu": case.lam_mu,
            "tau": case.tau,
            "edge": side,
            "other_edge": _other_edge(direction, int(other.slip_direction)),
            "slip_direction": direction,
            "solver_slip_direction": solved.slip_direction,
            "edge_lam_mu": orientation * float(estimate.lam) / MU,
            "edge_tau": orientation
            * float(tension_share(float(estimate.eta), float(estimate.a1), MU)),
            "elements": elements,
            "element": h,
            "a1": float(estimate.a1),
            "b_solver": b,
            "b_error_elements": solved.bound / h,
            "steps_change_elements": None
            if solved.steps_change is None
            else solved.steps_change / h,
            "width_elements": width / h,
            "b_accuracy_elements": float(estimate.b_accuracy) / h,
            **{key: float(value) for key, value in estimate.validity.items()},
            "validity_warning": int(max(estimate.validity.values()) > VALIDITY_THRESHOLD),
        }
        for name in ESTIMATES:
            value = getattr(estimate, name)
            difference = None if value is None else float(value) - b
            row[f"{name}_elements"] = None if difference is None else difference / h
            row[f"{name}_fraction"] = (
                _fraction(difference, width) if difference is not None and slipping else None
            )
        rows.append(row)
    return rows


def error_map(
    cases: Sequence[MapCase] | None = None,
    *,
    elements: int = ELEMENTS,
    progress: Callable[[int, int], None] | None = None,
) -> list[dict[str, Any]]:
    """Run the solver over ``cases`` (default: the whole map); two rows per case.

    Parameters
    ----------
    cases
        The cycles; default :func:`map_cases`.
    elements
        Solver elements (default ``ELEMENTS``).
    progress
        Called as ``progress(done, total)`` after each case.

    Examples
    --------
    >>> from asymslip.solver.error_map import MapCase, error_map
    >>> rows = error_map([MapCase("hertz", 1.05, 2.0, 0.0)], elements=1000)
    >>> [row["edge"] for row in rows], abs(rows[0]["b_exact_elements"]) < 1
    (['right', 'left'], True)
    """
    cases = map_cases() if cases is None else tuple(cases)
    rows: list[dict[str, Any]] = []
    for done, case in enumerate(cases, start=1):
        rows.extend(solve_case(case, elements=elements))
        if progress is not None:
            progress(done, len(cases))
    return rows


# --- the CSV ------------------------------------------------------------------------------------
def _header() -> list[str]:
    laws = "; ".join(f"{name}: {description}" for name, (_, description) in LAWS.items())
    return [
        "# asymslip error map: the reference solver's permanent stick boundary b_solver against "
        "every estimate of slip_zone, per edge.  Written by `make error-map` "
        "(asymslip.solver.error_map); do not edit.",
        f"# Cycles: mu = {MU:g}, a1 = {A1:g}, P1 = P(a1), P2 = P(a2_a1 a1), Q1 = sigma1 = 0, "
        "Q2 = lam dP, sigma2 = eta dP; lam_mu = lam/mu, tau = pi eta a1/(4 mu).",
        f"# Laws: {laws}.",
        "# other_edge: how the other edge slips in the global frame (same, opposite, none; "
        "slips where this edge does not); slip_direction (slip_zone) and "
        "solver_slip_direction: +1 forward, -1 backward, 0 none, in the edge's own frame; "
        "edge_lam_mu, edge_tau: the edge's own forward-frame slopes.",
        f"# Solver: elements N, {STEPS} load step per half-cycle (b extrapolated from {STEPS} "
        f"and {2 * STEPS} where an edge does not slip; steps_change_elements the change), "
        "element = its width; b_error_elements: the bound on b_solver.",
        "# width_elements = (a1 - b_solver)/element; b_accuracy_elements: b's stated accuracy; "
        "eq24-eq27: the validity measures of slip_zone; validity_warning: 1 where one exceeds "
        f"{VALIDITY_THRESHOLD:g} (slip_zone warns that the asymptotic solution is doubtful).",
        "# <estimate>_elements = (estimate - b_solver)/element; <estimate>_fraction = "
        "(estimate - b_solver)/(a1 - b_solver); empty where the estimate does not exist "
        "(b_exact with tension) or the edge does not slip.",
    ]


def _formatted(value: Any, fmt: str) -> str:
    if value is None:
        return ""
    if fmt == "s":
        return str(value)
    if fmt == "d":
        return f"{int(value):d}"
    text = format(float(value), fmt)
    # No "-0.000": a value that rounds to zero is written without a sign.
    return text[1:] if text.startswith("-") and float(text) == 0 else text


def csv_text(rows: Iterable[dict[str, Any]]) -> str:
    """The CSV: comment lines, a header row, one row per edge, numbers in fixed formats."""
    lines = [*_header(), ",".join(COLUMNS)]
    for row in rows:
        lines.append(",".join(_formatted(row[key], fmt) for key, fmt in COLUMNS.items()))
    return "\n".join(lines) + "\n"


def read_csv(text: str) -> list[dict[str, str]]:
    """The rows of an error-map CSV as text fields (comment lines skipped)."""
    body = [line for line in text.splitlines() if line and not line.startswith("#")]
    if not body or body[0].split(",") != list(COLUMNS):
        raise InputError(
            "error_map.csv",
            "is not an error map of this version (its header row differs): run `make error-map`",
        )
    return list(csv.DictReader(io.StringIO("\n".join(body))))


def case_of(row: dict[str, str]) -> MapCase:
    """The cycle a CSV row belongs to."""
    return MapCase(row["law"], float(row["a2_a1"]), float(row["lam_mu"]), float(row["tau"]))


def _last_place(text: str) -> float:
    """One unit in the last printed place of a number written by :func:`_formatted`."""
    mantissa, _, exponent = text.lower().partition("e")
    decimals = len(mantissa.partition(".")[2])
    return 10.0 ** (-decimals + (int(exponent) if exponent else 0))


def row_differences(committed: dict[str, str], fresh: dict[str, str]) -> list[str]:
    """The fields of a fresh row that differ from the committed one at the printed precision.

    Text fields must be equal; numbers may differ by one unit in the last printed place (a
    value recomputed on another machine may round the other way).
    """
    out = []
    for key, fmt in COLUMNS.items():
        old, new = committed.get(key, ""), fresh.get(key, "")
        if old == new:
            continue
        if fmt in ("s", "d") or not old or not new:
            out.append(f"{key}: committed {old!r}, now {new!r}")
            continue
        if abs(float(old) - float(new)) > 1.0001 * _last_place(old):
            out.append(f"{key}: committed {old}, now {new}")
    return out


def compare_texts(committed_text: str, fresh_text: str) -> list[str]:
    """Differences between a committed map and freshly computed rows, one line each.

    The committed map must hold the grid's number of rows, and every fresh row must be in it
    and equal at the printed precision (:func:`row_differences`).  Empty when fresh.
    """
    committed, fresh = read_csv(committed_text), read_csv(fresh_text)
    problems = []
    expected = 2 * len(map_cases())
    if expected != len(committed):
        problems.append(f"the committed map has {len(committed)} rows; the grid gives {expected}")
    keyed = {(case_of(row), row["edge"]): row for row in committed}
    for row in fresh:
        key = (case_of(row), row["edge"])
        label = (
            f"{row['law']} a2/a1 = {row['a2_a1']}, lam/mu = {row['lam_mu']}, "
            f"tau = {row['tau']}, {row['edge']} edge"
        )
        if key not in keyed:
            problems.append(f"{label}: missing from the committed map")
            continue
        problems.extend(f"{label}: {text}" for text in row_differences(keyed[key], row))
    return problems


def stale_rows(committed_text: str, cases: Sequence[MapCase] | None = None) -> list[str]:
    """Recompute ``cases`` (default ``CHECK_CASES``: a few seconds) and compare them with the
    committed CSV text (:func:`compare_texts`; ``cases`` = :func:`map_cases` checks every row).
    """
    cases = [MapCase(*case) for case in CHECK_CASES] if cases is None else cases
    return compare_texts(committed_text, csv_text(error_map(cases)))
