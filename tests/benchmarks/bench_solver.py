"""The reference solver against today's, for ``make bench`` (issues 17 and 22).

The paper's Fig. 5 cycle (Hertz, R = E* = 1, P1 = 100, Q1 = 0, P2 = 105, Q2 = 1, mu = 0.1), from
the first loading to the steady state, 20 load steps per half-cycle, on N = 10^4, 10^5 and
10^6 elements.  Targets (issue 22): N = 10^5 in at most 10 s; time growing no faster than
N^1.1 from 10^4 to 10^6; a 10^6-element run within 2 GB; the stick boundary within 0.1 element
of today's.

*Today's solver* is the package at ``BASELINE_REF`` (main before the fast solver), unpacked by
``git archive`` into a temporary folder and run from there -- never a copy kept in the tree.
Every run is a fresh process (``python -c``), so that its peak resident memory is its own
(``VmHWM`` on Linux: ``ru_maxrss`` would count the parent it was forked from too); it reports
the wall clock and CPU time of ``solve`` alone.  Today's and the new
solver alternate round by round at each N; a figure is the best round, a ratio best over best.

"Quiet" runs have nothing else started by the benchmark; on a shared machine they still share
the cores with whatever else runs (the load average is in the table's machine line).  "Loaded"
runs have one busy process started beside them (a Python loop, the other core's worth of
work), once with OpenBLAS's default threads and once with one thread (``OPENBLAS_NUM_THREADS=1``):
issue 17 found today's solver 4-8 times slower at N >= 16,000 with the default threads there.
Today's solver runs the quiet rounds with one BLAS thread, its faster setting on a busy machine.

Run from the repository root: ``.venv/bin/python -m tests.benchmarks.bench_solver [--quick]``.
"""

from __future__ import annotations

import argparse
import contextlib
import io
import json
import math
import os
import subprocess
import sys
import tarfile
import tempfile
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path

from .timing import Row, count, duration, verdict

ROOT = Path(__file__).resolve().parents[2]
#: main at the start of issue 22: the solver the targets compare with.
BASELINE_REF = "a2c7a9f249f28cfd3c434324541736e33f23b18c"
COUNTS = (10_000, 100_000, 1_000_000)
QUICK_COUNTS = (2_000, 20_000)
LOADED_COUNTS = (16_000, 100_000)
TARGET_COUNT, TARGET_SECONDS = 100_000, 10.0
TARGET_EXPONENT = 1.1
MEMORY_COUNT, TARGET_BYTES = 1_000_000, 2 * 10**9
TARGET_ELEMENTS = 0.1
THREAD_VARIABLES = ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")
#: A run not finished in this time is reported as such (and the benchmark goes on).
TIMEOUT_SECONDS = 3600

CHILD = """
import json, resource, sys, time
from asymslip import HertzLaw, LoadCycle
from asymslip.solver import solve
elements = int(sys.argv[1])
wall, cpu = time.perf_counter(), time.process_time()
result = solve(HertzLaw(R=1.0, E_star=1.0), LoadCycle(100.0, 0.0, 105.0, 1.0), 0.1,
               elements=elements, steps=20)
wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
try:  # the peak of this process image (ru_maxrss also counts the parent it was forked from)
    peak = [int(line.split()[1]) * 1024 for line in open("/proc/self/status")
            if line.startswith("VmHWM:")][0]
except OSError:
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
print(json.dumps({
    "wall": wall, "cpu": cpu, "peak": peak,
    "b_right": result.right.b, "b_left": result.left.b, "element": result.element_size,
    "steps": result.load_steps, "periods": result.cycles, "steady": result.steady,
}))
"""


@dataclass(frozen=True)
class Run:
    """One solve in a fresh process."""

    solver: str  # "new" or "today"
    elements: int
    threads: str  # "default" or "1"
    loaded: bool
    wall: float
    cpu: float
    peak: int  # bytes
    b_right: float
    b_left: float
    element: float
    steps: int
    periods: int


@contextlib.contextmanager
def todays_solver(ref: str = BASELINE_REF) -> Iterator[Path | None]:
    """A folder holding today's ``src`` and ``generated`` (from git), or None without git."""
    try:
        archive = subprocess.run(
            ["git", "-C", str(ROOT), "archive", "--format=tar", ref, "src", "generated"],
            capture_output=True,
            check=True,
        ).stdout
    except (OSError, subprocess.CalledProcessError):
        yield None
        return
    with tempfile.TemporaryDirectory(prefix="asymslip-today-") as folder:
        with tarfile.open(fileobj=io.BytesIO(archive)) as tar:
            # The "data" filter refuses links and paths out of the folder; tarfile has it from
            # Python 3.11.4 (Debian's 3.11.2 has not), and git's own archive needs no filter.
            if hasattr(tarfile, "data_filter"):
                tar.extractall(folder, filter="data")
            else:
                tar.extractall(folder)
        yield Path(folder)


@contextlib.contextmanager
def busy_core(loaded: bool) -> Iterator[None]:
    """One busy process beside the measured one while the block runs (if ``loaded``)."""
    if not loaded:
        yield
        return
    loop = subprocess.Popen([sys.executable, "-c", "while True: pass"])
    try:
        yield
    finally:
        loop.terminate()
        loop.wait()


def run_once(tree: Path | None, elements: int, threads: str, loaded: bool) -> Run | None:
    """Solve the Fig. 5 cycle in a fresh process: the new solver, or today's from ``tree``.

    None when it did not finish within ``TIMEOUT_SECONDS``.
    """
    env = {key: value for key, value in os.environ.items() if key not in THREAD_VARIABLES}
    if threads == "1":
        env.update({variable: "1" for variable in THREAD_VARIABLES})
    if tree is not None:
        env["PYTHONPATH"] = os.pathsep.join([str(tree / "src"), str(tree / "generated")])
    with busy_core(loaded):
        try:
            completed = subprocess.run(
                [sys.executable, "-c", CHILD, str(elements)],
                env=env,
                capture_output=True,
                text=True,
                cwd=tempfile.gettempdir(),  # not the repository: the tree on PYTHONPATH decides
                timeout=TIMEOUT_SECONDS,
            )
        except subprocess.TimeoutExpired:
            return None
    if completed.returncode:
        raise RuntimeError(f"N = {elements}: the solve failed: {completed.stderr.strip()}")
    data = json.loads(completed.stdout)
    if not data.pop("steady"):
        raise RuntimeError(f"N = {elements}: no steady state; the benchmark is meaningless")
    return Run("today" if tree is not None else "new", elements, threads, loaded, **data)


@dataclass(frozen=True)
class Measurements:
    runs: tuple[Run, ...]
    counts: tuple[int, ...]
    repeat: int
    with_today: bool
    unfinished: tuple[tuple[str, int, str, bool], ...] = ()

    def best(self, solver: str, elements: int, threads: str, loaded: bool) -> Run | None:
        chosen = [
            r
            for r in self.runs
            if (r.solver, r.elements, r.threads, r.loaded) == (solver, elements, threads, loaded)
        ]
        return min(chosen, key=lambda r: r.wall) if chosen else None


def measure(
    counts: Sequence[int] = COUNTS,
    repeat: int = 3,
    loaded_counts: Sequence[int] = LOADED_COUNTS,
    with_today: bool = True,
) -> Measurements:
    """Interleaved rounds of today's solver and the new one, quiet and loaded."""
    runs: list[Run] = []
    unfinished: list[tuple[str, int, str, bool]] = []

    def keep(tree: Path | None, elements: int, threads: str, loaded: bool) -> None:
        run = run_once(tree, elements, threads, loaded)
        if run is None:
            unfinished.append(("today" if tree else "new", elements, threads, loaded))
        else:
            runs.append(run)

    with todays_solver() if with_today else contextlib.nullcontext() as tree:
        for elements in counts:
            rounds = repeat if elements < 10**6 else 1  # a 10^6 round takes minutes
            for _ in range(rounds):
                if tree is not None:
                    keep(tree, elements, "1", False)
                keep(None, elements, "default", False)
        for elements in loaded_counts:
            keep(None, elements, "default", True)
            if tree is not None:
                keep(tree, elements, "default", True)
                keep(tree, elements, "1", True)
        return Measurements(tuple(runs), tuple(counts), repeat, tree is not None, tuple(unfinished))


def growth_exponent(counts: Sequence[int], seconds: Sequence[float]) -> float:
    """p of seconds ~ N^p, least squares in log-log."""
    x = [math.log(value) for value in counts]
    y = [math.log(value) for value in seconds]
    mean_x, mean_y = sum(x) / len(x), sum(y) / len(y)
    return sum((a - mean_x) * (b - mean_y) for a, b in zip(x, y, strict=True)) / sum(
        (a - mean_x) ** 2 for a in x
    )


def memory(size: float) -> str:
    return f"{size / 1e9:.2f} GB" if size >= 1e9 else f"{size / 1e6:.0f} MB"


def faster(today: float, new: float) -> str:
    return f"{today / new:.2f}x faster"


UNFINISHED = f"did not finish within {TIMEOUT_SECONDS // 60} min"


def rows(data: Measurements) -> list[Row]:
    """The table's rows: times, growth, memory, answers, loaded."""
    out: list[Row] = []
    for elements in data.counts:
        new = data.best("new", elements, "default", False)
        today = data.best("today", elements, "1", False)
        rounds = data.repeat if elements < 10**6 else 1
        measure = f"reference solver, Fig. 5 cycle to its steady state, N = {count(elements)}"
        if new is None:
            out.append(Row(measure, f"skipped: {UNFINISHED}"))
            continue
        target, met = "(information)", "-"
        if elements == TARGET_COUNT:
            target, met = f"<= {TARGET_SECONDS:g} s", verdict(new.wall <= TARGET_SECONDS)
        how = (
            f"wall clock of `solve` in a fresh process, best of {rounds} round(s)"
            + (" alternating with today's (1 BLAS thread)" if data.with_today else "")
            + f"; CPU time {duration(new.cpu)}"
            + (f" (today's {duration(today.cpu)})" if today else "")
            + f"; {new.steps} load steps, {new.periods} periods"
            + (f" (today's {today.steps} and {today.periods})" if today else "")
            + (f"; today's {UNFINISHED}" if today is None and data.with_today else "")
        )
        out.append(
            Row(
                measure,
                duration(new.wall),
                duration(today.wall) if today else "",
                faster(today.wall, new.wall) if today else "",
                target,
                met,
                how,
            )
        )
    finished = [n for n in data.counts if data.best("new", n, "default", False) is not None]
    if len(finished) >= 2:
        best = [data.best("new", n, "default", False) for n in finished]
        walls = [run.wall for run in best if run is not None]
        cpus = [run.cpu for run in best if run is not None]
        judged = finished[0] == COUNTS[0] and finished[-1] == COUNTS[-1]
        exponent = growth_exponent(finished, walls)
        out.append(
            Row(
                f"same: growth of the time with N, {count(finished[0])} to {count(finished[-1])}",
                f"N^{exponent:.2f}",
                "",
                "",
                f"<= N^{TARGET_EXPONENT:g}" if judged else "(information)",
                verdict(exponent <= TARGET_EXPONENT) if judged else "-",
                "least-squares slope of log wall clock on log N",
            )
        )
        out.append(
            Row(
                "same, by CPU time",
                f"N^{growth_exponent(finished, cpus):.2f}",
                how="least-squares slope of log CPU time on log N (what a quiet machine sees)",
            )
        )
    largest = data.counts[-1]
    new = data.best("new", largest, "default", False)
    today = data.best("today", largest, "1", False)
    if new is not None:
        judged = largest == MEMORY_COUNT
        out.append(
            Row(
                f"peak memory of a solve, N = {count(largest)}",
                memory(new.peak),
                memory(today.peak) if today else "",
                f"{today.peak / new.peak:.2f}x" if today else "",
                f"<= {TARGET_BYTES / 1e9:g} GB" if judged else "(information)",
                verdict(new.peak <= TARGET_BYTES) if judged else "-",
                "peak resident memory of the process (`VmHWM`), interpreter and NumPy "
                "included; ratio = today's / new",
            )
        )
    for elements in data.counts:
        new = data.best("new", elements, "default", False)
        today = data.best("today", elements, "1", False)
        if new is None or today is None:
            continue
        difference = max(abs(new.b_right - today.b_right), abs(new.b_left - today.b_left))
        difference /= new.element
        out.append(
            Row(
                f"stick boundary, new against today's, N = {count(elements)}",
                f"{difference:.1e} elements".replace("e+00", "").replace("0.0 ", "0 "),
                target=f"<= {TARGET_ELEMENTS:g} element",
                met=verdict(difference <= TARGET_ELEMENTS),
                how="largest |b_new - b_today| of the two edges, in elements",
            )
        )
    for elements in sorted({r.elements for r in data.runs if r.loaded}):
        new = data.best("new", elements, "default", True)
        if new is None:
            continue
        for threads in ("default", "1"):
            today = data.best("today", elements, threads, True)
            words = "default BLAS threads" if threads == "default" else "one BLAS thread"
            out.append(
                Row(
                    f"same, one busy process beside it, N = {count(elements)}: new against "
                    f"today's with {words}",
                    duration(new.wall),
                    duration(today.wall) if today else "",
                    faster(today.wall, new.wall) if today else "",
                    how="wall clock, one run each; the new solver with the default BLAS threads "
                    f"(it calls no BLAS); CPU time {duration(new.cpu)}"
                    + (f" (today's {duration(today.cpu)})" if today else f"; today's {UNFINISHED}"),
                )
            )
    return out


def solver_rows(quick: bool, repeat: int) -> list[Row]:
    """The section of ``make bench`` (``--quick``: two small grids, no loaded runs)."""
    if quick:
        data = measure(QUICK_COUNTS, 1, (), with_today=True)
    else:
        data = measure(COUNTS, repeat, LOADED_COUNTS, with_today=True)
    return rows(data)


def main(argv: Sequence[str] | None = None) -> int:
    from .timing import Section, markdown

    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="two small grids, one round")
    parser.add_argument("--repeat", type=int, default=3, help="rounds below 10^6 elements")
    args = parser.parse_args(argv)
    print(markdown([Section("Reference solver", solver_rows(args.quick, args.repeat))]))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
