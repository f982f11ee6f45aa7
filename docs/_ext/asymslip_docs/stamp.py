"""The build's stamp: a digest of every source the site is built from.

``make docs`` computes the digest before Sphinx starts and writes it into the built site
(``docs/_build/html/.sources-digest``) only when the build succeeded.  ``tests/docs`` computes
it again and compares: a site built from other sources than the working tree's (a merge, an
edited docstring, a new example since the last ``make docs``) is stale, and its checks skip with
one summary line on a developer's machine; where the site must be current
(``ASYMSLIP_REQUIRE_DOCS=1``: CI and ``make test-docs``, which have just built it) a stale or
missing site fails.

A content digest, not file times: a checkout that changes nothing does not make the site stale,
and a change that keeps a file's time does.  Standard library only (the tests load this file by
path).  Run as a script it prints the digest of the working tree.
"""

from __future__ import annotations

import hashlib
import sys
from collections.abc import Iterator
from pathlib import Path

#: The repository, from docs/_ext/asymslip_docs/stamp.py.
ROOT = Path(__file__).resolve().parents[3]
#: The stamp's name inside the built site.
NAME = ".sources-digest"
#: What the site is built from: the docs' own sources, the packages it documents, the records
#: and report the theory pages read, the derivations they link to, the project's metadata.
SOURCES = ("docs", "src", "generated", "derivations", "pyproject.toml")
#: Under docs/, what the build writes (pages written from the sources, the gallery's output).
WRITTEN = (
    "docs/_build",
    "docs/tutorials",
    "docs/reference/api",
    "docs/reference/languages",
    "docs/theory/derivations",
)
SKIPPED_PARTS = {"__pycache__", ".pytest_cache", ".ruff_cache", ".mypy_cache"}
SKIPPED_SUFFIXES = (".pyc", ".png", ".csv", ".parquet")


def _files(root: Path) -> Iterator[Path]:
    written = tuple(root / part for part in WRITTEN)
    for name in SOURCES:
        top = root / name
        if top.is_file():
            yield top
            continue
        for path in sorted(top.rglob("*")):
            if (
                not path.is_file()
                or SKIPPED_PARTS.intersection(path.parts)
                or path.name.endswith(".egg-info")
                or any(path.is_relative_to(folder) for folder in written)
                # A tutorial's saved figure (docs/examples/*.png) is its output, not a source.
                or (path.parent == root / "docs" / "examples" and path.suffix in SKIPPED_SUFFIXES)
            ):
                continue
            yield path


def digest(root: Path = ROOT) -> str:
    """SHA-256 over the relative path and the bytes of every source file, in path order."""
    total = hashlib.sha256()
    for path in _files(root):
        total.update(path.relative_to(root).as_posix().encode() + b"\0")
        total.update(hashlib.sha256(path.read_bytes()).digest())
    return total.hexdigest()


if __name__ == "__main__":
    sys.stdout.write(digest() + "\n")
