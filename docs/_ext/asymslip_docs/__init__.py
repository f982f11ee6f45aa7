"""Sphinx helpers of the asymslip site: pages written from the sources at build time.

Loaded by ``docs/conf.py`` by file path (nothing edits ``sys.path``); :func:`setup` connects
each helper.
"""

from __future__ import annotations

import hashlib
from pathlib import Path
from typing import Any

from sphinx.application import Sphinx

from . import (
    api_pages,
    bound_names,
    cli_pages,
    derivation_pages,
    docstrings,
    error_map_rows,
    language_pages,
    mathjax_local,
    paper_equations,
    report_sections,
    short_names,
)


def _digest() -> str:
    """Of these helpers' sources: a change re-reads every page (their output is in doctrees)."""
    digest = hashlib.sha256()
    for path in sorted(Path(__file__).parent.glob("*.py")):
        digest.update(path.read_bytes())
    return digest.hexdigest()


def setup(app: Sphinx) -> dict[str, Any]:
    app.add_config_value("asymslip_docs_digest", _digest(), "env")
    pages = (api_pages, derivation_pages, language_pages)
    directives = (paper_equations, report_sections, error_map_rows, cli_pages)
    for helper in (mathjax_local, *pages, *directives, bound_names, short_names, docstrings):
        helper.setup(app)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
