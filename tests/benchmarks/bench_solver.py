"""Cost of the reference solver against the number of elements N (for ``make bench``).

The paper's Fig. 5 cycle (Hertz, R = E* = 1, P1 = 100, Q1 = 0, P2 = 105, Q2 = 1, mu = 0.1),
from the first loading to the steady state, 20 load steps per half-cycle, on N = 500 ... 8000
elements.  Target (issue 11): N = 4000 in at most 10 s on the 2-core development machine (an
unoptimised dense prototype needed 41-73 s).  Each time is the best of ``repeat`` runs (the
least disturbed on a shared machine); the whole ``solve`` call is timed, domain choice and
post-processing included.

Run from the repository root: ``.venv/bin/python tests/benchmarks/bench_solver.py``.
"""

from __future__ import annotations

import argparse
import time
from collections.abc import Sequence

from asymslip import HertzLaw, LoadCycle
from asymslip.solver import solve

COUNTS = (500, 1000, 2000, 4000, 8000)
TARGET_COUNT, TARGET_SECONDS = 4000, 10.0


def solver_rows(
    counts: Sequence[int] = COUNTS, repeat: int = 3, steps: int = 20
) -> list[tuple[int, float, int, int]]:
    """(N, seconds, load steps, periods) for each N: the Fig. 5 cycle to its steady state."""
    law = HertzLaw(R=1.0, E_star=1.0)
    cycle = LoadCycle(P1=100.0, Q1=0.0, P2=105.0, Q2=1.0)
    rows = []
    for count in counts:
        best = float("inf")
        for _ in range(repeat):
            start = time.perf_counter()
            result = solve(law, cycle, 0.1, elements=count, steps=steps)
            best = min(best, time.perf_counter() - start)
        if not result.steady:
            raise RuntimeError(f"N = {count}: no steady state; the benchmark is meaningless")
        rows.append((count, best, result.load_steps, result.cycles))
    return rows


def markdown(rows: list[tuple[int, float, int, int]]) -> str:
    lines = [
        "| N | seconds | load steps | periods | target |",
        "| ---: | ---: | ---: | ---: | --- |",
    ]
    for count, seconds, steps, cycles in rows:
        target = ""
        if count == TARGET_COUNT:
            met = "met" if seconds <= TARGET_SECONDS else "missed"
            target = f"<= {TARGET_SECONDS:g} s: {met}"
        lines.append(f"| {count} | {seconds:.2f} | {steps} | {cycles} | {target} |")
    return "\n".join(lines)


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3, help="runs per N; the best is kept")
    parser.add_argument("--counts", type=int, nargs="+", default=list(COUNTS))
    args = parser.parse_args(argv)
    print(markdown(solver_rows(args.counts, args.repeat)))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
