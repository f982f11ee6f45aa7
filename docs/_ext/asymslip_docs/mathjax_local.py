"""MathJax 3 served from the built site, never from a CDN: the site must render offline.

The MathJax files come from the pinned PyPI package ``sphinx-mathjax-offline`` (MathJax 3.2.2,
its CommonHTML output and its woff fonts).  Its own Sphinx hook copies them only after a build
without errors; here the package's ``static`` folder is added to ``html_static_path`` instead, so
every build (a failing one too) serves them from ``_static/mathjax``.
"""

from __future__ import annotations

import importlib.util
from pathlib import Path
from typing import Any

from sphinx.application import Sphinx
from sphinx.config import Config
from sphinx.errors import ConfigError

PACKAGE = "sphinx-mathjax-offline"
#: The entry point MathJax's loader starts from; it finds its fonts and extensions beside it.
ENTRY = "mathjax/tex-chtml.js"


def mathjax_static_folder() -> Path:
    """The folder holding ``mathjax/`` in the installed package (an error naming the extra)."""
    spec = importlib.util.find_spec(PACKAGE)
    if spec is None or spec.origin is None:
        raise ConfigError(f"{PACKAGE} is not installed: pip install -e '.[docs]' (or make env)")
    folder = Path(spec.origin).parent / "static"
    if not (folder / ENTRY).is_file():
        raise ConfigError(f"{PACKAGE} has no {ENTRY}: reinstall the docs extra")
    return folder


def _configure(app: Sphinx, config: Config) -> None:
    config.html_static_path = [*config.html_static_path, str(mathjax_static_folder())]
    config.mathjax_path = ENTRY
    # Equation numbers are the paper's, written as \tag{N}; nothing is numbered automatically.
    config.mathjax3_config = {"tex": {"tags": "none"}}


def setup(app: Sphinx) -> dict[str, Any]:
    app.connect("config-inited", _configure, priority=400)
    return {"parallel_read_safe": True}
