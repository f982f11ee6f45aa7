"""The ``paper-equation`` directive: one of the paper's numbered equations, keyed to the code.

``{paper-equation} 17`` shows equation (17) as the paper prints it, tagged (17), with what the
derivation report records of it (title, status, the derivation script) and the generated
functions that implement it -- read from the formula records ``formulas.json``, which list each
function's equations, so the links cannot drift from the code.  Each equation gets the target
``paper-eq-17`` (link to it with ``{ref}`(17) <paper-eq-17>```).

When the build ends, every equation (1)-(51) must have been placed exactly once: a missing or
repeated one is a warning (an error under ``-W``).
"""

from __future__ import annotations

from typing import Any, ClassVar

from docutils import nodes
from docutils.parsers.rst import directives
from sphinx import addnodes
from sphinx.application import Sphinx
from sphinx.environment import BuildEnvironment
from sphinx.util import logging
from sphinx.util.docutils import SphinxDirective

from .records import FORMULAS, REPORT, displayable, formulas_of, printed_form, report_equations

logger = logging.getLogger(__name__)
PAPER_EQUATIONS = tuple(str(number) for number in range(1, 52))
#: Where the derivation scripts' pages live (written by derivation_pages).
DERIVATION_DOCS = "/theory/derivations"
#: Status words of the report that send the reader to the errata page.
ERRATUM = "erratum found"


def label(number: str) -> str:
    """The target name of paper equation ``number``."""
    return f"paper-eq-{number}"


def derivation_doc(path: str) -> str:
    """The page of a derivation script, from its path ``derivations/NAME.py``."""
    return f"{DERIVATION_DOCS}/{path.removeprefix('derivations/').removesuffix('.py')}"


def _xref(
    domain: str, kind: str, target: str, text: str, code: bool = True
) -> addnodes.pending_xref:
    inner: nodes.Node = nodes.literal(text, text) if code else nodes.inline(text, text)
    node = addnodes.pending_xref(
        "", inner, refdomain=domain, reftype=kind, reftarget=target, refexplicit=True, refwarn=True
    )
    return node


class PaperEquation(SphinxDirective):
    """``paper-equation NUMBER``: the printed equation, its status and its code."""

    required_arguments = 1
    optional_arguments = 0
    has_content = False
    option_spec: ClassVar[dict[str, Any]] = {"class": directives.class_option}

    def run(self) -> list[nodes.Node]:
        number = self.arguments[0].strip().strip("()")
        # Read again whenever the records or the report change.
        self.env.note_dependency(str(FORMULAS))
        self.env.note_dependency(str(REPORT))
        entries = report_equations().get(number)
        if entries is None:
            raise self.error(f"the derivation report has no equation ({number})")
        # Written out with its own delimiters (nowrap): Sphinx would wrap a formula with line
        # breaks in a split environment, where MathJax allows no \tag.
        latex = f"\\[{displayable(printed_form(number))} \\tag{{{number}}}\\]"
        block = nodes.container(classes=["paper-equation", *self.options.get("class", [])])
        block["ids"] = [label(number)]
        block["names"] = [label(number)]
        self.state.document.note_explicit_target(block)
        block += nodes.math_block(
            latex, latex, docname=self.env.docname, number=None, label=None, nowrap=True
        )
        notes = nodes.bullet_list(classes=["paper-equation-notes"])
        for entry in entries:
            item = nodes.paragraph()
            item += nodes.strong(f"({number}) ", f"({number}) ")
            item += nodes.Text(f"{entry.title} -- ")
            item += nodes.emphasis(entry.status, entry.status)
            item += nodes.Text(" in ")
            item += _xref("std", "doc", derivation_doc(entry.derivation), entry.derivation)
            if entry.status == ERRATUM:
                item += nodes.Text(" (")
                item += _xref("std", "ref", "errata", "see the errata", code=False)
                item += nodes.Text(")")
            notes += nodes.list_item("", item)
        functions = formulas_of(number)
        if functions:
            item = nodes.paragraph()
            item += nodes.Text("Implemented by ")
            for index, record in enumerate(functions):
                if index:
                    item += nodes.Text(", ")
                item += _xref("py", "func", record.python, f"{record.module}.{record.name}")
            item += nodes.Text(" (in asymslip_gen).")
            notes += nodes.list_item("", item)
        block += notes
        placed = getattr(self.env, "asymslip_paper_equations", {})
        placed.setdefault(number, []).append(self.env.docname)
        self.env.asymslip_paper_equations = placed  # type: ignore[attr-defined]
        return [block]


def _purge(app: Sphinx, env: BuildEnvironment, docname: str) -> None:
    placed = getattr(env, "asymslip_paper_equations", {})
    for number in list(placed):
        placed[number] = [doc for doc in placed[number] if doc != docname]


def _merge(app: Sphinx, env: BuildEnvironment, docnames: set[str], other: BuildEnvironment) -> None:
    placed = getattr(env, "asymslip_paper_equations", {})
    for number, docs in getattr(other, "asymslip_paper_equations", {}).items():
        placed.setdefault(number, []).extend(docs)
    env.asymslip_paper_equations = placed  # type: ignore[attr-defined]


def _check(app: Sphinx, env: BuildEnvironment) -> None:
    placed = getattr(env, "asymslip_paper_equations", {})
    missing = [number for number in PAPER_EQUATIONS if not placed.get(number)]
    repeated = [number for number, docs in placed.items() if len(docs) > 1]
    if missing:
        logger.warning("paper equations not shown on any theory page: (%s)", "), (".join(missing))
    if repeated:
        logger.warning("paper equations shown more than once: (%s)", "), (".join(repeated))


def setup(app: Sphinx) -> dict[str, Any]:
    app.add_directive("paper-equation", PaperEquation)
    app.connect("env-purge-doc", _purge)
    app.connect("env-merge-info", _merge)
    app.connect("env-check-consistency", _check)
    return {"parallel_read_safe": True}
