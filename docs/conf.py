"""Sphinx configuration of the asymslip documentation site (``make docs``).

The site is built offline with warnings as errors (``-W --keep-going -n``).  Pages that must
follow the sources are written at build time by the helpers in ``docs/_ext`` (loaded below by
file path, so that nothing edits ``sys.path``):

* ``api_pages``: one reference page per module of ``asymslip`` and ``asymslip_gen``;
* ``derivation_pages``: one page per derivation script, with the formulas it registers;
* ``paper_equations``: the paper's numbered equations with the code that implements them,
  read from the derivation report and the formula records (``formulas.json``);
* ``language_pages``: the generated functions in C, Fortran and MATLAB/Octave;
* ``mathjax_local``: MathJax 3 served from the build, never from a CDN.

The tutorials are the scripts in ``docs/examples/*.py``, run by sphinx-gallery on every build.
"""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path
from types import ModuleType
from typing import Any

DOCS = Path(__file__).resolve().parent
ROOT = DOCS.parent

project = "asymslip"
author = "the asymslip developers"
copyright = "2026, the asymslip developers; the paper: Moore, Hills et al. (CC BY)"
release = version = "0.1.0"

extensions = [
    "myst_parser",
    "sphinx.ext.autodoc",
    "sphinx.ext.mathjax",
    "numpydoc",
    "sphinx_gallery.gen_gallery",
    "matplotlib.sphinxext.plot_directive",
]

source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
exclude_patterns = [
    "_build",
    "examples",
    "tutorials/*.ipynb",
    "tutorials/*.py",
    "tutorials/*.zip",
    "tutorials/*.md5",
    "tutorials/*.json",
    "tutorials/*.pickle",
    "benchmark-results.md",
]
templates_path = ["_templates"]

# Cross-references must resolve (make docs passes -n).  Offline there is no intersphinx, so
# names of the standard library and of third-party packages cannot resolve: they alone are
# ignored, by the package they belong to; every asymslip name must resolve.
nitpicky = True
_FOREIGN = (
    r"(numpy|np|numpy\.typing|npt|sympy|pyarrow|pandas|dask|matplotlib|scipy|mpmath|argparse"
    r"|collections|collections\.abc|typing|typing_extensions|types|pathlib|os|io|enum"
    r"|dataclasses|datetime|re|json|csv|ast|importlib|concurrent|subprocess|sys|abc|contextlib"
    r"|functools|itertools|numbers|fractions|decimal|math|array|builtins|optional)"
)
_BUILTINS = (
    r"(float|int|str|bool|bytes|object|None|complex|list|tuple|dict|set|frozenset|type|slice"
    r"|Ellipsis|NotImplemented|Exception|ValueError|TypeError|RuntimeError|OSError|KeyError"
    r"|IndexError|ArithmeticError|OverflowError|FileNotFoundError|Path|PathLike|ArrayLike"
    r"|NDArray|Any|Callable|Iterable|Iterator|Sequence|Mapping|Generator|Self|Literal|Union"
    r"|Optional|ClassVar|Final|TextIO|BinaryIO|IO|array_like|array-like|ndarray|callable"
    r"|optional|default|scalar|float64|floating|generic|dtype|function|module|path-like|file"
    r"|Namespace|ArgumentParser|dict-like|sequence|iterable|mapping|positive)"
)
nitpick_ignore_regex = [
    (r"py:.*", _FOREIGN + r"(\..*)?"),
    (r"py:.*", _BUILTINS),
    # Subscripted builtins in annotations (dict[str, float]) split by the type parser.
    (r"py:.*", r"(dict|tuple|list|set|frozenset|type)\[.*|string"),
    # The project's own test and benchmark modules are not part of the site.
    (r"py:.*", r"tests(\..*)?"),
    # Private names (a leading underscore) are not part of the reference.
    (r"py:.*", r"(.*\.)?_[A-Za-z]\w*"),
]

# numpydoc renders the Parameters/Returns sections; autodoc lists the members itself.
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
numpydoc_xref_param_type = False
numpydoc_validation_checks: set[str] = set()
autodoc_member_order = "bysource"
autodoc_typehints = "signature"
autodoc_preserve_defaults = True
autodoc_default_options = {"show-inheritance": True}

myst_enable_extensions = ["dollarmath", "amsmath", "colon_fence", "deflist"]
myst_heading_anchors = 3
myst_dmath_double_inline = True

sphinx_gallery_conf = {
    "examples_dirs": "examples",
    "gallery_dirs": "tutorials",
    # Every script in docs/examples is a tutorial: run them all, whatever their names.
    "filename_pattern": r".*\.py$",
    "ignore_pattern": r"(^|/)_",
    "within_subsection_order": "FileNameSortKey",
    "download_all_examples": False,
    "remove_config_comments": True,
    "matplotlib_animations": False,
    "image_scrapers": ("matplotlib",),
    "show_memory": False,
    "show_signature": False,
    "plot_gallery": "True",
    "abort_on_example_error": True,
    # Every tutorial runs on every build, not only those whose script changed: a tutorial's
    # output must be what today's code prints (the gallery's cache keys on the script alone).
    "run_stale_examples": True,
    # Generated pages would link to a Binder/JupyterLite; the site is offline: none.
    "first_notebook_cell": None,
    "capture_repr": (),
    "min_reported_time": 1,
    "write_computation_times": False,
}

# The build-time pictures of Getting started (plot directive): PNG only, no source links.
plot_formats = [("png", 110)]
plot_html_show_source_link = False
plot_html_show_formats = False
plot_include_source = False

html_theme = "pydata_sphinx_theme"
html_title = "asymslip"
html_static_path = ["_static"]
html_css_files = ["asymslip.css"]
html_last_updated_fmt = None
html_copy_source = False
html_show_sourcelink = False
html_theme_options: dict[str, Any] = {
    "navigation_with_keys": False,
    "show_prev_next": True,
    # Every page links to the one statement of the conventions (docs/_templates).
    "secondary_sidebar_items": ["page-toc", "conventions-link"],
    "footer_start": ["copyright"],
    "footer_end": [],
    "icon_links": [],
    "header_links_before_dropdown": 7,
}
html_sidebars: dict[str, list[str]] = {"index": [], "changelog": [], "benchmarks": []}


def _load_helpers() -> ModuleType:
    """docs/_ext/asymslip_docs by file path (Sphinx imports extensions by name; these are ours)."""
    folder = DOCS / "_ext" / "asymslip_docs"
    spec = importlib.util.spec_from_file_location(
        "asymslip_docs", folder / "__init__.py", submodule_search_locations=[str(folder)]
    )
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    spec.loader.exec_module(module)
    return module


_HELPERS = _load_helpers()


def setup(app: Any) -> dict[str, Any]:
    _HELPERS.setup(app)
    return {"parallel_read_safe": True}
