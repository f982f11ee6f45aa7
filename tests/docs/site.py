"""Where the documentation tests find the built site and the browser, and when they may skip.

The site is built by ``make docs`` into ``docs/_build/html``; the browser test drives Debian's
Chromium (``make docs-tools`` installs it) through Playwright (the ``docs`` extra).  Where either
is missing the tests skip with one reason saying how to run them (``tests/conftest.py`` sums the
skips up in one line); where they are required -- ``make test-docs`` and CI set
``ASYMSLIP_REQUIRE_DOCS=1`` -- a missing site or browser is a failure, never a skip.

A site built from other sources than the working tree's is stale (an earlier checkout, a merge,
an edited docstring since the last ``make docs``): its checks would judge pages that no longer
describe the code, so they skip the same way, told by the stamp the build writes
(``docs/_ext/asymslip_docs/stamp.py``: a digest of every source, recomputed here).
"""

from __future__ import annotations

import importlib.util
import os
import shutil
from functools import cache
from pathlib import Path
from types import ModuleType

import pytest

ROOT = Path(__file__).resolve().parents[2]
DOCS = ROOT / "docs"
SITE = DOCS / "_build" / "html"
EXAMPLES = DOCS / "examples"
CHROMIUM = Path("/usr/bin/chromium")
#: Set to 1 where the site and the browser must be there (CI, ``make test-docs``).
REQUIRED = "ASYMSLIP_REQUIRE_DOCS"
#: The one skip reason of the site checks (the summary counts the skips by reason).
NOT_BUILT = "documentation site not built: `make test-docs` builds it and runs these checks"
STALE = "documentation site built from other sources: `make test-docs` rebuilds it and checks it"
NO_BROWSER = "no headless browser: `make test-docs` installs Chromium (Debian, as root) and runs it"


def _missing(reason: str) -> None:
    if os.environ.get(REQUIRED) == "1":
        pytest.fail(f"{reason} ({REQUIRED}=1)")
    pytest.skip(reason)


def stamp() -> ModuleType:
    """The build's stamp module, loaded by path (the docs helpers are not a package here)."""
    path = DOCS / "_ext" / "asymslip_docs" / "stamp.py"
    spec = importlib.util.spec_from_file_location("asymslip_docs_stamp", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@cache
def current() -> bool:
    """Whether the built site carries the digest of the working tree's sources."""
    module = stamp()
    written = SITE / module.NAME
    return written.is_file() and written.read_text().strip() == module.digest(ROOT)


def built_site() -> Path:
    """The built site's folder; skip (or fail where required) when it is not built, or was
    built from other sources than the working tree's."""
    if not (SITE / "index.html").is_file():
        _missing(NOT_BUILT)
    if not current():
        _missing(STALE)
    return SITE


def chromium() -> Path:
    """Debian's Chromium with Playwright to drive it; skip (or fail where required) without."""
    try:
        import playwright.sync_api  # noqa: F401
    except ImportError:
        _missing(NO_BROWSER)
    found = CHROMIUM if CHROMIUM.is_file() else None
    if found is None and shutil.which("chromium"):
        found = Path(shutil.which("chromium") or "")
    if found is None:
        _missing(NO_BROWSER)
    assert found is not None
    return found


def tutorials() -> list[Path]:
    """Every tutorial script: the gallery runs each one (names starting with _ are helpers)."""
    return sorted(path for path in EXAMPLES.glob("*.py") if not path.name.startswith("_"))


def pages(site: Path) -> list[Path]:
    """Every HTML page of the site (not the theme's template macros copied with its static
    files, nor the sources)."""
    return sorted(
        path
        for path in site.rglob("*.html")
        if "_sources" not in path.parts and "_static" not in path.parts
    )
