"""``{error-map-rows}``: chosen rows of the error map's data, as the data are now.

The error map (``generated/report/error_map.csv``, written by ``make error-map`` and checked by
``make check-error-map``) holds every estimate's error against the reference solver at every
edge it covers.  A page that quotes a few of its edges names them -- one per line of the
directive's content, ``law a2_a1 lam_mu tau edge`` as the CSV writes them -- and the table is
read from the CSV when the site is built, so it cannot go stale as a hand copy did.  A named
edge missing from the data fails the build.
"""

from __future__ import annotations

import csv
from dataclasses import dataclass
from typing import Any

from docutils import nodes
from docutils.statemachine import StringList
from sphinx.application import Sphinx
from sphinx.util.docutils import SphinxDirective

from .records import REPORT, SourceLayoutError

DATA = REPORT.parent / "error_map.csv"
#: The key columns that name one edge, in the order the directive's lines give them.
KEY = ("law", "a2_a1", "lam_mu", "tau", "edge")
#: The estimates shown, as (column, heading).
ESTIMATES = (
    ("b_paper_elements", "(22) `b_paper`"),
    ("b_first_order_elements", "(28) `b_first_order`"),
    ("b_elements", "`b` (b2)"),
    ("b_exact_elements", "a(P_K) `b_exact`"),
)
LAWS = {
    "hertz": "Hertz",
    "flat-rounded": "rounded flat",
    "power-1.5": "power n = 1.5",
    "power-3": "power n = 3",
}


@dataclass(frozen=True)
class Edge:
    """One edge of the error map, as a directive line names it."""

    law: str
    a2_a1: str
    lam_mu: str
    tau: str
    edge: str


def rows() -> dict[Edge, dict[str, str]]:
    """Every edge of the error map's data with its columns."""
    with DATA.open(encoding="utf-8", newline="") as handle:
        lines = [line for line in handle if not line.startswith("#")]
    return {Edge(*(row[name] for name in KEY)): row for row in csv.DictReader(lines)}


def _signed(value: str) -> str:
    return "-" if value == "" else f"{float(value):+.2f}"


def table(edges: list[Edge]) -> str:
    """The Markdown table of the named edges' errors in solver elements."""
    data = rows()
    head = ["law", "a2/a1", "lambda/mu", "pi eta a1/(4 mu)", "edge"]
    lines = [
        "| " + " | ".join(head + [heading for _, heading in ESTIMATES]) + " |",
        "|" + "---|" * len(head) + "---:|" * len(ESTIMATES),
    ]
    for edge in edges:
        row = data.get(edge)
        if row is None:
            raise SourceLayoutError(f"{DATA}: no edge {edge}")
        cells = [LAWS.get(edge.law, edge.law), edge.a2_a1, edge.lam_mu, edge.tau, edge.edge]
        cells += [_signed(row[column]) for column, _ in ESTIMATES]
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


class ErrorMapRows(SphinxDirective):
    """Parse the table of the edges named in the content in place."""

    has_content = True

    def run(self) -> list[nodes.Node]:
        self.env.note_dependency(str(DATA))
        edges = [Edge(*line.split()) for line in self.content if line.strip()]
        text = table(edges)
        container = nodes.container(classes=["error-map-rows"])
        self.state.nested_parse(StringList(text.splitlines(), source=str(DATA)), 0, container)
        return [container]


def setup(app: Sphinx) -> dict[str, Any]:
    app.add_directive("error-map-rows", ErrorMapRows)
    return {"parallel_read_safe": True}
