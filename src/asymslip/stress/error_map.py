"""The near-edge error map: the asymptotic amplitude against the solver and the exact field.

For a grid of the paper's cycles -- four contact laws (Hertz; a rounded flat, c = 1, R = 10;
power laws n = 1.5 and 3), a1 = 2, a2/a1 in ``RATIOS``, mu = 0.3 and the pairs ``PAIRS`` of
lambda/mu and tau = pi eta a1/(4 mu) (18): the other edge slipping the same way, the
opposite way or not at all, every pair at least 0.2 from either edge's threshold of slip (the
solver settles slowly at a threshold) -- and both edges, the amplitude of
:func:`~asymslip.stress.asymptote.edge_amplitude` is set against the reference solver's
(N = ``ELEMENTS``) on half circles of radius r about the state-2 edge (``ANGLES`` points from
the surface outside to the surface inside), r/a1 in ``DISTANCES``; for Hertz without tension
also against the exact Jaeger-Ciavarella field (47), a sum of semi-elliptic loads.

Each row gives, over its half circle, the largest error (every component) as a fraction of the
reference amplitude's largest component, the largest error over the stated accuracy, and the
stated accuracy as a fraction of the field; surface points within ``UNRESOLVED`` elements of
a1, a2 or the solver's b are left out of the solver rows (the solver's grid limits its own
field there: 3.9e-3 p0 on the surface next to an edge, ``tests/stress``) and counted.
``near_edge`` says whether every point was near the edge (no point warning), ``warned``
whether the cycle carries a validity warning.

Written with fixed formatting as ``generated/report/stress_error_map.csv`` (``make
stress-error-map``, a few minutes) and drawn as ``generated/figures/stress_error_map.png``;
summarised in the derivation report by ``derivations/stress_edge_asymptote.py`` (EA-7);
``--check`` recomputes the rows of a few cycles.

Examples
--------
>>> len(cases()), cases()[0]
(72, Case(law='hertz', ratio=1.02, lam_mu=1.5, tau=0.0))
"""

from __future__ import annotations

import argparse
import csv
import io
import sys
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..cycle import LoadCycle
from ..errors import InputError
from ..files.atomic import atomic_write
from ..laws import FlatRoundedLaw, HertzLaw, PowerLaw
from ..laws.base import ContactLaw
from ..slip_zones import slip_zone
from ..solver import solve
from .asymptote import Side, edge_amplitude, edge_loads
from .field import StressField
from .semi_elliptic import SemiEllipticLoad, semi_elliptic_stress
from .solver_source import solver_stress

CSV_FILE = "stress_error_map.csv"
PNG_FILE = "stress_error_map.png"
ELEMENTS = 4000
RATIOS = (1.02, 1.05, 1.10)
PAIRS = ((1.5, 0.0), (2.0, 0.0), (3.0, 0.0), (2.0, 0.2), (1.0, 1.5), (0.5, 2.0))
DISTANCES = (0.005, 0.01, 0.02, 0.05, 0.1, 0.2)
ANGLES = 25
UNRESOLVED = 3
MU = 0.3
A1 = 2.0
#: The cycles --check recomputes (law, a2/a1, lambda/mu, tau).
CHECKED = (("hertz", 1.05, 2.0, 0.0), ("flat-rounded", 1.05, 2.0, 0.2))
COLUMNS = (
    "law",
    "a2_a1",
    "lam_mu",
    "tau",
    "edge",
    "slip_direction",
    "reference",
    "r_a1",
    "points",
    "excluded",
    "near_edge",
    "warned",
    "error_fraction",
    "error_over_stated",
    "stated_fraction",
)


def laws() -> dict[str, ContactLaw]:
    return {
        "hertz": HertzLaw(R=1.0, E_star=1.0),
        "flat-rounded": FlatRoundedLaw(c=1.0, R=10.0, E_star=1.0),
        "power-1.5": PowerLaw(A=0.3, n=1.5, E_star=1.0),
        "power-3": PowerLaw(A=0.05, n=3.0, E_star=1.0),
    }


@dataclass(frozen=True)
class Case:
    law: str
    ratio: float
    lam_mu: float
    tau: float

    def cycle(self, law: ContactLaw) -> LoadCycle:
        P1, P2 = float(law.load(A1)), float(law.load(A1 * self.ratio))
        dP = P2 - P1
        eta = self.tau * 4 * MU / (np.pi * A1)
        return LoadCycle(P1, 0.0, P2, self.lam_mu * MU * dP, 0.0, eta * dP)


def cases() -> list[Case]:
    return [
        Case(name, ratio, lam_mu, tau)
        for name in laws()
        for ratio in RATIOS
        for lam_mu, tau in PAIRS
    ]


def _number(value: float) -> str:
    return f"{value:.4g}"


def _exact(law: ContactLaw, cycle: LoadCycle, x: np.ndarray, y: np.ndarray) -> StressField:
    """The Jaeger-Ciavarella amplitude of a Hertz cycle without tension (47): the pressure
    change and -mu (p2 + p1 - 2 pK) on the lower body."""
    P1, P2 = float(cycle.P1), float(cycle.P2)
    P_K = (P1 + P2) / 2 - abs(float(cycle.Q2) - float(cycle.Q1)) / (2 * MU)
    direction = float(np.sign(float(cycle.Q2) - float(cycle.Q1)))

    def peak(P: float) -> float:
        return 2 * P / (np.pi * float(law.half_width(P)))

    loads = [
        SemiEllipticLoad(float(law.half_width(P2)), peak(P2), -direction * MU * peak(P2)),
        SemiEllipticLoad(float(law.half_width(P1)), -peak(P1), -direction * MU * peak(P1)),
        SemiEllipticLoad(float(law.half_width(P_K)), 0.0, 2 * direction * MU * peak(P_K)),
    ]
    return semi_elliptic_stress(loads, x, y)


def rows_of(case: Case) -> list[dict[str, str]]:
    law = laws()[case.law]
    cycle = case.cycle(law)
    result = solve(law, cycle, MU, elements=ELEMENTS)
    if not result.steady:
        # Measured on the rounded flat at a2/a1 = 1.10, lambda/mu = 3: with 20 load steps the
        # tractions still change by 1.7e-8 mu max p after 40 periods (the tolerance is 1e-8);
        # with one step per half-cycle (the solver's error map's choice: where both edges
        # slip the states do not depend on the steps) it settles in two.
        result = solve(law, cycle, MU, elements=ELEMENTS, steps=1)
    h = result.element_size
    zone = slip_zone(law, cycle, MU, edge="both")
    rows: list[dict[str, str]] = []
    sides: tuple[Side, Side] = ("right", "left")
    for side in sides:
        sign = 1.0 if side == "right" else -1.0
        edge_result = zone if side == "right" else zone.left
        assert edge_result is not None
        loads = edge_loads(law, cycle, MU, side)
        solver_b = result.edge(side).b
        marks = [loads.a1, loads.a2] + ([solver_b] if solver_b is not None else [])
        warned = bool(edge_result.warnings)
        references = ["solver"] + (["exact"] if case.law == "hertz" and case.tau == 0 else [])
        for r in DISTANCES:
            angles = np.linspace(0.0, np.pi, ANGLES)
            outward = loads.a2 + r * A1 * np.cos(angles)
            x, y = sign * outward, r * A1 * np.sin(angles)
            field = edge_amplitude(law, cycle, MU, x, y, edge=side)
            for reference in references:
                if reference == "solver":
                    truth = solver_stress(result, x, y).amplitude
                    distance = np.min(np.abs(outward[:, None] - np.array(marks)[None, :]), axis=1)
                    resolved = ~((y < UNRESOLVED * h) & (distance < UNRESOLVED * h))
                else:
                    truth = _exact(law, cycle, x, y)
                    resolved = np.ones(x.size, dtype=bool)
                assert truth is not None and field.amplitude is not None
                error = np.max(
                    np.abs(
                        np.stack(
                            [
                                field.amplitude.component(c) - truth.component(c)
                                for c in ("sxx", "syy", "sxy")
                            ]
                        )
                    ),
                    axis=0,
                )
                scale = max(
                    float(np.max(np.abs(truth.component(c)))) for c in ("sxx", "syy", "sxy")
                )
                assert field.accuracy is not None and field.near_edge is not None
                rows.append(
                    {
                        "law": case.law,
                        "a2_a1": _number(case.ratio),
                        "lam_mu": _number(case.lam_mu),
                        "tau": _number(case.tau),
                        "edge": side,
                        "slip_direction": str(int(edge_result.slip_direction)),
                        "reference": reference,
                        "r_a1": _number(r),
                        "points": str(x.size),
                        "excluded": str(int((~resolved).sum())),
                        "near_edge": "1" if field.near_edge.all() else "0",
                        "warned": "1" if warned else "0",
                        "error_fraction": _number(float(error[resolved].max()) / scale),
                        "error_over_stated": _number(
                            float(np.max(error[resolved] / field.accuracy[resolved]))
                        ),
                        "stated_fraction": _number(float(field.accuracy.max()) / scale),
                    }
                )
    return rows


def render(rows: Iterable[dict[str, str]]) -> str:
    buffer = io.StringIO()
    buffer.write(
        "# The near-edge error map: asymslip.stress.error_map (make stress-error-map); "
        f"N = {ELEMENTS}, mu = {MU}, a1 = {A1}\n"
    )
    writer = csv.DictWriter(buffer, COLUMNS, lineterminator="\n")
    writer.writeheader()
    writer.writerows(rows)
    return buffer.getvalue()


def read(text: str) -> list[dict[str, str]]:
    body = "\n".join(line for line in text.splitlines() if line and not line.startswith("#"))
    return list(csv.DictReader(io.StringIO(body)))


def draw(rows: Sequence[dict[str, str]], path: Path) -> Path:
    try:
        from matplotlib.figure import Figure
    except ImportError:
        raise InputError(
            "out", "drawing the error map needs matplotlib (the 'plot' extra)"
        ) from None
    figure = Figure(figsize=(11.0, 4.2))
    left, right = figure.subplots(1, 2)
    names = list(dict.fromkeys(row["law"] for row in rows))
    for name in names:
        for reference, marker in (("solver", "o"), ("exact", "s")):
            chosen = [r for r in rows if r["law"] == name and r["reference"] == reference]
            if not chosen:
                continue
            distances = sorted({float(r["r_a1"]) for r in chosen})
            worst = [
                max(float(r["error_fraction"]) for r in chosen if float(r["r_a1"]) == d)
                for d in distances
            ]
            ratio = [
                max(float(r["error_over_stated"]) for r in chosen if float(r["r_a1"]) == d)
                for d in distances
            ]
            label = f"{name} ({reference})"
            left.loglog(distances, worst, marker=marker, label=label)
            right.semilogx(distances, ratio, marker=marker, label=label)
    left.set_xlabel("r / a1 (distance from the state-2 edge)")
    left.set_ylabel("largest error / largest amplitude")
    left.set_title("asymptote vs reference, worst over the map")
    right.axhline(1.0, color="k", linewidth=0.8)
    right.set_xlabel("r / a1")
    right.set_ylabel("largest error / stated accuracy")
    right.set_title("the stated accuracy holds below 1")
    right.legend(fontsize=7)
    figure.tight_layout()
    with atomic_write(path, "out") as handle:
        figure.savefig(handle, format="png", dpi=110)
    return path


def stale_lines(folder: Path) -> list[str]:
    """Rows of the checked cycles that differ from the committed CSV (at its precision)."""
    path = folder / CSV_FILE
    if not path.is_file():
        raise InputError("check", f"no {CSV_FILE} in {folder}: run `make stress-error-map`")
    committed = read(path.read_text(encoding="utf-8"))
    problems = []
    for name, ratio, lam_mu, tau in CHECKED:
        case = Case(name, ratio, lam_mu, tau)
        keys = (case.law, _number(ratio), _number(lam_mu), _number(tau))
        old = [r for r in committed if (r["law"], r["a2_a1"], r["lam_mu"], r["tau"]) == keys]
        new = rows_of(case)
        if old != new:
            problems.append(f"{keys}: {len(old)} committed rows differ from {len(new)} computed")
    return problems


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m asymslip.stress.error_map")
    parser.add_argument("--data", type=Path, default=Path("generated/report"))
    parser.add_argument("--out", type=Path, default=Path("generated/figures"))
    parser.add_argument("--check", action="store_true", help="recompute a few cycles' rows")
    parser.add_argument("--redraw", action="store_true", help="draw the PNG from the CSV")
    args = parser.parse_args(argv)
    if args.check:
        problems = stale_lines(args.data)
        for problem in problems:
            print(problem, file=sys.stderr)
        if problems:
            print(f"{args.data / CSV_FILE} is stale: run `make stress-error-map`", file=sys.stderr)
            return 1
        print(f"{args.data / CSV_FILE}: {len(CHECKED)} cycles recomputed, fresh")
        return 0
    if args.redraw:
        rows = read((args.data / CSV_FILE).read_text(encoding="utf-8"))
    else:
        # Rows are kept in a partial file as each cycle is done, so that an interrupted run
        # resumes where it stopped; the CSV appears complete, or not at all.
        partial = args.data / ".stress_error_map.progress.csv"
        rows = read(partial.read_text(encoding="utf-8")) if partial.is_file() else []
        done = {(r["law"], r["a2_a1"], r["lam_mu"], r["tau"]) for r in rows}
        for index, case in enumerate(cases()):
            key = (case.law, _number(case.ratio), _number(case.lam_mu), _number(case.tau))
            if key in done:
                continue
            print(f"[{index + 1}/{len(cases())}] {case}", file=sys.stderr, flush=True)
            rows += rows_of(case)
            with atomic_write(partial, "data", mode="w") as handle:
                handle.write(render(rows))
        with atomic_write(args.data / CSV_FILE, "data", mode="w") as handle:
            handle.write(render(rows))
        partial.unlink()
    draw(rows, args.out / PNG_FILE)
    print(f"wrote {args.data / CSV_FILE} and {args.out / PNG_FILE}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
