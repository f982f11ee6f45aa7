"""``make bench --quick`` runs every section and prints a well-formed table (not the timings)."""

from __future__ import annotations

import re

import pytest

from tests.benchmarks.run_benchmarks import main
from tests.benchmarks.timing import COLUMNS

#: A measure every full table must have, per section title, in this order.
EXPECTED = {
    "One scalar call": ["one scalar `slip_zone(", "kernel of its headline width", "evaluate`"],
    "Cycles in bulk, law against law": [
        "Hertz",
        "rounded flat",
        "table law",
        "power law",
        "bulk tension",
        "table law",
    ],
    "The sweep against its floor": [
        "`sweep_file` (API) vs the floor",
        "`asymslip sweep`",
        "Parquet",
    ],
    "Generated kernels against the strongest baselines": [
        "`stick_boundary_proportional`",
        "allocating",
        "lambdify",
        "memory floor",
        "`slip_zone_width`",
        "allocating",
        "lambdify",
        "memory floor",
    ],
    "Closed-form (49) against quadrature": ["quad", "same 2 points", "agreement"],
    "Import time": ["`from asymslip import", "`from asymslip_gen import *`"],
    "Code generation": ["`make generate`"],
    "Reference solver": ["reference solver"],
    "The stress field near an edge": [
        "grid near the right edge",
        "fast - direct",
        "the solve",
        "asymptotic amplitude",
        "stated accuracy",
    ],
    "Parameter studies on Dask": [
        "`LocalCluster`",
        "`solve-batch`",
        "sweep",
        "overhead per task",
        "overhead per task of a study",
    ],
}
MET = {"yes", "**no**", "-"}
MEASURED = re.compile(
    r"^([\d.,]+ (s|ms|µs|ns)|[\d.]+e-\d+|N\^[\d.]+|skipped: .+"
    r"|[\d.]+ (GB|MB)|[\d.]+(e-\d+)? elements)$"  # the solver's memory and boundary rows
)


def cells(line: str) -> list[str]:
    """The cells of one Markdown table line (``\\|`` is a pipe inside a cell)."""
    return [cell.strip() for cell in re.split(r"(?<!\\)\|", line.strip())[1:-1]]


@pytest.fixture(scope="module")
def quick_table(tmp_path_factory: pytest.TempPathFactory) -> list[str]:
    path = tmp_path_factory.mktemp("bench") / "bench.md"
    assert main(["--quick", "--markdown", str(path)]) == 0
    return path.read_text(encoding="utf-8").splitlines()


def test_quick_benchmark_prints_every_section_with_rows_of_seven_well_formed_cells(
    quick_table: list[str],
) -> None:
    assert quick_table[0].startswith("Machine: ") and "cores" in quick_table[0]
    table = [line for line in quick_table if line.startswith("|")]
    assert cells(table[0]) == list(COLUMNS)
    sections: dict[str, list[list[str]]] = {}
    for line in table[2:]:
        row = cells(line)
        assert len(row) == len(COLUMNS), line
        title = re.fullmatch(r"\*\*(.+)\*\*", row[0])
        if title:
            sections[title.group(1)] = []
            continue
        measure, measured, _, ratio, target, met, _ = row
        assert MEASURED.match(measured), line
        assert met in MET, line
        if met != "-":  # a target was judged: there is one, and a figure to judge
            assert target.startswith(("<", ">")), line
        if ratio:
            assert re.match(r"^[\d.e]+x( faster)?$", ratio), line
        sections[title_of(sections)].append(row)
    assert list(sections) == list(EXPECTED)
    for title, wanted in EXPECTED.items():
        measures = [row[0] for row in sections[title]]
        assert len(measures) >= len(wanted), title
        position = 0
        for fragment in wanted:  # each expected measure, in order
            while position < len(measures) and fragment not in measures[position]:
                position += 1
            assert position < len(measures), f"{title}: no row with {fragment!r}"
            position += 1


def title_of(sections: dict[str, list[list[str]]]) -> str:
    return list(sections)[-1]
