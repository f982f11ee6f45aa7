"""``make bench``: issue 10's targets against the strongest honest baselines, as one table.

Run from the repository root::

    .venv/bin/python -m tests.benchmarks.run_benchmarks [--quick] [--markdown FILE]
                     [--only scalar,laws,...] [--skip generate,...]

Prints the table (Markdown) on stdout, each section's rows on stderr as soon as they are
measured, and with ``--markdown FILE`` writes the same text to FILE (for the README).  Every
row says how it was measured.  Nothing asserts a timing: a missed target is a row that says
**no**; a section that cannot run (an extra missing) says why; a section that fails is a
"failed" row and the exit status is 1.

Sections (the modules beside this one):

scalar     one ``slip_zone(..., edge="both")`` vs the kernel it wraps       (bench_core)
laws       10^6 cycles through ``evaluate``: each law / Hertz               (bench_core)
sweep      10^6 Hertz rows to CSV, API and command line, vs the floor;
           Parquet vs CSV                                                   (bench_sweep)
kernels    generated (22) and the slip-zone width vs hand-written NumPy
           with ``out=`` buffers, ``lambdify(cse=True)``, the memory floor  (bench_kernels)
tractions  closed-form (49) vs ``quad(weight="cauchy")``                     (bench_tractions)
imports    ``from asymslip import ...`` vs ``import numpy``                 (bench_startup)
generate   ``make generate``, best of 3                                    (bench_startup)
solver     the reference solver's cost against N, if ``bench_solver.py``
           exists                                                          (bench_solver_hook)
stress     a 200 x 200 grid from N = 4000 solver elements vs the direct
           sum; the edge asymptote at 10^6 points vs complex NumPy          (bench_stress)
dask       solve-batch (200 solves) and the sweep (10^7 rows) on 2 local
           Dask workers vs one process; the overhead of a task             (bench_batch)

Noise (the machine is shared): every ratio comes from candidates interleaved in the same
rounds in one process, best of N, with the median of the per-round ratios beside it;
single-threaded work is timed by the process's CPU time (see :mod:`.timing`).
"""

from __future__ import annotations

import argparse
import sys
import time
import traceback
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from asymslip.files.atomic import atomic_write

from .timing import Row, Section, load_average, machine, markdown


@dataclass(frozen=True)
class Sizes:
    """How much each section measures (``--quick`` shrinks them all)."""

    scalar_rounds: int = 7
    scalar_calls: int = 2000
    cycles: int = 10**6
    law_rounds: int = 5
    rows: int = 10**6
    sweep_rounds: int = 5
    states: int = 10**7
    kernel_rounds: int = 7
    points: int = 10**6
    quad_points: int = 200
    traction_rounds: int = 3
    import_rounds: int = 11
    generate_rounds: int = 3
    solver_repeat: int = 3
    stress_grid: int = 200
    stress_elements: int = 4000
    stress_rounds: int = 3


QUICK = Sizes(
    scalar_rounds=3,
    scalar_calls=50,
    cycles=10**4,
    law_rounds=2,
    rows=2000,
    sweep_rounds=1,
    states=10**4,
    kernel_rounds=2,
    points=10**4,
    quad_points=2,
    traction_rounds=1,
    import_rounds=1,
    generate_rounds=0,
    solver_repeat=1,
    stress_grid=20,
    stress_elements=400,
    stress_rounds=1,
)


Measure = Callable[[], list[Row]]


def sections(sizes: Sizes, quick: bool, seed: int) -> dict[str, tuple[str, Measure]]:
    """Key -> (title, measure); imported lazily so that one missing extra skips one section."""

    def scalar() -> list[Row]:
        from .bench_core import bench_scalar

        return bench_scalar(sizes.scalar_rounds, sizes.scalar_calls)

    def laws() -> list[Row]:
        from .bench_core import bench_laws

        return bench_laws(sizes.cycles, sizes.law_rounds)

    def sweep() -> list[Row]:
        from .bench_sweep import bench_sweep

        return bench_sweep(sizes.rows, sizes.sweep_rounds)

    def kernels() -> list[Row]:
        from .bench_kernels import bench_kernels

        return bench_kernels(sizes.states, sizes.kernel_rounds, seed)

    def tractions() -> list[Row]:
        from .bench_tractions import bench_tractions

        return bench_tractions(sizes.points, sizes.quad_points, sizes.traction_rounds)

    def imports() -> list[Row]:
        from .bench_startup import bench_imports

        return bench_imports(sizes.import_rounds)

    def generate() -> list[Row]:
        if sizes.generate_rounds < 1:
            return [Row("`make generate`", "skipped: --quick (about 20 s a run)", target="< 20 s")]
        from .bench_startup import bench_generate

        return bench_generate(sizes.generate_rounds)

    def solver() -> list[Row]:
        from .bench_solver_hook import bench_solver

        return bench_solver(quick, sizes.solver_repeat)

    def stress() -> list[Row]:
        from .bench_stress import bench_asymptote, bench_grid

        return bench_grid(
            sizes.stress_grid, sizes.stress_elements, sizes.stress_rounds
        ) + bench_asymptote(sizes.points, sizes.stress_rounds, seed)

    def dask() -> list[Row]:
        from .bench_batch import bench_batch

        return bench_batch(quick)

    return {
        "scalar": ("One scalar call", scalar),
        "laws": ("Cycles in bulk, law against law", laws),
        "sweep": ("The sweep against its floor", sweep),
        "kernels": ("Generated kernels against the strongest baselines", kernels),
        "tractions": ("Closed-form (49) against quadrature", tractions),
        "imports": ("Import time", imports),
        "generate": ("Code generation", generate),
        "solver": ("Reference solver", solver),
        "stress": ("The stress field near an edge", stress),
        "dask": ("Parameter studies on Dask", dask),
    }


def run(keys: list[str], table: dict[str, tuple[str, Measure]]) -> list[Section]:
    done = []
    for key in keys:
        title, measure = table[key]
        print(f"[{key}] {title} ...", file=sys.stderr, flush=True)
        section = Section(title)
        start = time.perf_counter()
        try:
            section.rows = measure()
        except Exception as error:  # one broken section must not hide the others' figures
            traceback.print_exc(file=sys.stderr)
            section.rows = [Row(f"{title}: failed", f"{type(error).__name__}: {error}")]
            section.failed = True
        section.seconds = time.perf_counter() - start
        print(markdown([section]) + f"\n({section.seconds:.1f} s)\n", file=sys.stderr, flush=True)
        done.append(section)
    return done


def _keys(text: str, known: list[str], option: str) -> list[str]:
    keys = [key.strip() for key in text.split(",") if key.strip()]
    unknown = [key for key in keys if key not in known]
    if unknown:
        raise SystemExit(
            f"{option}: unknown section {', '.join(unknown)} (known: {', '.join(known)})"
        )
    return keys


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument(
        "--quick",
        action="store_true",
        help="small sizes, one or two rounds: a smoke test in a few seconds",
    )
    parser.add_argument(
        "--markdown",
        type=Path,
        metavar="FILE",
        help="also write the table (and the machine line) to FILE",
    )
    parser.add_argument("--only", default="", help="comma-separated sections to run")
    parser.add_argument("--skip", default="", help="comma-separated sections to leave out")
    parser.add_argument("--seed", type=int, default=0, help="seed of the random inputs")
    args = parser.parse_args(argv)

    sizes = QUICK if args.quick else Sizes()
    table = sections(sizes, args.quick, args.seed)
    known = list(table)
    keys = _keys(args.only, known, "--only") or known
    skipped = set(_keys(args.skip, known, "--skip"))
    keys = [key for key in keys if key not in skipped]

    load_at_start = load_average()
    done = run(keys, table)
    load_at_end = load_average()
    mode = " (--quick: small sizes, the figures mean little)" if args.quick else ""
    text = f"Machine: {machine(load_at_start, load_at_end)}{mode}\n\n{markdown(done)}\n"
    print(text)
    if args.markdown is not None:
        with atomic_write(args.markdown, "markdown", mode="w") as handle:
            handle.write(text)
    return 1 if any(section.failed for section in done) else 0


if __name__ == "__main__":
    sys.exit(main())
