"""Benchmarks of :mod:`asymslip.files`: reading a cases file, writing a result table.

Run from the repository root: ``.venv/bin/python tests/benchmarks/bench_files.py [--rows N]``.
Every function returns rows (benchmark, measured, baseline, ratio, how) for the ``make bench``
table; each ratio is taken within one process, best of N rounds, the candidates interleaved in
every round (so all see the same load on a shared machine).  Nothing here asserts.

(r) Read a 10^6-row cases file (6 numeric columns): ``pyarrow.csv.read_csv`` with its own type
    inference (the fastest read) vs :func:`read_table` with pyarrow and with NumPy alone.
(w) Write 10^6 rows x 43 double columns + 2 text columns (a dictionary-encoded warnings column
    and an error column), the shape of a both-edges sweep: ``pyarrow.csv.write_csv`` of the same
    columns (the floor) vs :func:`open_table` to CSV with pyarrow, with NumPy alone, and to
    Parquet.
(p) The worker-pool question: the same CSV written by one process vs two forked processes that
    each format half and send the bytes back (what a pool would do), and the CPU time
    ``pyarrow.csv.write_csv`` uses per wall-clock second (above 1: it already uses threads).
"""

from __future__ import annotations

import argparse
import io
import multiprocessing
import os
import sys
import tempfile
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from asymslip.files import Categorical, TextColumn, open_table, read_table
from asymslip.files.writer import csv_rows

FLOAT_COLUMNS = 43
WARNINGS = (
    "",
    "eq24 = 0.31 > 0.1: the contact grows too much",
    "no slip: |lam| < mu",
    "P_K <= 0: b_exact is not defined | eq27 = 0.2 > 0.1",
)


@dataclass
class Row:
    benchmark: str
    measured: str
    baseline: str
    ratio: str
    how: str


def best_of_each(functions: list[Callable[[], object]], repeat: int) -> list[float]:
    """Smallest wall time of each function over ``repeat`` interleaved rounds."""
    best = [float("inf")] * len(functions)
    for _ in range(repeat):
        for index, function in enumerate(functions):
            start = time.perf_counter()
            function()
            best[index] = min(best[index], time.perf_counter() - start)
    return best


def seconds(value: float) -> str:
    return f"{value:.2f} s" if value >= 1 else f"{value * 1e3:.0f} ms"


def write_cases(path: Path, rows: int, seed: int = 0) -> None:
    """Random valid Hertz cycles written with 17 digits, as the sweep benchmark does."""
    rng = np.random.default_rng(seed)
    P1 = rng.uniform(50.0, 150.0, rows)
    dP = P1 * rng.uniform(1e-4, 0.1, rows)
    lam = rng.uniform(-1.0, 1.0, rows)
    table = np.column_stack([P1, np.zeros(rows), np.zeros(rows), P1 + dP, lam * dP, np.zeros(rows)])
    with path.open("w") as handle:
        handle.write("P1,Q1,sigma1,P2,Q2,sigma2\n")
        np.savetxt(handle, table, delimiter=",", fmt="%.17g")


def result_columns(rows: int, seed: int = 1) -> tuple[list[tuple[str, str]], dict[str, object]]:
    """43 doubles of the spread a sweep gives (a few NaN: invalid rows) + warnings + error."""
    rng = np.random.default_rng(seed)
    columns: dict[str, object] = {}
    for index in range(FLOAT_COLUMNS):
        values = rng.standard_normal(rows) * 10.0 ** rng.integers(-8, 4)
        values[rng.random(rows) < 0.01] = np.nan
        columns[f"x{index}"] = values
    columns["warnings"] = Categorical(rng.integers(0, len(WARNINGS), rows), WARNINGS)
    errors = np.where(rng.random(rows) < 0.001, "P2: must exceed P1 (got 99.0)", "")
    columns["error"] = TextColumn.from_strings(errors.tolist())
    schema = [(f"x{index}", "float") for index in range(FLOAT_COLUMNS)]
    schema += [("warnings", "category"), ("error", "text")]
    return schema, columns


def arrow_table(schema, columns):  # noqa: ANN001, ANN201
    import pyarrow as pa

    from asymslip.files.writer import _arrow_array

    return pa.table({name: _arrow_array(columns[name], kind) for name, kind in schema})


def bench_read(rows: int, repeat: int) -> list[Row]:
    import pyarrow.csv as pcsv

    with tempfile.TemporaryDirectory() as scratch:
        path = Path(scratch) / "cases.csv"
        write_cases(path, rows)
        required, numeric = ["P1", "Q1", "P2", "Q2"], ["sigma1", "sigma2", "mu"]
        raw, fast, slow = best_of_each(
            [
                lambda: pcsv.read_csv(path),
                lambda: read_table(path, required=required, numeric=numeric, engine="pyarrow"),
                lambda: read_table(path, required=required, numeric=numeric, engine="numpy"),
            ],
            repeat,
        )
    how = f"best of {repeat}, interleaved"
    label = f"read {rows:,} cases (6 columns)"
    return [
        Row(
            f"{label}: `read_table`, pyarrow",
            seconds(fast),
            seconds(raw),
            f"{fast / raw:.2f}x",
            how + "; baseline `pyarrow.csv.read_csv` with type inference",
        ),
        Row(
            f"{label}: `read_table`, NumPy only",
            seconds(slow),
            seconds(raw),
            f"{slow / raw:.2f}x",
            how,
        ),
    ]


def bench_write(rows: int, repeat: int) -> list[Row]:
    import pyarrow.csv as pcsv

    schema, columns = result_columns(rows)
    table = arrow_table(schema, columns)
    with tempfile.TemporaryDirectory() as scratch:
        folder = Path(scratch)

        def write(name: str, engine: str | None) -> Callable[[], None]:
            def run() -> None:
                with open_table(folder / name, schema, engine=engine) as writer:
                    for start in range(0, rows, 100_000):
                        writer.write(
                            {
                                key: _part(column, start, start + 100_000)
                                for key, column in columns.items()
                            }
                        )

            return run

        floor, fast, slow, parquet = best_of_each(
            [
                lambda: pcsv.write_csv(table, str(folder / "floor.csv")),
                write("arrow.csv", "pyarrow"),
                write("numpy.csv", "numpy"),
                write("out.parquet", None),
            ],
            repeat,
        )
        same = (folder / "arrow.csv").read_bytes() == (folder / "numpy.csv").read_bytes()
    how = f"best of {repeat}, interleaved; chunks of 100,000 rows"
    label = f"write {rows:,} rows x {FLOAT_COLUMNS} doubles + 2 text"
    return [
        Row(
            f"{label}: CSV, `open_table` with pyarrow",
            seconds(fast),
            seconds(floor),
            f"{fast / floor:.2f}x",
            how + "; baseline one `pyarrow.csv.write_csv` call",
        ),
        Row(
            f"{label}: CSV, NumPy only",
            seconds(slow),
            seconds(floor),
            f"{slow / floor:.2f}x",
            how + f"; same bytes as the pyarrow writer: {'yes' if same else 'NO'}",
        ),
        Row(
            f"{label}: Parquet",
            seconds(parquet),
            seconds(fast),
            f"{parquet / fast:.2f}x",
            how + "; baseline the CSV writer with pyarrow",
        ),
    ]


def _part(column, start: int, stop: int):  # noqa: ANN001, ANN202
    if isinstance(column, TextColumn | Categorical):
        return column.slice(start, min(stop, len(column)))
    return column[start:stop]


# --- (p) would a pool of processes help? -------------------------------------------------------
_JOB: tuple | None = None


def _format_half(half: int) -> bytes:
    assert _JOB is not None
    schema, columns, rows, engine = _JOB
    start, stop = (0, rows // 2) if half == 0 else (rows // 2, rows)
    part = {key: _part(column, start, stop) for key, column in columns.items()}
    if engine == "numpy":
        return csv_rows(part, schema)
    import pyarrow.csv as pcsv

    sink = io.BytesIO()
    pcsv.write_csv(
        arrow_table(schema, part),
        sink,
        pcsv.WriteOptions(include_header=False, quoting_style="none"),
    )
    return sink.getvalue()


def bench_pool(rows: int, repeat: int) -> list[Row]:
    global _JOB
    import pyarrow.csv as pcsv

    if "fork" not in multiprocessing.get_all_start_methods():
        return []
    schema, columns = result_columns(rows)
    out: list[Row] = []
    for engine in ("pyarrow", "numpy"):
        _JOB = (schema, columns, rows, engine)

        def one() -> None:
            _format_half(0)
            _format_half(1)

        def two() -> None:
            with multiprocessing.get_context("fork").Pool(2) as pool:
                pool.map(_format_half, [0, 1])

        single, pooled = best_of_each([one, two], repeat)
        out.append(
            Row(
                f"format {rows:,} rows to CSV text ({engine}): 2 worker processes",
                seconds(pooled),
                seconds(single),
                f"{pooled / single:.2f}x",
                f"best of {repeat}, interleaved; baseline the same work in one "
                "process; workers forked, bytes sent back by pipe",
            )
        )
    _JOB = None
    table = arrow_table(schema, columns)
    cpu, wall = time.process_time(), time.perf_counter()
    pcsv.write_csv(table, io.BytesIO())
    cpu, wall = time.process_time() - cpu, time.perf_counter() - wall
    out.append(
        Row(
            "`pyarrow.csv.write_csv`: CPU seconds per wall second",
            f"{cpu / wall:.2f}",
            "",
            "",
            f"one call, {rows:,} rows; {os.cpu_count()} cores",
        )
    )
    return out


def table(rows: list[Row]) -> str:
    lines = [
        "| Benchmark | Measured | Baseline | Ratio | How |",
        "| --- | ---: | ---: | ---: | --- |",
    ]
    lines += [
        f"| {r.benchmark} | {r.measured} | {r.baseline} | {r.ratio} | {r.how} |" for r in rows
    ]
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--rows", type=int, default=10**6)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--skip", default="", help="sections to skip, e.g. 'p'")
    args = parser.parse_args(argv)
    rows: list[Row] = []
    for key, run in (("r", bench_read), ("w", bench_write), ("p", bench_pool)):
        if key not in args.skip:
            print(f"({key}) ...", file=sys.stderr, flush=True)
            measured = run(args.rows, args.repeat)
            print(table(measured), file=sys.stderr, flush=True)  # seen before the end
            rows.extend(measured)
    print(table(rows))
    return 0


if __name__ == "__main__":
    sys.exit(main())
