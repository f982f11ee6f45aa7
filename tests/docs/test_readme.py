"""The README is the front page: short, and every link in it leads into the site's sources.

The long descriptions, measured tables and examples live in the site (``docs/``); the README
says what the project is, shows a picture, the two commands and one example, and links there.
"""

from __future__ import annotations

import re
from pathlib import Path

from .site import DOCS, ROOT

README = ROOT / "README.md"
#: Markdown links and images: ``[text](target)`` and ``![alt](target)``.
LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)\)")


def _targets() -> list[str]:
    return LINK.findall(README.read_text(encoding="utf-8"))


def test_the_readme_is_a_front_page_under_150_lines():
    assert len(README.read_text(encoding="utf-8").splitlines()) < 150


def test_every_link_of_the_readme_leads_to_a_file_of_the_repository():
    targets = [target for target in _targets() if not re.match(r"[a-z]+:", target)]
    assert targets, "the README links nowhere"
    missing = [target for target in targets if not (ROOT / target.split("#")[0]).is_file()]
    assert missing == []


def test_the_readme_links_every_guide_page_or_its_index():
    linked = {Path(target).name for target in _targets()}
    guide = sorted(path.name for path in (DOCS / "guide").glob("*.md") if path.name != "index.md")
    assert [name for name in guide if name not in linked] == []


def test_the_readme_links_the_conventions_and_shows_a_picture():
    targets = _targets()
    assert "docs/conventions.md" in targets
    assert any(target.endswith(".png") for target in targets)
