"""The built pages in a real headless browser: math typeset, figures loaded, nothing fetched.

Debian's Chromium, driven by Playwright, opens each page of the site from disk (file://) with
no network: every request the page makes is recorded, and any that leaves the site fails the
test.  On each page MathJax must have typeset every formula (no raw ``$$``, ``\\frac`` or
``\\[`` left in the text the reader sees), and every image must have loaded (naturalWidth > 0).
A screenshot of each page is saved to ``docs/_build/screenshots`` (not committed).
"""

from __future__ import annotations

import pytest

from .site import SITE, built_site, chromium, tutorials

#: Chromium's flags for a sandboxed, offline machine (no background traffic, a fresh profile).
FLAGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-first-run",
    "--disable-quic",
]
SCREENSHOTS = SITE.parent / "screenshots"
#: Pages with display math that MathJax must typeset, and the rest opened for their images.
MATH_PAGES = [
    "theory/section2.html",
    "theory/section3.html",
    "theory/errata.html",
    "theory/beyond.html",
]
OTHER_PAGES = [
    "index.html",
    "getting-started.html",
    "theory/error-map.html",
    "reference/cli.html",
    "reference/api/asymslip.slip_zones.html",
    "reference/api/asymslip_gen.corrective_slip.html",
    "benchmarks.html",
    "conventions.html",
    "theory/trust.html",
    "guide/slip-zone.html",
    "guide/stress.html",
]
RAW_TEX = ("$$", "\\frac", "\\sqrt", "\\[", "\\tag")


@pytest.fixture(scope="module")
def browser(tmp_path_factory: pytest.TempPathFactory):
    built_site()
    executable = chromium()
    from playwright.sync_api import sync_playwright

    profile = tmp_path_factory.mktemp("chromium-profile")
    with sync_playwright() as playwright:
        context = playwright.chromium.launch_persistent_context(
            str(profile),
            executable_path=str(executable),
            args=FLAGS,
            headless=True,
            viewport={"width": 1280, "height": 900},
        )
        yield context
        context.close()


def visit(browser, page_path: str) -> dict[str, object]:
    """Open one page; return what the reader sees and everything it fetched."""
    target = (SITE / page_path).resolve()
    assert target.is_file(), f"{page_path} is not built"
    page = browser.new_page()
    requests: list[str] = []
    failed: list[str] = []
    page.on("request", lambda request: requests.append(request.url))
    page.on("requestfailed", lambda request: failed.append(request.url))
    page.goto(target.as_uri(), wait_until="load")
    has_mathjax = page.evaluate("() => Boolean(window.MathJax && window.MathJax.startup)")
    if has_mathjax:
        page.wait_for_function("() => window.MathJax.startup.promise !== undefined", timeout=30_000)
        page.evaluate("() => window.MathJax.startup.promise")
    images = page.evaluate(
        """() => Array.from(document.images).map(img => ({
               src: img.currentSrc || img.src, ok: img.complete && img.naturalWidth > 0}))"""
    )
    sidebar = page.query_selector(".bd-sidebar-secondary")
    result = {
        "sidebar": sidebar.inner_text() if sidebar is not None else "",
        "text": page.inner_text("article")
        if page.query_selector("article")
        else page.inner_text("body"),
        "math": page.evaluate("() => document.querySelectorAll('mjx-container').length"),
        "images": images,
        "requests": requests,
        "failed": failed,
        "mathjax": has_mathjax,
        # A formula MathJax could not typeset is shown as an error box with the reason.
        "math_errors": page.evaluate(
            """() => Array.from(document.querySelectorAll('mjx-merror'))
                   .map(e => e.getAttribute('data-mjx-error'))"""
        ),
    }
    SCREENSHOTS.mkdir(parents=True, exist_ok=True)
    page.screenshot(
        path=str(SCREENSHOTS / (page_path.replace("/", "__") + ".png")), full_page=False
    )
    page.close()
    return result


def _outside(requests: list[str]) -> list[str]:
    return [url for url in requests if not url.startswith(("file://", "data:", "blob:"))]


@pytest.mark.parametrize("page_path", MATH_PAGES)
def test_math_is_typeset_offline(browser, page_path: str):
    seen = visit(browser, page_path)
    assert seen["mathjax"], "MathJax did not start"
    assert seen["math"] > 0, "no formula was typeset"
    assert seen["math_errors"] == []
    assert [tex for tex in RAW_TEX if tex in seen["text"]] == []
    assert _outside(seen["requests"]) == []
    assert seen["failed"] == []


def test_every_paper_equation_is_typeset(browser):
    count = sum(visit(browser, page)["math"] for page in MATH_PAGES[:2])
    assert count >= 51


@pytest.mark.parametrize("script", [path.stem for path in tutorials()])
def test_tutorial_figures_load(browser, script: str):
    seen = visit(browser, f"tutorials/{script}.html")
    figures = [image for image in seen["images"] if "sphx_glr" in image["src"]]
    assert figures, f"{script}: no figure on its page"
    assert [image["src"] for image in seen["images"] if not image["ok"]] == []
    assert _outside(seen["requests"]) == []
    assert seen["failed"] == []


@pytest.mark.parametrize("page_path", OTHER_PAGES)
def test_page_loads_offline_with_its_images(browser, page_path: str):
    seen = visit(browser, page_path)
    assert [image["src"] for image in seen["images"] if not image["ok"]] == []
    assert _outside(seen["requests"]) == []
    assert seen["failed"] == []
    assert [tex for tex in RAW_TEX if tex in seen["text"]] == []
    assert seen["math_errors"] == []


def test_the_stress_guide_shows_its_two_committed_figures(browser):
    seen = visit(browser, "guide/stress.html")
    shown = [image for image in seen["images"] if "_images" in image["src"]]
    assert len(shown) == 2 and all(image["ok"] for image in shown)


def test_the_conventions_link_is_beside_a_tutorial(browser):
    seen = visit(browser, "tutorials/fig5_cycle.html")
    assert "Conventions" in seen["sidebar"]


def test_getting_started_draws_which_edge_is_which(browser):
    seen = visit(browser, "getting-started.html")
    drawn = [
        image
        for image in seen["images"]
        if "getting-started" in image["src"] or "plot" in image["src"]
    ]
    assert drawn and all(image["ok"] for image in drawn)
