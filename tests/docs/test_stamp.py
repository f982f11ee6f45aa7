"""The build's stamp: a site built from other sources than the working tree's is not checked.

``make docs`` writes the digest of the sources into the site; these tests build small trees of
their own, so they run without a built site.
"""

from __future__ import annotations

import os
from collections.abc import Iterator
from pathlib import Path

import pytest

from . import site

STAMP = site.stamp()


def _tree(root: Path) -> Path:
    """The smallest tree with every kind of source the site is built from."""
    for name, text in {
        "pyproject.toml": "[project]\n",
        "docs/conf.py": "project = 'x'\n",
        "docs/examples/tutorial.py": "print(1)\n",
        "src/asymslip/__init__.py": "'''The package.'''\n",
        "generated/report/derivation.md": "# report\n",
        "derivations/hertz.py": "a = 1\n",
    }.items():
        path = root / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return root


@pytest.fixture
def tree(tmp_path: Path) -> Path:
    return _tree(tmp_path)


@pytest.fixture
def fake_site(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[Path]:
    """A built site somewhere else than the real one, for the skip rules."""
    folder = tmp_path / "html"
    folder.mkdir()
    (folder / "index.html").write_text("<html></html>")
    monkeypatch.setattr(site, "SITE", folder)
    site.current.cache_clear()
    yield folder
    site.current.cache_clear()


def test_a_changed_source_changes_the_digest(tree: Path) -> None:
    before = STAMP.digest(tree)
    (tree / "src" / "asymslip" / "__init__.py").write_text("'''The package, edited.'''\n")
    assert STAMP.digest(tree) != before


def test_a_new_tutorial_changes_the_digest(tree: Path) -> None:
    before = STAMP.digest(tree)
    (tree / "docs" / "examples" / "another.py").write_text("print(2)\n")
    assert STAMP.digest(tree) != before


def test_what_the_build_writes_does_not_change_the_digest(tree: Path) -> None:
    before = STAMP.digest(tree)
    for name in (
        "docs/_build/html/index.html",
        "docs/tutorials/tutorial.py",
        "docs/reference/api/asymslip.rst",
        "docs/reference/languages/c.rst",
        "docs/theory/derivations/hertz.rst",
        "docs/examples/tutorial.png",
        "src/asymslip/__pycache__/__init__.cpython-311.pyc",
    ):
        path = tree / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text("written by a build")
    assert STAMP.digest(tree) == before


def test_a_file_time_alone_does_not_change_the_digest(tree: Path) -> None:
    before = STAMP.digest(tree)
    os.utime(tree / "docs" / "conf.py", (1.0, 1.0))
    assert STAMP.digest(tree) == before


def test_a_site_without_its_stamp_skips_as_stale(
    fake_site: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.delenv(site.REQUIRED, raising=False)
    with pytest.raises(pytest.skip.Exception, match="built from other sources"):
        site.built_site()


def test_a_site_of_other_sources_skips_as_stale(
    fake_site: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.delenv(site.REQUIRED, raising=False)
    (fake_site / STAMP.NAME).write_text("0" * 64 + "\n")
    with pytest.raises(pytest.skip.Exception, match="built from other sources"):
        site.built_site()


def test_a_stale_site_fails_where_the_site_is_required(
    fake_site: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv(site.REQUIRED, "1")
    (fake_site / STAMP.NAME).write_text("0" * 64 + "\n")
    with pytest.raises(pytest.fail.Exception, match="built from other sources"):
        site.built_site()


def test_a_site_of_the_working_tree_is_checked(
    fake_site: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv(site.REQUIRED, "1")
    (fake_site / STAMP.NAME).write_text(STAMP.digest(site.ROOT) + "\n")
    assert site.built_site() == fake_site
