"""What a user waits for before any work: imports in a fresh interpreter, and ``make generate``.

Imports: each statement runs in a fresh interpreter that times it from the inside (interpreter
start-up excluded), with its bytecode cached in a scratch folder as an install's is, the
statements interleaved round by round, best of N, by the child's CPU time (the import's own
work; waiting for a busy core left out) with the wall clock beside it.
``make generate``: ``python -m asymslip.codegen generate`` (what the target runs) into a scratch
root -- every derivation, every language, the report -- best of N by the CPU time of the child
(SymPy works on one thread), the wall clock beside it.
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from .timing import Row, duration, interleaved, times, verdict

ROOT = Path(__file__).resolve().parents[2]
IMPORT_TARGET = 1.5
GENERATE_TARGET = 20.0  # seconds

#: What a user runs first; ``import asymslip`` alone is lazy (PEP 562) and loads nothing.
IMPORTS = {
    "numpy": "import numpy",
    "asymslip": "from asymslip import HertzLaw, LoadCycle, slip_zone",
    "asymslip_gen": "from asymslip_gen import *",  # the package is lazy; * loads every module
}


def _import_seconds(statement: str, cache: str) -> tuple[float, float]:
    """(CPU, wall) seconds of ``statement`` in a fresh interpreter whose bytecode is cached in
    ``cache``, as an installed package's is (pip compiles it; an environment with
    PYTHONDONTWRITEBYTECODE would otherwise time the compilation of every source file of
    asymslip while NumPy loads its installed bytecode)."""
    environment = {
        key: value for key, value in os.environ.items() if key != "PYTHONDONTWRITEBYTECODE"
    }
    environment["PYTHONPYCACHEPREFIX"] = cache
    code = (
        "import time; cpu, wall = time.process_time(), time.perf_counter(); "
        f"{statement}; "
        "print(time.process_time() - cpu, time.perf_counter() - wall)"
    )
    completed = subprocess.run(
        [sys.executable, "-c", code],
        cwd=ROOT,
        capture_output=True,
        text=True,
        check=True,
        env=environment,
    )
    cpu, wall = completed.stdout.split()
    return float(cpu), float(wall)


def bench_imports(rounds: int) -> list[Row]:
    seconds: dict[str, list[float]] = {name: [] for name in IMPORTS}
    walls: dict[str, list[float]] = {name: [] for name in IMPORTS}
    names = list(IMPORTS)
    with tempfile.TemporaryDirectory() as cache:
        for name in names:  # one untimed import each writes the bytecode
            _import_seconds(IMPORTS[name], cache)
        for round_index in range(rounds):
            shift = round_index % len(names)
            for name in names[shift:] + names[:shift]:
                cpu, wall = _import_seconds(IMPORTS[name], cache)
                seconds[name].append(cpu)
                walls[name].append(wall)
    best = {name: min(values) for name, values in seconds.items()}
    per_round = sorted(a / n for a, n in zip(seconds["asymslip"], seconds["numpy"], strict=True))
    median = per_round[len(per_round) // 2]
    wall_ratio = min(walls["asymslip"]) / min(walls["numpy"])
    how = (
        f"fresh interpreters timing the import from inside, bytecode cached as after an "
        f"install, CPU time of the child, best of "
        f"{rounds} interleaved rounds; median per-round ratio {median:.2f}x; wall clock "
        f"{duration(min(walls['asymslip']))} vs {duration(min(walls['numpy']))}, "
        f"{times(wall_ratio)}"
    )
    ratio = best["asymslip"] / best["numpy"]
    return [
        Row(
            f"`{IMPORTS['asymslip']}` vs `import numpy`",
            duration(best["asymslip"]),
            duration(best["numpy"]),
            times(ratio),
            f"< {IMPORT_TARGET}x",
            verdict(ratio < IMPORT_TARGET),
            how,
        ),
        Row(
            "`from asymslip_gen import *` (every generated kernel) vs `import numpy`",
            duration(best["asymslip_gen"]),
            duration(best["numpy"]),
            times(best["asymslip_gen"] / best["numpy"]),
            "(information)",
            "-",
            how.split(";")[0],
        ),
    ]


def bench_generate(rounds: int) -> list[Row]:
    with tempfile.TemporaryDirectory() as scratch:
        command = [
            sys.executable,
            "-m",
            "asymslip.codegen",
            "generate",
            "--root",
            scratch,
            "--quiet",
        ]

        def generate() -> None:
            completed = subprocess.run(command, cwd=ROOT, capture_output=True, text=True)
            if completed.returncode != 0:
                tail = completed.stderr.strip().splitlines()[-1:] or ["?"]
                raise RuntimeError(f"generate failed: {tail[0]}")

        started = time.perf_counter()
        measured = interleaved({"generate": generate}, rounds, clock="cpu", warm_up=False)
        total = time.perf_counter() - started
    best = measured.best("generate")
    wall = measured.best("generate", "wall")
    return [
        Row(
            f"`make generate` (every derivation, 4 languages, the report), best of {rounds}",
            duration(best),
            "",
            "",
            f"< {GENERATE_TARGET:g} s",
            verdict(best < GENERATE_TARGET),
            f"CPU time of the child processes (SymPy runs on one thread), "
            f"`python -m asymslip.codegen generate` into a scratch root; wall clock best "
            f"{duration(wall)}, {duration(total)} for all {rounds}",
        )
    ]
