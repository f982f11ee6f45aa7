"""The stress field: a 200 x 200 grid from the solver, the asymptote at 10^6 points (issue 18).

Targets of issue 18: the field on a 200 x 200 grid around one edge from N = 4000 solver
elements in at most 2 s, and the asymptotic amplitude at 10^6 points in at most 1 s, each as
a ratio against the strongest plain NumPy baseline written here:

* the grid: the solver's Fig. 5 cycle (N = 4000, solved once, outside the timing), both states
  and their difference at x in a2 +- 0.1 a, depth 0 to 0.2 a.  Baseline: the direct sum of
  every node for every point (``method="direct"``: the node kernel's logarithms as matrix-
  vector products, chunked), timed on a tenth of the grid's rows and scaled by ten (its cost
  is the same for every point: measured within 3 % of linear);
* the asymptote: :func:`asymslip.stress.asymptote.edge_amplitude` (amplitude only) at 10^6
  points near the right edge of the Fig. 5 cycle.  Baseline: the same field in NumPy's
  complex arithmetic, written out here from the potential -pi A sqrt(w) of each square-root
  load (no generated code).
"""

from __future__ import annotations

import time

import numpy as np

from asymslip import HertzLaw, LoadCycle
from asymslip.solver import solve
from asymslip.stress.asymptote import edge_amplitude, edge_loads
from asymslip.stress.half_plane import half_plane_stress
from asymslip.stress.solver_source import solver_load, solver_stress

from .timing import Row, duration, interleaved, times, verdict
from .timing import count as number

GRID_TARGET = 2.0
ASYMPTOTE_TARGET = 1.0
LAW, CYCLE, MU = HertzLaw(R=1.0, E_star=1.0), LoadCycle(100, 0, 105, 1), 0.1


def _grid(a: float, count: int) -> tuple[np.ndarray, np.ndarray]:
    return np.meshgrid(np.linspace(0.9 * a, 1.1 * a, count), np.linspace(0, 0.2 * a, count))


def bench_grid(count: int, elements: int, rounds: int) -> list[Row]:
    started = time.perf_counter()
    result = solve(LAW, CYCLE, MU, elements=elements)
    solve_seconds = time.perf_counter() - started
    a = float(LAW.half_width(CYCLE.P2))
    X, Y = _grid(a, count)
    rows = max(1, count // 10)
    Xs, Ys = X[:rows], Y[:rows]  # a tenth of the grid's rows for the direct baseline
    scale = X.size / Xs.size
    loads = [solver_load(result, state) for state in result.states]

    def direct() -> None:
        for load in loads:
            half_plane_stress(load, Xs, Ys, method="direct")

    measured = interleaved(
        {"fast": lambda: solver_stress(result, X, Y), "direct": direct}, rounds, warm_up=True
    )
    fast = measured.best("fast")
    baseline = measured.best("direct") * scale
    check = solver_stress(result, Xs, Ys)
    reference = [half_plane_stress(load, Xs, Ys, method="direct") for load in loads]
    agreement = max(
        float(np.max(np.abs(getattr(state, c) - state_ref.with_bulk(s.sigma).component(c))))
        for state, state_ref, s in zip(check.states, reference, result.states, strict=True)
        for c in ("sxx", "syy", "sxy")
    )
    p0 = 2 * CYCLE.P2 / (np.pi * a)
    return [
        Row(
            f"the field on a {count} x {count} grid near the right edge from N = "
            f"{number(elements)} solver elements (both states and their difference) vs the "
            "direct sum of every node",
            duration(fast),
            duration(baseline),
            f"{times(baseline / fast)} faster",
            f"<= {GRID_TARGET:g} s",
            verdict(fast <= GRID_TARGET),
            f"{measured.clock_words()}; the direct sum timed on {Xs.size:,} of the "
            f"{X.size:,} points and scaled by {scale:.0f}; Fig. 5 cycle, x in a2 +- 0.1 a2, "
            f"depth 0 to 0.2 a2",
        ),
        Row(
            "same: largest difference fast - direct over the tenth, / p0",
            f"{agreement / p0:.1e}",
            "",
            "",
            "<= 1e-10",
            verdict(agreement / p0 <= 1e-10),
            "the far nodes by a 34-term series per box of points (asymslip.stress.half_plane)",
        ),
        Row(
            f"the solve itself (N = {number(elements)}, Fig. 5 cycle to its steady state)",
            duration(solve_seconds),
            target="(information)",
            how="wall clock, once (not part of the grid's time)",
        ),
    ]


def complex_baseline(X: np.ndarray, Y: np.ndarray) -> tuple[np.ndarray, ...]:
    """The asymptotic amplitude in NumPy's complex arithmetic: potential -pi A sqrt(w) per
    square-root load (pressure A_p, shear A_q), F' = -pi A / (2 sqrt(w)), then sxx + syy =
    -(2/pi) Re(Q - i P), syy - sxx + 2 i sxy = (2/pi) (i y conj(Q' - i P') + conj(Q))."""
    loads = edge_loads(LAW, CYCLE, MU)
    Q = np.zeros(X.shape, dtype=complex)
    P = np.zeros(X.shape, dtype=complex)
    yQ = np.zeros(X.shape, dtype=complex)
    yP = np.zeros(X.shape, dtype=complex)
    with np.errstate(divide="ignore", invalid="ignore"):  # y/sqrt(w) at the edge point
        for load in loads.loads:
            root = np.sqrt((X - load.edge) - 1j * Y + 0j)
            slope = np.where(root != 0, Y / (2 * root), 0)
            Q -= np.pi * load.shear * root
            P -= np.pi * load.pressure * root
            yQ -= np.pi * load.shear * slope
            yP -= np.pi * load.pressure * slope
    F, yF = Q - 1j * P, yQ - 1j * yP
    trace = -2 / np.pi * F.real
    deviator = 2 / np.pi * (1j * np.conj(yF) + np.conj(Q))
    sxx = 0.5 * (trace - deviator.real) + loads.uniform
    return sxx, 0.5 * (trace + deviator.real), 0.5 * deviator.imag


def bench_asymptote(count: int, rounds: int, seed: int) -> list[Row]:
    a2 = float(LAW.half_width(CYCLE.P2))
    rng = np.random.default_rng(seed)
    X = a2 + 0.05 * a2 * rng.uniform(-1, 1, count)
    Y = 0.05 * a2 * rng.uniform(0, 1, count)
    measured = interleaved(
        {
            "generated": lambda: edge_amplitude(LAW, CYCLE, MU, X, Y, accuracy=False),
            "with accuracy": lambda: edge_amplitude(LAW, CYCLE, MU, X, Y),
            "complex": lambda: complex_baseline(X, Y),
        },
        rounds,
    )
    field = edge_amplitude(LAW, CYCLE, MU, X, Y, accuracy=False).amplitude
    baseline = complex_baseline(X, Y)
    scale = max(float(np.max(np.abs(v))) for v in baseline)
    agreement = (
        max(
            float(np.max(np.abs(getattr(field, c) - v)))
            for c, v in zip(("sxx", "syy", "sxy"), baseline, strict=True)
        )
        / scale
    )
    best = measured.best("generated")
    return [
        Row(
            f"asymptotic amplitude near an edge at {number(count)} points (`edge_amplitude`, "
            "accuracy off) vs the same field in NumPy complex arithmetic",
            duration(best),
            duration(measured.best("complex")),
            f"{times(measured.ratio('generated', 'complex'))}",
            f"<= {ASYMPTOTE_TARGET:g} s",
            verdict(best <= ASYMPTOTE_TARGET),
            measured.how("generated", "complex") + f"; agreement {agreement:.1e} of the field",
        ),
        Row(
            "same, with each point's stated accuracy (the next-order field)",
            duration(measured.best("with accuracy")),
            duration(best),
            f"{times(measured.ratio('with accuracy', 'generated'))}",
            "(information)",
            "-",
            measured.how("with accuracy", "generated"),
        ),
    ]
