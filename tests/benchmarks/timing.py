"""Timing on a shared, noisy machine: interleaved rounds, best of N, per-round ratios.

Two clocks.  Work done by this process on one thread (NumPy ufuncs, the core, SciPy's quad) is
timed by the **CPU time of the process** (user + system, ``time.process_time``): on an idle
machine it equals the wall time, and on a busy one it leaves out the time spent waiting for a
core, which is the largest noise when five other people share two cores.  Work that uses
threads (pyarrow's reader and writer) or other processes (the command line, fresh
interpreters) is timed by the **wall clock**.  Each row says which.

Every ratio in ``make bench`` is taken inside one process from candidates timed in the same
rounds: each round runs every candidate once (in an order rotated from round to round, so that
no candidate always runs right after the same neighbour), and a candidate's figure is its best
round -- the least disturbed by other work on the cores.  The ratio reported is the ratio of
the bests; the median over rounds of the ratio *within* a round (two figures taken seconds
apart, under the same load) is given beside it as a check: when the two disagree by much, the
machine was too busy for the figure to mean much, and the row says so.
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


@dataclass(frozen=True)
class Timing:
    """The wall times of one candidate over the rounds, in seconds (per call)."""

    times: tuple[float, ...]

    @property
    def best(self) -> float:
        return min(self.times)

    @property
    def median(self) -> float:
        return statistics.median(self.times)


@dataclass(frozen=True)
class Timings:
    """Every candidate of one interleaved measurement."""

    by_name: dict[str, Timing]
    rounds: int
    clock: str = "cpu"

    def __getitem__(self, name: str) -> Timing:
        return self.by_name[name]

    def ratio(self, name: str, baseline: str) -> float:
        """Best over best."""
        return self[name].best / self[baseline].best

    def round_ratio(self, name: str, baseline: str) -> float:
        """Median over rounds of the ratio within a round."""
        pairs = zip(self[name].times, self[baseline].times, strict=True)
        return statistics.median(value / base for value, base in pairs)

    def how(self, name: str, baseline: str, calls: int = 1) -> str:
        """How the ratio was measured, with its per-round check."""
        per_call = f", {calls:,} calls a round" if calls > 1 else ""
        text = (f"{CLOCK_WORDS[self.clock]}, best of {self.rounds} interleaved rounds{per_call}; "
                f"median per-round ratio "
                f"{self.round_ratio(name, baseline):.2f}x")  # fmt: skip
        if self.rounds >= 3 and not _agree(self.ratio(name, baseline),
                                           self.round_ratio(name, baseline)):  # fmt: skip
            text += " (they disagree: the machine was busy, trust neither much)"
        return text


def _agree(first: float, second: float, tolerance: float = 0.25) -> bool:
    return abs(first - second) <= tolerance * max(first, second)


CLOCKS: dict[str, Callable[[], float]] = {"cpu": time.process_time, "wall": time.perf_counter}
CLOCK_WORDS = {"cpu": "CPU time of this process (one thread)", "wall": "wall clock"}


def interleaved(candidates: Mapping[str, Callable[[], object]], rounds: int, calls: int = 1,
                clock: str = "cpu", warm_up: bool = True) -> Timings:  # fmt: skip
    """Time each candidate ``calls`` times a round for ``rounds`` rounds, interleaved.

    ``clock`` is ``"cpu"`` (the process's CPU time: single-threaded work in this process) or
    ``"wall"``.  With ``warm_up`` each candidate is called once before timing (imports,
    caches, first-touch page faults of its buffers do not count).  Times are per call.
    """
    now = CLOCKS[clock]
    names = list(candidates)
    if warm_up:
        for function in candidates.values():
            function()
    times: dict[str, list[float]] = {name: [] for name in names}
    for round_index in range(rounds):
        shift = round_index % len(names)
        for name in names[shift:] + names[:shift]:
            function = candidates[name]
            start = now()
            for _ in range(calls):
                function()
            times[name].append((now() - start) / calls)
    return Timings({name: Timing(tuple(times[name])) for name in names}, rounds, clock)


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
    lines = ["| " + " | ".join(COLUMNS) + " |",
             "| --- | ---: | ---: | ---: | --- | --- | --- |"]  # fmt: skip
    for section in sections:
        lines.append(f"| **{section.title}** |  |  |  |  |  |  |")
        for row in section.rows:
            cells = (row.measure, row.measured, row.baseline, row.ratio, row.target, row.met,
                     row.how)  # fmt: skip
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
        text += (f" Load average {load_at_start:.2f} at the start and {load_at_end:.2f} at the "
                 f"end of the run")  # fmt: skip
        if busy > 0.5 * cores:
            text += (f": other work shared the {cores} cores, so absolute times are pessimistic "
                     "and ratios are the figures to read (each from interleaved rounds in one "
                     "process)")  # fmt: skip
        text += "."
    return text
