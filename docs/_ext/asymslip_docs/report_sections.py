"""``{derivation-report-section} HEADING``: a section of the derivation report, as it is now.

The report (``generated/report/derivation.md``) is written by ``make report`` from the
derivation records and the error map's CSV, and freshness-checked; a page that shows one of its
sections this way shows today's numbers, never a copy that could go stale.
"""

from __future__ import annotations

from typing import Any

from docutils import nodes
from docutils.statemachine import StringList
from sphinx.application import Sphinx
from sphinx.util.docutils import SphinxDirective

from .records import REPORT, report_section


class ReportSection(SphinxDirective):
    """Parse one section of the report (Markdown) in place."""

    required_arguments = 1
    final_argument_whitespace = True
    has_content = False

    def run(self) -> list[nodes.Node]:
        self.env.note_dependency(str(REPORT))
        text = report_section(self.arguments[0])
        container = nodes.container(classes=["derivation-report-section"])
        self.state.nested_parse(StringList(text.splitlines(), source=str(REPORT)), 0, container)
        return [container]


def setup(app: Sphinx) -> dict[str, Any]:
    app.add_directive("derivation-report-section", ReportSection)
    return {"parallel_read_safe": True}
