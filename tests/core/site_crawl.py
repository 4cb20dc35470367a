"""Build the course site and read every page of it in headless Chromium: what ``tests/core/test_site.py`` checks.

``crawl(site_dir, base_url, widths)`` opens every HTML page of a ``mkdocs build`` (served at ``base_url``) at each
window width and returns, per width and page, what one script (``_FACTS``) measured in the browser:

* ``code``: code blocks whose lines wrap (more rendered lines than text lines: a line broken mid-token) or that are
  wider than their box without scrolling (no ``overflow-x: auto``) or with a hidden scrollbar; ``long_lines``
  counts code lines over ``LONG_LINE`` columns (they scroll: fine, but excerpts should stay short);
* ``tables``: tables whose box (the table, or the scrolling wrapper around it) sticks out of the content column;
* ``page_overflow``: the page itself wider than the window;
* ``maths``: every ``arithmatex`` element and whether KaTeX typeset it; ``formulas``: formula-shaped text left
  untypeset (a plain-text code block or prose with ``=`` and a mathematical symbol such as ``α²`` or ``n·l``);
* ``roles``: raw Sphinx roles (``:class:``, ``:func:`` ...) in the text outside code;
* ``diagrams``: the ``images/diagram_*`` pictures shown, with their alt text;
* ``prev`` / ``next``: the footer's previous and next links; ``headings``: the page's h2 headings;
* ``links``, ``images``, ``ids``: for the broken-link check.

Tabs of tabbed blocks and ``<details>`` are opened before measuring, so hidden blocks are measured too.
Console errors, uncaught exceptions and failed requests are collected as ``load`` problems.
"""

from __future__ import annotations

import functools
import http.server
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from urllib.parse import urljoin

#: Folders of docs/ whose Markdown files are tables included into pages by snippets (the studies' outputs); mkdocs
#: builds each into a page of its own too, which no page links to: they are checked where they are included.
SNIPPET_FOLDERS = ("images/",)
#: Code lines longer than this many columns are counted (they scroll inside their block).
LONG_LINE = 90
#: Milliseconds a page may take to load (a page loads in ~0.3 s here).
PAGE_TIMEOUT_MS = 20_000

_FACTS = """
(longLine) => {
  const style = document.createElement("style");
  style.textContent = ".tabbed-set > .tabbed-content > .tabbed-block { display: block !important; }";
  document.head.appendChild(style);
  document.querySelectorAll("details").forEach((d) => { d.open = true; });
  const article = document.querySelector("article.md-content__inner") || document.body;
  const column = (document.querySelector(".md-content") || document.body).getBoundingClientRect();
  const first = (el) => (el.textContent || "").trim().split("\\n")[0].slice(0, 80);
  const scrolls = (el) => {  // overflow does not clip an element drawn as a table: its wrapper must scroll
    const cs = getComputedStyle(el);
    return ["auto", "scroll"].includes(cs.overflowX) && cs.display !== "table";
  };
  const facts = {code: [], long_lines: 0, code_blocks: 0, code_scrolling: 0, tables: [], table_count: 0,
                 tables_scrolling: 0, maths: [], formulas: [], roles: [], diagrams: [], headings: []};

  article.querySelectorAll("pre").forEach((pre) => {
    const el = pre.querySelector(":scope > code") || pre;
    if (el.clientWidth === 0) return;
    facts.code_blocks++;
    const cs = getComputedStyle(el);
    const text = el.textContent.replace(/\\n$/, "");
    const lines = text.split("\\n");
    facts.long_lines += lines.filter((line) => line.length > longLine).length;
    const range = document.createRange();
    range.selectNodeContents(el);
    const lineHeight = parseFloat(cs.lineHeight);
    const rendered = Math.round(range.getBoundingClientRect().height / lineHeight);
    if (!(rendered <= lines.length)) {
      facts.code.push({problem: `${lines.length} lines drawn as ${rendered}: lines wrap`, first: first(el)});
    }
    if (el.scrollWidth > el.clientWidth + 1) {
      facts.code_scrolling++;
      if (!scrolls(el)) {
        facts.code.push({problem: `${el.scrollWidth} px wide in ${el.clientWidth} px, no scrollbar`, first: first(el)});
      } else if (cs.scrollbarWidth === "none") {
        facts.code.push({problem: "scrolls with its scrollbar hidden", first: first(el)});
      }
    }
    const lang = pre.closest('[class*="language-"]');
    const plain = !lang || /language-(text|plain|console)\b/.test(lang.className);
    if (plain && FORMULA.test(text)) facts.formulas.push(`code block: ${first(el)}`);
  });

  article.querySelectorAll("table").forEach((table) => {
    if (table.closest(".highlighttable") || table.clientWidth === 0) return;
    facts.table_count++;
    // The box that clips the table: the innermost scrolling box it overflows (Material's wrapper), else the
    // outermost scrolling box around it (it fits), else the table itself.
    let scroller = null;
    for (let el = table; el && el !== article; el = el.parentElement) {
      if (!scrolls(el)) continue;
      if (el.scrollWidth > el.clientWidth + 1) { scroller = el; break; }
      scroller = el;
    }
    const box = (scroller || table).getBoundingClientRect();
    const head = (table.querySelector("tr") || table).textContent.trim().replace(/\\s+/g, " ").slice(0, 60);
    if (box.right > column.right + 1 || box.left < column.left - 1) {
      facts.tables.push(`${Math.round(box.width)} px box at ${Math.round(box.left)}..${Math.round(box.right)} ` +
                        `in a ${Math.round(column.left)}..${Math.round(column.right)} column: ${head}`);
    } else if (scroller && scroller.scrollWidth > scroller.clientWidth + 1) {
      facts.tables_scrolling++;
    }
  });

  const page = document.scrollingElement;
  facts.page_overflow = page.scrollWidth > page.clientWidth + 1 ? `${page.scrollWidth} px in ${page.clientWidth}` : "";

  article.querySelectorAll(".arithmatex").forEach((el) => {
    facts.maths.push({tex: el.textContent.trim().slice(0, 60), typeset: el.querySelector(".katex") !== null});
  });

  const walker = document.createTreeWalker(article, NodeFilter.SHOW_TEXT);
  while (walker.nextNode()) {
    const node = walker.currentNode;
    if (node.parentElement.closest("pre, .katex, .arithmatex, script, style")) continue;
    const text = node.textContent;
    if (node.parentElement.closest("code")) continue;  // code quoting a role's syntax is no raw role
    const role = text.match(ROLE);
    if (role) facts.roles.push(`${role[0]} in "${text.trim().slice(0, 60)}"`);
    if (FORMULA.test(text)) {
      facts.formulas.push(`text: ${text.trim().slice(0, 70)}`);
    }
  }

  article.querySelectorAll("img").forEach((img) => {
    const src = img.getAttribute("src") || "";
    const name = src.split("/").pop();
    if (name.startsWith("diagram_")) facts.diagrams.push({name, alt: (img.getAttribute("alt") || "").trim()});
  });
  article.querySelectorAll("h2").forEach((h) => facts.headings.push(h.textContent.replace(/¶$/, "").trim()));
  facts.prev = document.querySelector("a.md-footer__link--prev")?.getAttribute("href") || "";
  facts.next = document.querySelector("a.md-footer__link--next")?.getAttribute("href") || "";
  facts.links = Array.from(document.querySelectorAll("a[href]"), (a) => a.getAttribute("href"));
  facts.images = Array.from(document.images, (img) => ({src: img.currentSrc || img.src,
                                                          ok: img.complete && img.naturalWidth > 0}));
  facts.ids = Array.from(document.querySelectorAll("[id]"), (el) => el.id);
  style.remove();
  return facts;
}
"""
#: A raw Sphinx role left in text: ``:class:`Scene``` renders as ":class:" then the name in code.
_ROLE = r"/:(?:py:)?(?:class|func|meth|attr|mod|obj|data|exc|const|ref|doc|term|envvar|option|kbd|file|samp):/"
#: Formula-shaped text: an equals sign (or ≈) on a line that also holds a Greek letter, a superscript, a square root,
#: a sum or integral sign, or a dot product written as "n·l".
_FORMULA = r"/(=|≈|∝)[^\n]*([α-ωΓ-Ω²³⁴⁵⁻√∑∫∂∇]|\w·\w)|([α-ωΓ-Ω²³⁴⁵⁻√∑∫∂∇]|\w·\w)[^\n]*(=|≈|∝)/"
_FACTS = _FACTS.replace("(longLine) => {", "(longLine) => {\n  const ROLE = " + _ROLE + ";\n  const FORMULA = "
                        + _FORMULA + ";", 1)


def pages(site: Path) -> list[str]:
    """Every HTML page of the site, as a path relative to its root (``steps/step04_camera/``)."""
    found = []
    for path in sorted(site.rglob("*.html")):
        rel = path.relative_to(site).as_posix()
        if rel == "404.html" or rel.startswith(SNIPPET_FOLDERS):
            continue
        found.append(rel[: -len("index.html")] if rel.endswith("index.html") else rel)
    return found


@contextmanager
def serve(site: Path) -> Iterator[str]:
    """Serve ``site`` on 127.0.0.1 (a free port) while the block runs; yields the base URL."""

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


def crawl(site: Path, server: str, chromium: str, widths: tuple[int, ...]) -> dict:
    """Open every page and measure it at every width; returns ``{"pages", "load", "facts": {width: {page: {...}}}}``."""
    from playwright.sync_api import sync_playwright

    found = pages(site)
    load: list[str] = []
    facts: dict[int, dict[str, dict]] = {}
    with sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=chromium, args=["--no-sandbox", "--disable-gpu"])
        # One load per page, measured at every width by resizing the window (the layout follows; no reload).
        page = browser.new_page(viewport={"width": widths[0], "height": 800})
        page.set_default_timeout(PAGE_TIMEOUT_MS)
        current = {"page": ""}
        page.on("console", lambda msg: msg.type == "error" and load.append(f"{current['page']}: {msg.text}"))
        page.on("pageerror", lambda exc: load.append(f"{current['page']}: uncaught {exc}"))
        # A request the browser itself aborts (the search worker's script, cut off when the crawl moves on) is no
        # broken resource: a missing file answers 404, which the response check catches.
        page.on("requestfailed", lambda req: req.url.startswith(server) and "ERR_ABORTED" not in str(req.failure)
                and load.append(f"{current['page']}: request failed: {req.url[len(server):]} ({req.failure})"))
        page.on("response", lambda res: res.url.startswith(server) and res.status >= 400
                and load.append(f"{current['page']}: HTTP {res.status} for {res.url[len(server):]}"))
        for number, rel in enumerate(found):
            current["page"] = rel or "index"
            if number == 1:
                # The search worker fetches and indexes the whole site (1 MB) on every page load. The first page
                # asks for it (a missing index or worker answers 404, which the response check reports); on the
                # others it is cut off (an aborted request, not a broken one), which takes a fifth off the crawl.
                for pattern in ("**/search/search_index.json", "**/assets/javascripts/workers/search*"):
                    page.route(pattern, lambda route: route.abort("aborted"))
            page.set_viewport_size({"width": widths[0], "height": 800})
            response = page.goto(urljoin(server, rel), wait_until="load")
            if response is None or response.status != 200:
                load.append(f"{rel}: HTTP {response.status if response else 'no response'}")
                continue
            for width in widths:
                if width != widths[0]:
                    page.set_viewport_size({"width": width, "height": 800})
                facts.setdefault(width, {})[rel] = page.evaluate(_FACTS, LONG_LINE)
        page.close()
        browser.close()
    return {"pages": found, "load": load, "facts": facts}
