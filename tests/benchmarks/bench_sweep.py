"""The sweep end to end against the floor measured in the same run.

Input: N random Hertz cycles (R = E* = 1, mu = 0.3; P1 from 50 to 150, dP/P1 from 1e-4 to 0.1,
dQ/dP from -1 to 1, so both slip directions, no-slip rows and warnings occur), written with
17 significant digits, as a user's file might be.  Output: every quantity of both edges
(45 columns: the 6 input columns, 19 per edge, the error).

* the sweep through the API, :func:`asymslip.sweep.sweep_file`, to CSV;
* the sweep through the command line, ``python -m asymslip sweep ... --out RESULTS.csv``
  (a fresh interpreter: start-up and imports included);
* the **floor**: the fastest read of the input (``pyarrow.csv.read_csv``, multithreaded, its own
  type inference), the core (:func:`asymslip.slip_zones.evaluate`: the rules, the law and the
  kernels, both edges -- work no sweep can skip), and one ``pyarrow.csv.write_csv`` of the same
  45 columns (warnings dictionary-encoded, as the sweep does);
* the sweep to Parquet (``--out RESULTS.parquet``), against the CSV sweep.

All four run in each round, interleaved; judged by the wall clock (pyarrow uses threads), the
ratio being the median of the per-round ratios, with the CPU-time ratio beside it.
"""

from __future__ import annotations

import subprocess
import sys
import tempfile
from collections.abc import Callable
from pathlib import Path

import numpy as np

from asymslip import HertzLaw, LoadCycle
from asymslip.edge_flags import MEASURE_KEYS, NUMBER_KEYS, warning_texts
from asymslip.slip_zones import evaluate
from asymslip.sweep import WARNING_SEPARATOR, output_columns, sweep_file

from .timing import Row, duration, interleaved, times, verdict
from .timing import count as number

ROOT = Path(__file__).resolve().parents[2]
CSV_TARGET, PARQUET_TARGET = 1.5, 0.5
MU = 0.3
INPUT_COLUMNS = ("P1", "Q1", "sigma1", "P2", "Q2", "sigma2")


def write_cases(path: Path, rows: int, seed: int = 0) -> None:
    """Random valid Hertz cycles, 17 significant digits."""
    rng = np.random.default_rng(seed)
    P1 = rng.uniform(50.0, 150.0, rows)
    dP = P1 * rng.uniform(1e-4, 0.1, rows)
    lam = rng.uniform(-1.0, 1.0, rows)
    zeros = np.zeros(rows)
    table = np.column_stack([P1, zeros, zeros, P1 + dP, lam * dP, zeros])
    with path.open("w") as handle:
        handle.write(",".join(INPUT_COLUMNS) + "\n")
        np.savetxt(handle, table, delimiter=",", fmt="%.17g")


def floor(cases: Path, out: Path, law: HertzLaw) -> int:
    """Fastest read + the core + one ``pyarrow.csv.write_csv``; returns the columns written."""
    import pyarrow as pa
    import pyarrow.csv as pcsv

    table = pcsv.read_csv(cases)
    loads = [table.column(name).to_numpy() for name in INPUT_COLUMNS]
    P1, Q1, sigma1, P2, Q2, sigma2 = loads
    evaluation = evaluate(law, LoadCycle.unchecked(P1, Q1, P2, Q2, sigma1, sigma2), MU)
    columns: dict[str, object] = {name: table.column(name) for name in INPUT_COLUMNS}
    for side, prefix in (("right", ""), ("left", "left_")):
        edge = evaluation.edges[side]
        for key in (*NUMBER_KEYS, *MEASURE_KEYS):
            columns[prefix + key] = pa.array(np.broadcast_to(getattr(edge, key), P1.shape))
        distinct, codes = np.unique(edge.flags, return_inverse=True)
        words = [
            WARNING_SEPARATOR.join(warning_texts(int(flags), law)) for flags in distinct.tolist()
        ]
        columns[prefix + "warnings"] = pa.DictionaryArray.from_arrays(
            pa.array(codes.astype(np.int32)), pa.array(words, pa.string())
        )
    columns["error"] = pa.nulls(len(P1), pa.string())
    pcsv.write_csv(pa.table(columns), out)
    return len(columns)


def header(path: Path) -> list[str]:
    with path.open() as handle:
        return [name.strip('"') for name in handle.readline().rstrip("\n").split(",")]


#: Columns compared number for number between the sweep's file and the floor's.
COMPARED = ("b", "slip_zone_width", "b_exact", "left_b", "left_eq27")


def same_numbers(first: Path, second: Path) -> bool:
    """Whether the two CSV files hold the same doubles in :data:`COMPARED`."""
    import pyarrow.csv as pcsv

    options = pcsv.ConvertOptions(include_columns=list(COMPARED))
    one, two = (pcsv.read_csv(path, convert_options=options) for path in (first, second))
    return all(
        np.array_equal(one.column(name).to_numpy(), two.column(name).to_numpy(), equal_nan=True)
        for name in COMPARED
    )


def bench_sweep(rows: int, rounds: int) -> list[Row]:
    try:
        import pyarrow  # noqa: F401
    except ImportError:
        return [
            Row(
                "sweep vs the floor",
                "skipped: pyarrow not installed (the parquet extra)",
                target=f"<= {CSV_TARGET}x",
            )
        ]
    law = HertzLaw(R=1.0, E_star=1.0)
    with tempfile.TemporaryDirectory() as scratch:
        folder = Path(scratch)
        cases = folder / "cases.csv"
        write_cases(cases, rows)
        command = [
            sys.executable,
            "-m",
            "asymslip",
            "sweep",
            str(cases),
            "--law",
            "hertz",
            "--R",
            "1",
            "--E-star",
            "1",
            "--mu",
            str(MU),
            "--out",
            str(folder / "cli.csv"),
        ]

        def cli() -> None:
            completed = subprocess.run(command, cwd=ROOT, capture_output=True, text=True)
            if completed.returncode != 0:
                raise RuntimeError(f"asymslip sweep failed: {completed.stderr.strip()[-300:]}")

        candidates: dict[str, Callable[[], object]] = {
            "api": lambda: sweep_file(cases, law, folder / "api.csv", mu=MU, progress=False),
            "cli": cli,
            "floor": lambda: floor(cases, folder / "floor.csv", law),
            "parquet": lambda: sweep_file(
                cases, law, folder / "api.parquet", mu=MU, progress=False
            ),
        }
        measured = interleaved(candidates, rounds, clock="wall")
        # The floor wrote what the sweep wrote, or the comparison means nothing.
        expected = output_columns(list(INPUT_COLUMNS), "both")
        for name in ("api.csv", "cli.csv", "floor.csv"):
            if header(folder / name) != expected:
                raise RuntimeError(f"{name}: columns {header(folder / name)} != {expected}")
        sizes = {name: (folder / name).stat().st_size for name in ("api.csv", "floor.csv")}
        if not same_numbers(folder / "api.csv", folder / "floor.csv"):
            raise RuntimeError("the sweep and the floor wrote different numbers")
    t = {name: measured.best(name) for name in candidates}
    label = f"sweep, {number(rows)} Hertz rows, both edges, {len(expected)} columns, to CSV"
    floor_how = (
        f"floor = `pyarrow.csv.read_csv` + `evaluate` + `pyarrow.csv.write_csv` of the "
        f"same columns and numbers ({sizes['floor.csv'] / 1e6:,.0f} MB; the sweep's "
        f"{sizes['api.csv'] / 1e6:,.0f} MB)"
    )
    return [
        Row(
            f"{label}: `sweep_file` (API) vs the floor",
            duration(t["api"]),
            duration(t["floor"]),
            times(measured.ratio("api", "floor")),
            f"<= {CSV_TARGET}x",
            verdict(measured.ratio("api", "floor") <= CSV_TARGET),
            f"{measured.how('api', 'floor')}; {floor_how}; {rows / t['api']:,.0f} rows/s",
        ),
        Row(
            "same: `asymslip sweep` (command line, fresh interpreter) vs the floor",
            duration(t["cli"]),
            duration(t["floor"]),
            times(measured.ratio("cli", "floor")),
            f"<= {CSV_TARGET}x",
            verdict(measured.ratio("cli", "floor") <= CSV_TARGET),
            measured.how("cli", "floor") + "; start-up and imports included",
        ),
        Row(
            "same to Parquet (`sweep_file`, `.parquet`) vs the CSV sweep",
            duration(t["parquet"]),
            duration(t["api"]),
            times(measured.ratio("parquet", "api")),
            f"<= {PARQUET_TARGET}x",
            verdict(measured.ratio("parquet", "api") <= PARQUET_TARGET),
            measured.how("parquet", "api"),
        ),
    ]
