"""Benchmark suite for ``make bench``: ratios measured in one process, printed as Markdown.

Run from the repository root: ``.venv/bin/python tests/benchmarks/run_benchmarks.py``.
Needs the ``bench`` extra (scipy) for section (b) and the ``derive`` extra (SymPy) for the
lambdify baseline of section (a).  Nothing here asserts: the test suite has no timing
assertions; the table states each target and whether this run met it.

(a) Generated ``stick_boundary_proportional`` (22) and ``slip_zone_width`` over 10^7 load
    states, against a hand-written NumPy transcription of (22), against ``sympy.lambdify`` of
    the same derived expression without CSE, and against a memory-bound floor (one pass summing
    the input arrays).  Targets: within 1.3x of hand-written, within 4x of the floor.
(b) Generated closed-form ``traction_difference`` (49) at 10^6 points against
    ``scipy.integrate.quad(weight="cauchy")`` per point on a small sample, scaled to the same
    count.  Target: >= 1e4 times faster at 1e-10 agreement.
(c) ``generate`` wall time (target < 20 s) and ``import asymslip`` against ``import numpy`` in
    fresh interpreters (target < 1.5x).
(d) The million-case sweep end to end, once ``asymslip sweep`` exists.

Timings are best-of-N (minimum over repeats: the least disturbed run on a shared machine) on
float64 arrays prepared before timing.
"""

from __future__ import annotations

import argparse
import inspect
import os
import platform
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from dataclasses import dataclass
from functools import cache, partial
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
DERIVATIONS = ROOT / "derivations"


@dataclass
class Row:
    """One line of the results table."""

    benchmark: str
    measured: str
    baseline: str
    ratio: str
    target: str
    met: str


def skipped(benchmark: str, why: str, target: str = "-") -> Row:
    return Row(benchmark, f"skipped: {why}", "", "", target, "-")


def best_of(function: Callable[[], object], repeat: int) -> float:
    """Smallest wall time of ``repeat`` calls, in seconds."""
    return best_of_each([function], repeat)[0]


def best_of_each(functions: list[Callable[[], object]], repeat: int) -> list[float]:
    """Smallest wall time of each function over ``repeat`` rounds, the rounds interleaved.

    Interleaving exposes every candidate to the same load on a shared machine, so the ratios
    are fairer than timing one candidate after another.
    """
    best = [float("inf")] * len(functions)
    for _ in range(repeat):
        for index, function in enumerate(functions):
            start = time.perf_counter()
            function()
            best[index] = min(best[index], time.perf_counter() - start)
    return best


def seconds(value: float) -> str:
    if value >= 1:
        return f"{value:.2f} s"
    if value >= 1e-3:
        return f"{value * 1e3:.1f} ms"
    return f"{value * 1e6:.1f} µs"


def verdict(ok: bool) -> str:
    return "yes" if ok else "**no**"


def machine() -> str:
    """CPU model, core count, NumPy and Python versions, and the load at the start."""
    model = platform.processor() or "unknown CPU"
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    load = ""
    if hasattr(os, "getloadavg"):
        load = f", load average {os.getloadavg()[0]:.2f}"
    return (
        f"{model}, {os.cpu_count()} cores{load}; Python {platform.python_version()}, "
        f"NumPy {np.__version__}"
    )


# --------------------------------------------------------------------------------------------
# (a) stick boundary and slip-zone width over many load states
# --------------------------------------------------------------------------------------------


def load_states(count: int, seed: int) -> dict[str, np.ndarray]:
    """Valid proportional-path inputs of (22): float64, contiguous, made before any timing."""
    rng = np.random.default_rng(seed)
    mu = rng.uniform(0.05, 1.5, count)
    lam = rng.uniform(-2.0, 2.0, count)
    eta = rng.uniform(-0.5, 0.5, count)
    a1 = rng.uniform(0.5, 2.0, count)
    da = a1 * 10.0 ** rng.uniform(-8.0, -1.0, count)
    L_I1 = rng.uniform(0.5, 2.0, count)
    L_I2 = L_I1 * (1.0 + da / a1 / 4.0)
    return {
        "mu": mu, "lam": lam, "eta": eta, "a1": a1, "a2": a1 + da, "da": da,
        "L_I1": L_I1, "L_I2": L_I2,
    }  # fmt: skip


def hand_stick_boundary(mu, lam, eta, a1, a2, L_I1, L_I2):
    """(22) transcribed by hand: b = (C2 a2 + C1 a1) / (C2 + C1)."""
    c2 = (1.0 - lam / mu - np.pi * a2 / 4.0 * eta / mu) * L_I2
    c1 = (1.0 + lam / mu + np.pi * a1 / 4.0 * eta / mu) * L_I1
    return (c2 * a2 + c1 * a1) / (c2 + c1)


def hand_slip_zone_width(mu, lam, eta, a1, da, L_I1, L_I2):
    """a1 - b from (22) by hand, reduced to -C2 da / (C1 + C2) so that it does not cancel."""
    c2 = (1.0 - lam / mu - np.pi * (a1 + da) / 4.0 * eta / mu) * L_I2
    c1 = (1.0 + lam / mu + np.pi * a1 / 4.0 * eta / mu) * L_I1
    return -c2 * da / (c1 + c2)


@cache
def _emitted_formulas() -> dict[str, object]:
    from asymslip.codegen.loader import import_derivation

    # The script that emits both functions of section (a).
    section2_calibrations = import_derivation(DERIVATIONS, "section2_calibrations")
    return {formula.name: formula for formula in section2_calibrations.derive().formulas}


def lambdified(name: str) -> tuple[Callable[..., np.ndarray], tuple[str, ...]] | None:
    """``sympy.lambdify`` (no CSE) of the expression the derivation emits as ``name``."""
    try:
        import sympy
    except ImportError:
        return None
    formula = _emitted_formulas().get(name)
    if formula is None:
        return None
    symbols = [arg.symbol for arg in formula.args]
    function = sympy.lambdify(symbols, formula.expr, modules="numpy", cse=False)
    return function, tuple(arg.name for arg in formula.args)


def floor_sum(arrays: list[np.ndarray]) -> np.ndarray:
    """Read every input once and write one output: the memory-bound floor."""
    out = np.add(arrays[0], arrays[1])
    for array in arrays[2:]:
        np.add(out, array, out=out)
    return out


def bench_load_states(count: int, repeat: int, seed: int) -> list[Row]:
    from asymslip_gen.corrective_slip import slip_zone_width, stick_boundary_proportional

    states = load_states(count, seed)
    rows: list[Row] = []
    cases = [
        ("stick_boundary_proportional", stick_boundary_proportional, hand_stick_boundary,
         ("mu", "lam", "eta", "a1", "a2", "L_I1", "L_I2")),
        ("slip_zone_width", slip_zone_width, hand_slip_zone_width,
         ("mu", "lam", "eta", "a1", "da", "L_I1", "L_I2")),
    ]  # fmt: skip
    for name, generated, hand, names in cases:
        arrays = [states[n] for n in names]
        # Agreement first (the same numbers, or the comparison means nothing).
        reference = hand(*arrays)
        spread = np.max(np.abs(generated(*arrays) - reference) / np.abs(reference))
        print(f"  {name}: generated vs hand-written max relative difference {spread:.1e}",
              file=sys.stderr)  # fmt: skip
        candidates = [partial(generated, *arrays), partial(hand, *arrays),
                      partial(floor_sum, arrays)]  # fmt: skip
        lambdified_function = lambdified(name)
        if lambdified_function is not None:
            function, order = lambdified_function
            candidates.append(partial(function, *[states[n] for n in order]))
        t_generated, t_hand, t_floor, *t_lambdify = best_of_each(candidates, repeat)
        label = f"`{name}`, {count:.0e} states vs"
        rows.append(Row(f"{label} hand-written (22)", seconds(t_generated), seconds(t_hand),
                        f"{t_generated / t_hand:.2f}x", "<= 1.3x",
                        verdict(t_generated <= 1.3 * t_hand)))  # fmt: skip
        if t_lambdify:
            rows.append(Row(f"{label} sympy.lambdify (no CSE)", seconds(t_generated),
                            seconds(t_lambdify[0]), f"{t_generated / t_lambdify[0]:.2f}x",
                            "(information)", "-"))  # fmt: skip
        else:
            rows.append(skipped(f"{label} sympy.lambdify", "SymPy not installed"))
        rows.append(Row(f"{label} memory floor (one summing pass)", seconds(t_generated),
                        seconds(t_floor), f"{t_generated / t_floor:.2f}x", "<= 4x",
                        verdict(t_generated <= 4 * t_floor)))  # fmt: skip
    return rows


# --------------------------------------------------------------------------------------------
# (b) closed-form traction difference (49) against Cauchy-weighted quadrature
# --------------------------------------------------------------------------------------------


def fig5_problem() -> dict[str, float]:
    """The paper's Fig. 5 example (R = E* = 1, mu = 0.1, lam = 0.2, P1 = 100, dP = 5)."""
    from asymslip_gen.corrective_slip import stick_boundary
    from asymslip_gen.hertz import hertz_half_width, hertz_normal_edge_multiplier

    R, E_star, mu, lam, P1, dP = 1.0, 1.0, 0.1, 0.2, 100.0, 5.0
    a1, a2 = hertz_half_width(P1, R, E_star), hertz_half_width(P1 + dP, R, E_star)
    L_I1 = hertz_normal_edge_multiplier(P1, R, E_star)
    L_I2 = hertz_normal_edge_multiplier(P1 + dP, R, E_star)
    L_II1, L_II2 = lam * L_I1, lam * L_I2  # (21) with eta = 0
    b = stick_boundary(mu, a1, a2, L_I1, L_I2, L_II1, L_II2)
    values = {"b": b, "a1": a1, "a2": a2, "mu": mu, "L_I1": L_I1, "L_I2": L_I2,
              "L_II1": L_II1, "L_II2": L_II2, "E_star": E_star}  # fmt: skip
    return {key: float(value) for key, value in values.items()}


def quad_traction_difference(x: float, p: dict[str, float]) -> float:
    """(49) with the density (15) integrated by QUADPACK's Cauchy-weighted rule (QAWC).

    q = L_II2 sqrt(a2 - x) - L_II1 H(a1 - x) sqrt(a1 - x)
        - E*/(2 pi sqrt(a2 - x)) PV int_b^a2 sqrt(a2 - t) B(t) dt / (t - x),
    the integral split at a1, where B has a square-root kink.
    """
    from scipy.integrate import quad

    from asymslip_gen.corrective_slip import dislocation_density

    density_args = tuple(p[k] for k in ("b", "a1", "mu", "L_I1", "L_I2", "L_II1", "L_II2"))

    def weighted(t: float) -> float:
        density = dislocation_density(t, *density_args, p["E_star"])
        return float(np.sqrt(max(p["a2"] - t, 0.0)) * density)

    integral = 0.0
    for low, high in ((p["b"], p["a1"]), (p["a1"], p["a2"])):
        options = {"epsabs": 0.0, "epsrel": 1e-12, "limit": 200}
        if low < x < high:
            value, _ = quad(weighted, low, high, weight="cauchy", wvar=x, **options)
        else:
            value, _ = quad(lambda t: weighted(t) / (t - x), low, high, **options)
        integral += value
    edge = p["L_II2"] * np.sqrt(p["a2"] - x) - p["L_II1"] * np.sqrt(max(p["a1"] - x, 0.0))
    return float(edge - p["E_star"] / (2 * np.pi * np.sqrt(p["a2"] - x)) * integral)


def closed_form_traction_difference() -> Callable[..., np.ndarray] | None:
    """The generated closed form of (49), under its current or its planned name."""
    try:
        from asymslip_gen import tractions
    except ImportError:
        return None
    for name in ("shear_traction_difference", "traction_difference"):
        if hasattr(tractions, name):
            return getattr(tractions, name)
    return None


def bench_traction_difference(count: int, sample: int, repeat: int) -> list[Row]:
    title = "closed-form q_diff (49) vs scipy quad (cauchy)"
    function = closed_form_traction_difference()
    if function is None:
        print("  (b) skipped: the closed form of (49) is not generated yet", file=sys.stderr)
        return [skipped(title, "`asymslip_gen.tractions` not generated yet", ">= 1e4x")]
    try:
        import scipy  # noqa: F401
    except ImportError:
        return [skipped(title, "scipy not installed (the bench extra)", ">= 1e4x")]
    p = fig5_problem()
    # Called by parameter name: E* cancels in the closed form, which may not take it.
    arguments = {name: p[name] for name in inspect.signature(function).parameters if name != "x"}
    # Points over the contact half 0 <= x < a2, avoiding the breakpoints b and a1 exactly.
    x = np.linspace(0.0, p["a2"], count, endpoint=False) + 0.5 * p["a2"] / count
    t_closed = best_of(partial(function, x, **arguments), repeat)
    x_sample = x[:: max(1, count // sample)][:sample]
    start = time.perf_counter()
    quadrature = np.array([quad_traction_difference(float(xi), p) for xi in x_sample])
    t_quad = (time.perf_counter() - start) * count / len(x_sample)
    closed = np.asarray(function(x_sample, **arguments), dtype=np.float64)
    # Relative to the traction scale: q_diff passes through zero inside the contact.
    agreement = float(np.max(np.abs(closed - quadrature)) / np.max(np.abs(quadrature)))
    speedup = t_quad / t_closed
    return [
        Row(f"`{function.__name__}` (49), {count:.0e} points vs scipy quad (cauchy), "
            f"{len(x_sample)} points scaled", seconds(t_closed), seconds(t_quad),
            f"{speedup:.1e}x faster", ">= 1e4x", verdict(speedup >= 1e4)),
        Row("agreement: max abs(closed - quad) / max abs(quad)", f"{agreement:.1e}", "", "",
            "<= 1e-10", verdict(agreement <= 1e-10)),
    ]  # fmt: skip


# --------------------------------------------------------------------------------------------
# (c) generate wall time and import time
# --------------------------------------------------------------------------------------------


def bench_generate(runs: int) -> list[Row]:
    times = []
    for _ in range(runs):
        with tempfile.TemporaryDirectory() as scratch:
            command = [sys.executable, "-m", "asymslip.codegen", "generate",
                       "--root", scratch, "--quiet"]  # fmt: skip
            start = time.perf_counter()
            completed = subprocess.run(command, cwd=ROOT, capture_output=True, text=True)
            times.append(time.perf_counter() - start)
            if completed.returncode != 0:
                tail = completed.stderr.strip().splitlines()[-1:] or ["?"]
                return [Row("`generate` wall time", f"failed: {tail[0]}", "", "", "< 20 s", "-")]
    best = min(times)
    return [Row(f"`generate` wall time (best of {runs})", seconds(best), "", "", "< 20 s",
                verdict(best < 20))]  # fmt: skip


#: What a user runs first; `import asymslip` alone is lazy (PEP 562) and loads nothing.
IMPORT_STATEMENTS = {
    "numpy": "import numpy",
    "asymslip": "from asymslip import HertzLaw, LoadCycle, slip_zone",
    "asymslip_gen": "import asymslip_gen",
}


def import_time(module: str, repeat: int) -> float:
    """Best import time of ``module`` in fresh interpreters (interpreter start-up excluded)."""
    code = (
        "import time; start = time.perf_counter(); "
        f"{IMPORT_STATEMENTS[module]}; print(time.perf_counter() - start)"
    )
    times = []
    for _ in range(repeat):
        completed = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True,
                                   text=True, check=True)  # fmt: skip
        times.append(float(completed.stdout.strip()))
    return min(times)


def bench_import(repeat: int) -> list[Row]:
    t_numpy = import_time("numpy", repeat)
    rows = []
    for module in ("asymslip", "asymslip_gen"):
        try:
            t_module = import_time(module, repeat)
        except subprocess.CalledProcessError as error:
            rows.append(Row(f"`import {module}`", f"failed: {error.stderr.strip()[-80:]}", "",
                            "", "< 1.5x", "-"))  # fmt: skip
            continue
        target, met = ("< 1.5x", verdict(t_module < 1.5 * t_numpy)) if module == "asymslip" else (
            "(information)", "-")  # fmt: skip
        rows.append(Row(f"`{IMPORT_STATEMENTS[module]}` vs `import numpy` (fresh interpreters, "
                        f"best of {repeat})", seconds(t_module), seconds(t_numpy),
                        f"{t_module / t_numpy:.2f}x", target, met))  # fmt: skip
    return rows


# --------------------------------------------------------------------------------------------
# (d) the million-case sweep
# --------------------------------------------------------------------------------------------

SWEEP_ROWS = 10**6


def _write_cases(path: Path, rows: int, seed: int = 0) -> None:
    """Random valid Hertz cycles (both slip directions, no-slip rows, warnings), as a CSV."""
    rng = np.random.default_rng(seed)
    P1 = rng.uniform(50.0, 150.0, rows)
    dP = P1 * rng.uniform(1e-4, 0.1, rows)
    lam = rng.uniform(-1.0, 1.0, rows)
    table = np.column_stack([P1, np.zeros(rows), np.zeros(rows), P1 + dP, lam * dP, np.zeros(rows)])
    with path.open("w") as handle:
        handle.write("P1,Q1,sigma1,P2,Q2,sigma2\n")
        np.savetxt(handle, table, delimiter=",", fmt="%.17g")


def bench_sweep(rows: int = SWEEP_ROWS) -> list[Row]:
    """`asymslip sweep` end to end (read, evaluate both edges, write), in a subprocess."""
    with tempfile.TemporaryDirectory() as scratch:
        cases = Path(scratch) / "cases.csv"
        _write_cases(cases, rows)
        command = [sys.executable, "-m", "asymslip", "sweep", str(cases), "--law", "hertz",
                   "--R", "1", "--E-star", "1", "--mu", "0.3", "--out",
                   str(Path(scratch) / "results.csv")]  # fmt: skip
        start = time.perf_counter()
        completed = subprocess.run(command, cwd=ROOT, capture_output=True, text=True)
        elapsed = time.perf_counter() - start
    label = f"`asymslip sweep` of {rows:.0e} load cases, both edges, end to end"
    if completed.returncode != 0:
        tail = completed.stderr.strip().splitlines()[-1:] or ["?"]
        return [Row(label, f"failed: {tail[0]}", "", "", "-", "-")]
    return [Row(label, seconds(elapsed), "", f"{rows / elapsed:,.0f} rows/s", "-", "-")]


# --------------------------------------------------------------------------------------------


def table(rows: list[Row]) -> str:
    lines = [
        "| Benchmark | Measured | Baseline | Ratio | Target | Met |",
        "| --- | ---: | ---: | ---: | --- | --- |",
    ]
    for row in rows:
        lines.append(f"| {row.benchmark} | {row.measured} | {row.baseline} | {row.ratio} | "
                     f"{row.target} | {row.met} |")  # fmt: skip
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--states", type=int, default=10**7, help="load states for (a)")
    parser.add_argument("--points", type=int, default=10**6, help="traction points for (b)")
    parser.add_argument("--quad-sample", type=int, default=200, help="points quad evaluates")
    parser.add_argument("--repeat", type=int, default=5, help="best of N for array timings")
    parser.add_argument("--import-repeat", type=int, default=7, help="best of N for imports")
    parser.add_argument("--generate-runs", type=int, default=1, help="best of N for generate")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--skip", default="", help="sections to skip, e.g. 'cd'")
    args = parser.parse_args(argv)

    rows: list[Row] = []
    sections = [
        ("a", "stick boundary / slip-zone width",
         lambda: bench_load_states(args.states, args.repeat, args.seed)),
        ("b", "closed-form tractions",
         lambda: bench_traction_difference(args.points, args.quad_sample, args.repeat)),
        ("c", "generate and import", lambda: bench_generate(args.generate_runs)
         + bench_import(args.import_repeat)),
        ("d", "sweep", bench_sweep),
    ]  # fmt: skip
    for key, title, run in sections:
        if key in args.skip:
            continue
        print(f"({key}) {title} ...", file=sys.stderr, flush=True)
        rows.extend(run())
    print(f"Machine: {machine()}\n")
    print(table(rows))
    return 0


if __name__ == "__main__":
    sys.exit(main())
