"""The built site: offline, its links resolve, and it documents everything there is.

Read from the HTML that ``make docs`` wrote (``docs/_build/html``) with the standard library's
parser; the lists of what must be there -- public names, commands and options, paper equations,
tutorials -- are computed here from the packages and the parser, independently of the docs'
own page writers.
"""

from __future__ import annotations

import argparse
import importlib
import inspect
import pkgutil
import re
import zlib
from collections.abc import Iterator
from html.parser import HTMLParser
from pathlib import Path
from urllib.parse import unquote, urlsplit

import pytest

from .site import built_site, pages, tutorials

#: Attributes that make the browser fetch something when the page loads.
LOADED = {
    "script": ("src",),
    "img": ("src", "srcset"),
    "source": ("src", "srcset"),
    "iframe": ("src",),
    "video": ("src", "poster"),
    "audio": ("src",),
    "embed": ("src",),
    "object": ("data",),
    "input": ("src",),
}
REMOTE = re.compile(r"^\s*(https?:)?//", re.I)
CSS_URL = re.compile(r"""url\(\s*['"]?([^'")]+)|@import\s+['"]([^'"]+)""", re.I)


class Page(HTMLParser):
    """What one HTML page loads, links to and defines as anchors."""

    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.loads: list[str] = []
        self.links: list[str] = []
        self.ids: set[str] = set()
        self.styles: list[str] = []
        self._in_style = False

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        values = {name: value or "" for name, value in attrs}
        for name in ("id", "name") if tag == "a" else ("id",):
            if values.get(name):
                self.ids.add(values[name])
        for name in LOADED.get(tag, ()):
            if values.get(name):
                self.loads.extend(
                    part.split()[0] for part in values[name].split(",") if part.strip()
                )
        if tag == "link" and values.get("href"):
            rel = values.get("rel", "").lower()
            if any(
                word in rel for word in ("stylesheet", "icon", "preload", "modulepreload", "font")
            ):
                self.loads.append(values["href"])
            else:
                self.links.append(values["href"])
        if tag == "a" and values.get("href"):
            self.links.append(values["href"])
        if values.get("style"):
            self.styles.append(values["style"])
        self._in_style = tag == "style"

    def handle_endtag(self, tag: str) -> None:
        if tag == "style":
            self._in_style = False

    def handle_data(self, data: str) -> None:
        if self._in_style:
            self.styles.append(data)


def parse(path: Path) -> Page:
    page = Page()
    page.feed(path.read_text(encoding="utf-8"))
    return page


@pytest.fixture(scope="module")
def site() -> Path:
    return built_site()


@pytest.fixture(scope="module")
def parsed(site: Path) -> dict[Path, Page]:
    return {path: parse(path) for path in pages(site)}


def test_the_site_has_its_sections(site: Path, parsed: dict[Path, Page]):
    for page in (
        "index.html",
        "getting-started.html",
        "tutorials/index.html",
        "theory/index.html",
        "theory/errata.html",
        "theory/beyond.html",
        "theory/error-map.html",
        "theory/trust.html",
        "reference/api/index.html",
        "reference/cli.html",
        "reference/languages/index.html",
        "reference/languages/c.html",
        "reference/languages/fortran.html",
        "reference/languages/matlab.html",
        "benchmarks.html",
        "changelog.html",
        "conventions.html",
        "guide/index.html",
    ):
        assert site / page in parsed, f"{page} is missing"


def test_every_page_links_to_the_conventions(site: Path, parsed: dict[Path, Page]):
    # The index of names and the search page are Sphinx's own, not pages of the site's text.
    own = {site / "genindex.html", site / "search.html", site / "py-modindex.html"}
    unlinked = [
        str(path.relative_to(site))
        for path, page in parsed.items()
        if path not in own
        and not any(
            (local := _local_target(path, href, site)) is not None
            and local[0] == site / "conventions.html"
            for href in page.links
        )
    ]
    assert len(parsed) > 100
    assert unlinked == []


def test_every_guide_page_is_in_the_site(site: Path):
    from .site import DOCS

    guide = sorted(path.stem for path in (DOCS / "guide").glob("*.md"))
    assert len(guide) >= 10
    assert [name for name in guide if not (site / "guide" / f"{name}.html").is_file()] == []


def test_the_trust_table_is_the_error_maps_data(site: Path):
    # Hertz, a2/a1 = 1.10, lambda/mu = 2, tension 0.2, right edge: (22)'s error in elements, read
    # here from the CSV the solver wrote, must be what the page shows (a hand copy went stale).
    import csv

    from .site import ROOT

    lines = (ROOT / "generated" / "report" / "error_map.csv").read_text().splitlines()
    rows = csv.DictReader(line for line in lines if not line.startswith("#"))
    (row,) = [
        r
        for r in rows
        if (r["law"], r["a2_a1"], r["lam_mu"], r["tau"], r["edge"])
        == ("hertz", "1.10", "2.00", "0.20", "right")
    ]
    text = (site / "theory" / "trust.html").read_text(encoding="utf-8")
    assert f"{float(row['b_paper_elements']):+.2f}" in text


def test_no_page_loads_anything_from_the_network(site: Path, parsed: dict[Path, Page]):
    remote = [
        f"{path.relative_to(site)}: {url}"
        for path, page in parsed.items()
        for url in page.loads + [u for style in page.styles for u in _css_urls(style)]
        if REMOTE.match(url)
    ]
    assert remote == []


def _css_urls(text: str) -> Iterator[str]:
    for match in CSS_URL.finditer(text):
        yield match.group(1) or match.group(2)


def test_no_stylesheet_loads_anything_from_the_network(site: Path):
    remote = [
        f"{path.relative_to(site)}: {url}"
        for path in site.rglob("*.css")
        for url in _css_urls(path.read_text(encoding="utf-8", errors="replace"))
        if REMOTE.match(url)
    ]
    assert remote == []


def test_mathjax_is_served_from_the_site(site: Path, parsed: dict[Path, Page]):
    section2 = parsed[site / "theory" / "section2.html"]
    scripts = [url for url in section2.loads if "mathjax" in url.lower()]
    assert scripts, "the theory page loads no MathJax"
    for url in scripts:
        target = (site / "theory" / urlsplit(url).path).resolve()
        assert target.is_file(), f"{url} is not in the built site"
    fonts = list((site / "_static" / "mathjax").rglob("*.woff"))
    assert fonts, "MathJax's fonts are not in the built site"


def _local_target(page: Path, href: str, site: Path) -> tuple[Path, str] | None:
    parts = urlsplit(href)
    if parts.scheme or parts.netloc or href.startswith(("mailto:", "javascript:")):
        return None
    target = page if not parts.path else (page.parent / unquote(parts.path)).resolve()
    if target.is_dir():
        target = target / "index.html"
    return target, unquote(parts.fragment)


def test_every_internal_link_and_anchor_resolves(site: Path, parsed: dict[Path, Page]):
    broken = []
    checked = 0
    for path, page in parsed.items():
        for href in page.links + page.loads:
            local = _local_target(path, href, site)
            if local is None:
                continue
            target, fragment = local
            checked += 1
            if not target.exists():
                broken.append(f"{path.relative_to(site)}: {href} (no such file)")
            elif fragment and target.suffix == ".html":
                ids = parsed[target].ids if target in parsed else parse(target).ids
                if fragment not in ids:
                    broken.append(f"{path.relative_to(site)}: {href} (no anchor {fragment!r})")
    assert checked > 1000, f"only {checked} links checked: is the site complete?"
    assert broken == []


def _public_names(module) -> list[str]:
    exported = getattr(module, "__all__", None)
    if exported is not None:
        return list(exported)
    return [
        name
        for name, value in vars(module).items()
        if not name.startswith("_")
        and (inspect.isclass(value) or inspect.isfunction(value))
        and value.__module__ == module.__name__
    ]


def _modules() -> Iterator[str]:
    for package in ("asymslip", "asymslip_gen"):
        root = importlib.import_module(package)
        yield package
        for info in pkgutil.walk_packages(root.__path__, f"{package}."):
            if not info.name.endswith("__main__") and not info.name.split(".")[-1].startswith("_"):
                yield info.name


def _inventory(site: Path) -> set[str]:
    data = (site / "objects.inv").read_bytes()
    body = data.split(b"\n", 4)[4]
    lines = zlib.decompress(body).decode("utf-8").splitlines()
    return {line.split(" ", 1)[0] for line in lines if " py:" in line}


def test_every_public_name_is_in_the_reference(site: Path):
    documented = _inventory(site)
    missing = []
    count = 0
    for name in _modules():
        module = importlib.import_module(name)
        if name not in documented:
            missing.append(name)
        for member in _public_names(module):
            count += 1
            value = getattr(module, member)
            home = getattr(value, "__module__", None)
            canonical = f"{home}.{getattr(value, '__qualname__', member)}" if home else None
            if f"{name}.{member}" not in documented and canonical not in documented:
                missing.append(f"{name}.{member}")
    assert count > 300, f"only {count} public names found"
    assert missing == []


def _commands(
    parser: argparse.ArgumentParser, prefix: str = "cli"
) -> Iterator[tuple[str, argparse.ArgumentParser]]:
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for name, sub in action.choices.items():
                anchor = f"{prefix}-{name}"
                yield anchor, sub
                yield from _commands(sub, anchor)


def test_every_command_and_option_is_in_the_reference(site: Path, parsed: dict[Path, Page]):
    from asymslip.cli import build_parser

    page = site / "reference" / "cli.html"
    text = page.read_text(encoding="utf-8")
    missing = []
    commands = list(_commands(build_parser()))
    assert len(commands) >= 7
    for anchor, parser in commands:
        if anchor not in parsed[page].ids:
            missing.append(anchor)
        for action in parser._actions:
            for option in action.option_strings:
                if f">{option}" not in text and f" {option}" not in text:
                    missing.append(f"{anchor}: {option}")
    assert missing == []


def test_every_paper_equation_is_on_a_theory_page(site: Path, parsed: dict[Path, Page]):
    ids = (
        parsed[site / "theory" / "section2.html"].ids
        | parsed[site / "theory" / "section3.html"].ids
    )
    assert [n for n in range(1, 52) if f"paper-eq-{n}" not in ids] == []


def test_every_tutorial_has_a_page_with_its_output(site: Path):
    for script in tutorials():
        page = site / "tutorials" / f"{script.stem}.html"
        assert page.is_file(), f"{script.name} has no page"
        assert "sphx-glr-script-out" in page.read_text(encoding="utf-8"), (
            f"{script.name}: no output"
        )


def test_every_generated_function_is_in_every_language_page(site: Path):
    import json

    from .site import ROOT

    records = json.loads((ROOT / "generated" / "asymslip_gen" / "formulas.json").read_text())
    pages_text = {
        language: (site / "reference" / "languages" / f"{language}.html").read_text(
            encoding="utf-8"
        )
        for language in ("c", "fortran", "matlab")
    }
    missing = [
        f"{language}: asymslip_{record['name']}"
        for record in records["formulas"]
        for language, text in pages_text.items()
        if f"asymslip_{record['name']}" not in text
    ]
    assert len(records["formulas"]) > 70
    assert missing == []
