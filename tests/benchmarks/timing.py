"""Timing on a shared, noisy machine: interleaved rounds, two clocks, best of N, per-round ratios.

Every candidate is timed by two clocks at once:

* the **CPU time** it costs: this process's user + system time (every thread of it) plus that
  of the child processes it waited for.  On an idle machine, for one-thread work, it equals
  the wall time; on a busy one it leaves out the time spent waiting for a core -- the largest
  noise when five other people share two cores.  Work done on one thread (NumPy ufuncs, the
  core, SciPy's quad, SymPy in ``generate``, imports) is judged by it.
* the **wall clock**, which is what a user waits for.  Work spread over threads (pyarrow's CSV
  reader and writer in the sweep) is judged by it, since there CPU time and waiting differ
  even on an idle machine.

Every ratio is taken inside one process from candidates timed in the same rounds: each round
runs every candidate once, in an order rotated from round to round (so that no candidate always
follows the same neighbour).  By CPU time a candidate's figure is its best round and the ratio
is best over best; the median over rounds of the ratio *within* a round is given beside it as a
check, and when the two disagree by more than 25 % the row says the machine was too busy to
trust either.  By the wall clock the best round is mostly a matter of luck on a loaded machine,
so the ratio is the median of the per-round ratios (two runs seconds apart, under about the
same load), with best over best and the CPU-time ratio beside it.
"""

from __future__ import annotations

import os
import platform
import statistics
import time
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

try:
    import resource
except ImportError:  # not on Windows: the CPU time of child processes is then not counted
    resource = None  # type: ignore[assignment]


def cpu_time() -> float:
    """CPU seconds used so far by this process (all threads) and its waited-for children."""
    used = time.process_time()
    if resource is not None:
        children = resource.getrusage(resource.RUSAGE_CHILDREN)
        used += children.ru_utime + children.ru_stime
    return used


CLOCKS: dict[str, Callable[[], float]] = {"cpu": cpu_time, "wall": time.perf_counter}
CLOCK_WORDS = {"cpu": "CPU time", "wall": "wall clock"}


@dataclass(frozen=True)
class Timing:
    """One candidate's seconds per call, round by round, by both clocks."""

    cpu: tuple[float, ...]
    wall: tuple[float, ...]

    def times(self, clock: str) -> tuple[float, ...]:
        return self.cpu if clock == "cpu" else self.wall


@dataclass(frozen=True)
class Timings:
    """Every candidate of one interleaved measurement; ``clock`` is the one that judges."""

    by_name: dict[str, Timing]
    rounds: int
    clock: str = "cpu"

    def best(self, name: str, clock: str | None = None) -> float:
        return min(self.by_name[name].times(clock or self.clock))

    def round_ratio(self, name: str, baseline: str, clock: str | None = None) -> float:
        """Median over rounds of the ratio within a round."""
        clock = clock or self.clock
        pairs = zip(
            self.by_name[name].times(clock), self.by_name[baseline].times(clock), strict=True
        )
        return statistics.median(value / base for value, base in pairs)

    def best_ratio(self, name: str, baseline: str, clock: str | None = None) -> float:
        return self.best(name, clock) / self.best(baseline, clock)

    def ratio(self, name: str, baseline: str) -> float:
        """The ratio the row reports: best over best by CPU time, the per-round median by wall."""
        if self.clock == "cpu":
            return self.best_ratio(name, baseline)
        return self.round_ratio(name, baseline)

    def how(self, name: str, baseline: str, calls: int = 1) -> str:
        """How the ratio was measured, with its check."""
        per_call = f", {calls:,} calls a round" if calls > 1 else ""
        text = f"{CLOCK_WORDS[self.clock]}, best of {self.rounds} interleaved rounds{per_call}; "
        if self.clock == "cpu":
            text += f"median per-round ratio {self.round_ratio(name, baseline):.2f}x"
            if self.rounds >= 3 and not _agree(
                self.best_ratio(name, baseline), self.round_ratio(name, baseline)
            ):
                text += " (they disagree: the machine was busy, trust neither much)"
            return text
        return (
            text + f"ratio = median of the per-round ratios (best over best "
            f"{self.best_ratio(name, baseline):.2f}x; by CPU time "
            f"{self.best_ratio(name, baseline, 'cpu'):.2f}x)"
        )

    def clock_words(self, calls: int = 1) -> str:
        per_call = f", {calls:,} calls a round" if calls > 1 else ""
        return f"{CLOCK_WORDS[self.clock]}, best of {self.rounds} interleaved rounds{per_call}"


def _agree(first: float, second: float, tolerance: float = 0.25) -> bool:
    return abs(first - second) <= tolerance * max(first, second)


def interleaved(
    candidates: Mapping[str, Callable[[], object]],
    rounds: int,
    calls: int = 1,
    clock: str = "cpu",
    warm_up: bool = True,
) -> Timings:
    """Time each candidate ``calls`` times a round for ``rounds`` rounds, interleaved.

    Both clocks are read; ``clock`` (``"cpu"`` or ``"wall"``) is the one the rows judge by.
    With ``warm_up`` each candidate is called once before timing (imports, caches, first-touch
    page faults of its buffers do not count).  Times are per call.
    """
    names = list(candidates)
    if warm_up:
        for function in candidates.values():
            function()
    cpu: dict[str, list[float]] = {name: [] for name in names}
    wall: dict[str, list[float]] = {name: [] for name in names}
    for round_index in range(rounds):
        shift = round_index % len(names)
        for name in names[shift:] + names[:shift]:
            function = candidates[name]
            cpu_start, wall_start = cpu_time(), time.perf_counter()
            for _ in range(calls):
                function()
            wall[name].append((time.perf_counter() - wall_start) / calls)
            cpu[name].append((cpu_time() - cpu_start) / calls)
    return Timings(
        {name: Timing(tuple(cpu[name]), tuple(wall[name])) for name in names}, rounds, clock
    )


# --- rows of the table ----------------------------------------------------------------------------
@dataclass
class Row:
    """One line of the table; ``met`` is "yes", "**no**" or "-" (no target)."""

    measure: str
    measured: str
    baseline: str = ""
    ratio: str = ""
    target: str = "-"
    met: str = "-"
    how: str = ""


@dataclass
class Section:
    """The rows of one part of the benchmark, and how long measuring them took."""

    title: str
    rows: list[Row] = field(default_factory=list)
    seconds: float = 0.0
    failed: bool = False


COLUMNS = ("Measure", "Measured", "Baseline", "Ratio", "Target", "Met", "How measured")


def verdict(ok: bool) -> str:
    return "yes" if ok else "**no**"


def duration(value: float) -> str:
    """A time with three significant figures, in the unit that reads best."""
    for unit, scale in (("s", 1.0), ("ms", 1e-3), ("µs", 1e-6), ("ns", 1e-9)):
        if value >= scale:
            return f"{_significant(value / scale)} {unit}"
    return f"{value:.2g} s"


def _significant(value: float) -> str:
    return f"{value:,.0f}" if value >= 100 else f"{value:.3g}"


def times(value: float) -> str:
    """A ratio: ``1.23x``, or ``2.5e+05x`` when large."""
    if value < 1000:
        return f"{value:.2f}x"
    return f"{value:.2g}x".replace("e+0", "e").replace("e+", "e")


def count(value: int) -> str:
    """``10^6`` for a power of ten, ``2,000`` otherwise."""
    exponent = len(str(value)) - 1
    return f"10^{exponent}" if value == 10**exponent and exponent >= 2 else f"{value:,}"


def markdown(sections: list[Section]) -> str:
    """The table: one header, each section's rows under a bold section line."""
    lines = ["| " + " | ".join(COLUMNS) + " |", "| --- | ---: | ---: | ---: | --- | --- | --- |"]
    for section in sections:
        lines.append(f"| **{section.title}** |  |  |  |  |  |  |")
        for row in section.rows:
            cells = (
                row.measure,
                row.measured,
                row.baseline,
                row.ratio,
                row.target,
                row.met,
                row.how,
            )
            lines.append("| " + " | ".join(cell.replace("|", "\\|") for cell in cells) + " |")
    return "\n".join(lines)


# --- the machine ----------------------------------------------------------------------------------
def load_average() -> float | None:
    """The 1-minute load average (runnable processes), None where the system has none."""
    return os.getloadavg()[0] if hasattr(os, "getloadavg") else None


def cpu_model() -> str:
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown CPU"


def versions() -> str:
    """Python and the libraries whose speed the figures depend on."""
    found = [f"Python {platform.python_version()}", f"NumPy {np.__version__}"]
    for module in ("pyarrow", "scipy", "sympy"):
        try:
            found.append(f"{module} {__import__(module).__version__}")
        except ImportError:
            found.append(f"{module} missing")
    return ", ".join(found)


def machine(load_at_start: float | None, load_at_end: float | None) -> str:
    """CPU, cores, versions and the load on the cores during the run."""
    cores = os.cpu_count() or 1
    text = f"{cpu_model()}, {cores} cores; {versions()}."
    if load_at_start is not None and load_at_end is not None:
        busy = max(load_at_start, load_at_end)
        text += (
            f" Load average {load_at_start:.2f} at the start and {load_at_end:.2f} at the "
            f"end of the run"
        )
        if busy > 0.5 * cores:
            text += (
                f": other work shared the {cores} cores, so absolute times are pessimistic "
                "and ratios are the figures to read (each from interleaved rounds in one "
                "process)"
            )
        text += "."
    return text
