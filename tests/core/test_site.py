"""The built course site, opened page by page in a real browser (headless Chromium driven by playwright).

The site is built with ``mkdocs build --strict`` into a temporary folder and served on 127.0.0.1. Every page is
opened at 1280 x 800 and checked for:

* loading: HTTP 200, no JavaScript console error, no uncaught exception, no failed request for a file of the site;
* links and images: every same-site link points to a page or file the build wrote, and its ``#anchor`` to an id on
  that page; every ``<img>`` has loaded (``naturalWidth > 0``);
* maths: every ``arithmatex`` element (``$...$`` / ``$$...$$`` in the Markdown) holds a KaTeX rendering;
* width: no code block (``pre`` or its ``code``) and no display formula is wider than its box
  (``scrollWidth > clientWidth``), nor the page wider than the window, with the tabs of tabbed blocks and
  ``<details>`` all opened so hidden blocks are measured too.

Every page means every HTML page of the build except ``404.html`` and the study tables under ``images/``, which
are included into the step pages and checked there.

The browser is Debian's ``chromium`` (``/usr/bin/chromium``, installed by ``scripts/setup.sh``), not a download of
playwright's own. Without it the test is skipped, saying so; CI installs it, so there it runs.
"""

from __future__ import annotations

import functools
import http.server
import os
import shutil
import subprocess
import sys
import threading
from collections.abc import Iterator
from pathlib import Path
from urllib.parse import unquote, urldefrag, urljoin, urlparse

import pytest

ROOT = Path(__file__).resolve().parents[2]
CHROMIUM = os.environ.get("GANDALF_CHROMIUM", "/usr/bin/chromium")
VIEWPORT = {"width": 1280, "height": 800}
#: Folders of docs/ whose Markdown files are tables included into pages by snippets (the studies' outputs); mkdocs
#: builds each into a page of its own too, which no page links to: they are checked where they are included.
SNIPPET_FOLDERS = ("images/",)
#: Seconds a page may take to load (the software renderer makes nothing slow here; a page loads in ~0.3 s).
PAGE_TIMEOUT_MS = 20_000

# Opens every tab and <details> and measures every code block. Returns the overflowing ones.
_MEASURE = """
() => {
  const style = document.createElement("style");
  style.textContent = ".tabbed-set > .tabbed-content > .tabbed-block { display: block !important; }";
  document.head.appendChild(style);
  document.querySelectorAll("details").forEach((d) => { d.open = true; });
  const out = [];
  document.querySelectorAll("pre, pre > code, div.arithmatex").forEach((el) => {
    if (el.clientWidth > 0 && el.scrollWidth > el.clientWidth + 1) {
      const text = (el.textContent || "").trim().split("\\n")[0].slice(0, 80);
      out.push({tag: el.tagName, scroll: el.scrollWidth, client: el.clientWidth, first_line: text});
    }
  });
  const page = document.scrollingElement;
  if (page.scrollWidth > page.clientWidth + 1) {
    out.push({tag: "html", scroll: page.scrollWidth, client: page.clientWidth, first_line: "the page itself"});
  }
  style.remove();
  return out;
}
"""

_LINKS = """
() => Array.from(document.querySelectorAll("a[href]"), (a) => a.getAttribute("href"))
"""

_IMAGES = """
() => Array.from(document.images, (img) => ({src: img.currentSrc || img.src, ok: img.complete && img.naturalWidth > 0}))
"""

_IDS = """
() => Array.from(document.querySelectorAll("[id]"), (el) => el.id)
"""

_MATHS = """
() => Array.from(document.querySelectorAll(".arithmatex"), (el) => ({
  tex: el.textContent.trim().slice(0, 60), typeset: el.querySelector(".katex") !== null,
}))
"""


def _chromium_or_skip() -> None:
    if not Path(CHROMIUM).exists():
        pytest.skip(f"no Chromium at {CHROMIUM}: install Debian's package ('apt-get install chromium', which "
                    "scripts/setup.sh does as root) or set GANDALF_CHROMIUM to a Chromium binary")
    pytest.importorskip("playwright", reason="the site test needs the dev extra (playwright)")


@pytest.fixture(scope="module")
def site(tmp_path_factory: pytest.TempPathFactory) -> Path:
    _chromium_or_skip()
    out = tmp_path_factory.mktemp("site")
    mkdocs = [sys.executable, "-m", "mkdocs", "build", "--strict", "-q", "-d", str(out)]
    result = subprocess.run(mkdocs, cwd=ROOT, capture_output=True, text=True, timeout=300,
                            env={**os.environ, "NO_MKDOCS_2_WARNING": "1"})
    assert result.returncode == 0, f"mkdocs build --strict failed:\n{result.stdout}\n{result.stderr}"
    return out


@pytest.fixture(scope="module")
def server(site: Path) -> Iterator[str]:
    class Quiet(http.server.SimpleHTTPRequestHandler):
        def log_message(self, *args: object) -> None:
            pass

    httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(Quiet, directory=str(site)))
    thread = threading.Thread(target=httpd.serve_forever, daemon=True)
    thread.start()
    try:
        yield f"http://127.0.0.1:{httpd.server_address[1]}/"
    finally:
        httpd.shutdown()
        httpd.server_close()


def _pages(site: Path) -> list[str]:
    """Every HTML page of the site, as a path relative to its root (``steps/step04_camera/``)."""
    pages = []
    for path in sorted(site.rglob("*.html")):
        rel = path.relative_to(site).as_posix()
        if rel == "404.html" or rel.startswith(SNIPPET_FOLDERS):
            continue
        pages.append(rel[: -len("index.html")] if rel.endswith("index.html") else rel)
    return pages


def _target_file(site: Path, path: str) -> Path | None:
    """The built file a URL path points to, or None."""
    candidate = site / unquote(path).lstrip("/")
    if candidate.is_dir():
        candidate = candidate / "index.html"
    return candidate if candidate.is_file() else None


def test_every_page_loads_links_resolve_maths_renders_and_no_code_block_overflows(site: Path, server: str) -> None:
    from playwright.sync_api import sync_playwright

    pages = _pages(site)
    assert len(pages) > 10, f"the build wrote only {pages}"
    problems: dict[str, list[str]] = {"load": [], "console": [], "links": [], "images": [], "maths": [],
                                      "overflow": []}
    ids: dict[str, set[str]] = {}
    anchored_links: list[tuple[str, str, str, str]] = []  # (page, href, target page, fragment)
    maths_pages = 0
    with sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=CHROMIUM, args=["--no-sandbox", "--disable-gpu"])
        page = browser.new_page(viewport=VIEWPORT)
        page.set_default_timeout(PAGE_TIMEOUT_MS)
        current = {"page": ""}
        page.on("console", lambda msg: msg.type == "error" and problems["console"].append(
            f"{current['page']}: {msg.text}"))
        page.on("pageerror", lambda exc: problems["console"].append(f"{current['page']}: uncaught {exc}"))
        # A request the browser itself aborts (the search worker's script, cut off when the test moves to the next
        # page) is no broken resource: a missing file answers 404, which the response check below catches.
        page.on("requestfailed", lambda req: req.url.startswith(server) and "ERR_ABORTED" not in str(req.failure)
                and problems["load"].append(
                    f"{current['page']}: request failed: {req.url[len(server):]} ({req.failure})"))
        page.on("response", lambda res: res.url.startswith(server) and res.status >= 400 and problems["load"].append(
            f"{current['page']}: HTTP {res.status} for {res.url[len(server):]}"))
        for rel in pages:
            current["page"] = rel or "index"
            url = urljoin(server, rel)
            response = page.goto(url, wait_until="load")
            if response is None or response.status != 200:
                problems["load"].append(f"{rel}: HTTP {response.status if response else 'no response'}")
                continue
            ids[rel] = set(page.evaluate(_IDS))
            for href in page.evaluate(_LINKS):
                absolute = urljoin(url, href)
                if not absolute.startswith(server):
                    continue  # another site: not checked (the site must work offline, so it links out rarely)
                target, fragment = urldefrag(absolute)
                target_path = urlparse(target).path
                built = _target_file(site, target_path)
                if built is None:
                    problems["links"].append(f"{rel}: link {href!r} -> {target_path} does not exist in the build")
                elif fragment and built.suffix == ".html":
                    target_rel = built.relative_to(site).as_posix()
                    target_rel = target_rel[: -len("index.html")] if target_rel.endswith("index.html") else target_rel
                    anchored_links.append((rel, href, target_rel, unquote(fragment)))
            for image in page.evaluate(_IMAGES):
                if not image["ok"]:
                    problems["images"].append(f"{rel}: image {image['src']} did not load")
            maths = page.evaluate(_MATHS)
            maths_pages += bool(maths)
            for item in maths:
                if not item["typeset"]:
                    problems["maths"].append(f"{rel}: not typeset: {item['tex']!r}")
            for block in page.evaluate(_MEASURE):
                problems["overflow"].append(
                    f"{rel}: <{block['tag'].lower()}> {block['scroll']} px wide in {block['client']} px: "
                    f"{block['first_line']!r}")
        browser.close()
    for rel, href, target, fragment in anchored_links:
        if target in ids and fragment not in ids[target]:
            problems["links"].append(f"{rel}: link {href!r}: no id {fragment!r} on {target or 'index'}")
    assert maths_pages >= 2, "no page has typeset maths (expected at least steps 04 and 06): is arithmatex on?"
    report = [f"{kind}: {len(items)}\n  " + "\n  ".join(items[:60]) for kind, items in problems.items() if items]
    assert not report, f"{len(pages)} pages checked at {VIEWPORT['width']} px:\n" + "\n".join(report)


def test_site_test_finds_the_browser_set_up_installs() -> None:
    """setup.sh installs Debian's chromium, the browser this test drives (not playwright's own download)."""
    setup = (ROOT / "scripts" / "setup.sh").read_text()
    assert "chromium" in setup, "scripts/setup.sh must install Debian's chromium for tests/core/test_site.py"
    if not Path(CHROMIUM).exists() and shutil.which("chromium") is None:
        pytest.skip(f"no Chromium at {CHROMIUM} on this machine")


def test_make_diagrams_helps_refuses_to_overwrite_and_draws(tmp_path: Path) -> None:
    """scripts/make_diagrams.py: --help only prints help; it keeps existing files unless --force; it draws all four."""
    pytest.importorskip("matplotlib", reason="the diagrams need the dev extra (matplotlib)")
    script = [sys.executable, str(ROOT / "scripts" / "make_diagrams.py")]
    helped = subprocess.run([*script, "--help", "--out", str(tmp_path)], capture_output=True, text=True, timeout=60)
    assert helped.returncode == 0 and "usage:" in helped.stdout, helped.stderr
    assert not list(tmp_path.iterdir()), "--help must not write anything"
    drawn = subprocess.run([*script, "--out", str(tmp_path)], capture_output=True, text=True, timeout=120)
    assert drawn.returncode == 0, drawn.stderr
    names = sorted(p.name for p in tmp_path.glob("diagram_*.png"))
    assert names == ["diagram_ecs_frame.png", "diagram_pipeline.png", "diagram_sampling.png", "diagram_spaces.png"]
    before = {p: p.stat().st_mtime_ns for p in tmp_path.iterdir()}
    again = subprocess.run([*script, "--out", str(tmp_path)], capture_output=True, text=True, timeout=60)
    assert again.returncode == 1 and "--force" in again.stderr, (again.returncode, again.stderr)
    assert before == {p: p.stat().st_mtime_ns for p in tmp_path.iterdir()}, "files changed without --force"
    for name in names:  # every diagram the script draws is on a page of the site
        pages = [p for p in (ROOT / "docs").rglob("*.md") if name in p.read_text()]
        assert pages, f"{name} is on no page of docs/"
