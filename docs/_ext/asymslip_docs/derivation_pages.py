"""One page per derivation script (``docs/theory/derivations/``, not committed).

Each page shows the script's docstring, the paper equations the derivation report credits to
it (linked to the theory pages), the generated functions it registers (from ``formulas.json``,
linked to the API reference) and its full source.  A new script appears with no change to the
docs.
"""

from __future__ import annotations

import ast
from pathlib import Path
from typing import Any

from sphinx.application import Sphinx

from .api_pages import write_if_changed
from .docstrings import escape_line
from .records import derivation_scripts, formula_records, report_equations

FOLDER = Path("theory") / "derivations"


def _docstring(path: Path) -> str:
    return ast.get_docstring(ast.parse(path.read_text(encoding="utf-8"))) or ""


def _indent(text: str) -> str:
    return "\n".join(f"   {line}" if line else "" for line in text.splitlines())


def render(path: Path, docname_depth: int = 3) -> str:
    """reStructuredText of the page of one derivation script."""
    relative = f"derivations/{path.name}"
    title = f"``{relative}``"
    lines = [f".. _derivation-{path.stem}:", "", title, "=" * len(title), ""]
    doc = _docstring(path)
    if doc:
        lines += ["::", "", _indent(doc), ""]
    covered = sorted(
        {
            number
            for number, entries in report_equations().items()
            if any(entry.derivation == relative for entry in entries)
        },
        key=int,
    )
    if covered:
        links = ", ".join(f":ref:`({number}) <paper-eq-{number}>`" for number in covered)
        lines += [f"**Paper equations it covers:** {links}.", ""]
    registered = [record for record in formula_records() if record.source == relative]
    if registered:
        lines += ["**Generated functions it registers:**", ""]
        for record in registered:
            equations = ", ".join(f"({number})" for number in record.equations) or "no paper number"
            lines.append(
                f"- :py:func:`{record.python}` -- {equations}: {escape_line(record.summary)}"
            )
        lines.append("")
    source = "../" * docname_depth + relative
    lines += [
        ".. rubric:: Source",
        "",
        f".. literalinclude:: {source}",
        "   :language: python",
        "   :linenos:",
        "",
    ]
    return "\n".join(lines)


def render_index(scripts: list[Path]) -> str:
    lines = [
        "Derivation scripts",
        "==================",
        "",
        "Every formula the package computes is derived by one of these SymPy scripts from the",
        "paper's starting points and asserted against the printed form (``make verify`` runs",
        "them all; ``make generate`` emits what they register).  Each page lists the paper",
        "equations the script covers and the generated functions it registers.",
        "",
        ".. list-table::",
        "   :header-rows: 1",
        "   :widths: 35 65",
        "",
        "   * - script",
        "     - what it derives",
    ]
    for path in scripts:
        first = (_docstring(path).strip().splitlines() or [" "])[0].replace("|", "\\|")
        lines += [f"   * - :ref:`{path.name} <derivation-{path.stem}>`", f"     - ``{first}``"]
    lines += ["", ".. toctree::", "   :hidden:", ""]
    lines += [f"   {path.stem}" for path in scripts]
    return "\n".join(lines) + "\n"


def write_pages(srcdir: Path) -> None:
    folder = srcdir / FOLDER
    scripts = derivation_scripts()
    wanted = {"index.rst", *(f"{path.stem}.rst" for path in scripts)}
    for path in scripts:
        write_if_changed(folder / f"{path.stem}.rst", render(path))
    write_if_changed(folder / "index.rst", render_index(scripts))
    for stale in folder.glob("*.rst"):
        if stale.name not in wanted:
            stale.unlink()


def _builder_inited(app: Sphinx) -> None:
    write_pages(Path(app.srcdir))


def setup(app: Sphinx) -> dict[str, Any]:
    app.connect("builder-inited", _builder_inited)
    return {"parallel_read_safe": True}
