"""The built course site, read page by page in a real browser (headless Chromium driven by playwright).

The site is built with ``mkdocs build --strict`` into a temporary folder, served on 127.0.0.1 and every page is
opened at 1280 px and at 390 px (a phone) by ``tests/core/site_crawl.py``, which says what it measures. The tests
below hold the site to the standard of a good graphics book:

* every page loads without a console error, every same-site link and ``#anchor`` resolves, every image loads;
* no code block wraps a line (a token broken in two) or is wider than its box without a scrollbar;
* no table and no page is wider than the content column (a wide table scrolls inside its own box);
* every formula is typeset by KaTeX (served by the site itself), and no formula is left as plain text;
* no raw Sphinx role (``:class:`` ...) is shown, on the API page or elsewhere;
* at least ``MIN_DIAGRAMS`` diagrams, each with alt text; previous/next links on every page; a recap and a
  "Try next" on every step page; a sitemap listing every page; the repository linked from every page;
* the notebooks are pages of the site, with their pictures, linked from the curriculum.

The browser is Debian's ``chromium`` (``/usr/bin/chromium``, installed by ``scripts/setup.sh``), not a download of
playwright's own. Without it the tests are skipped, saying so; CI installs it, so there they run.
"""

from __future__ import annotations

import importlib
import inspect
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path
from urllib.parse import unquote, urldefrag, urljoin, urlparse

import pytest
from site_crawl import crawl, serve

ROOT = Path(__file__).resolve().parents[2]
CHROMIUM = os.environ.get("GANDALF_CHROMIUM", "/usr/bin/chromium")
#: The window widths every page is measured at: a laptop and a phone.
WIDTHS = (1280, 390)
MIN_DIAGRAMS = 10
#: The repository address the test builds the site with (mkdocs.yml reads it from GANDALF_REPO_URL).
REPO_URL = "https://git.invalid/gandalf"


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
                            env={**os.environ, "NO_MKDOCS_2_WARNING": "1", "GANDALF_REPO_URL": REPO_URL})
    assert result.returncode == 0, f"mkdocs build --strict failed:\n{result.stdout}\n{result.stderr}"
    return out


@pytest.fixture(scope="module")
def crawled(site: Path) -> dict:
    with serve(site) as server:
        result = crawl(site, server, CHROMIUM, WIDTHS)
    result["server"] = server
    assert len(result["pages"]) > 10, f"the build wrote only {result['pages']}"
    return result


def _report(problems: list[str], what: str) -> str:
    return f"{len(problems)} {what}:\n  " + "\n  ".join(problems[:60])


def _target_file(site: Path, path: str) -> Path | None:
    """The built file a URL path points to, or None."""
    candidate = site / unquote(path).lstrip("/")
    if candidate.is_dir():
        candidate = candidate / "index.html"
    return candidate if candidate.is_file() else None


def _rel(site: Path, built: Path) -> str:
    rel = built.relative_to(site).as_posix()
    return rel[: -len("index.html")] if rel.endswith("index.html") else rel


def test_pages_load_and_every_link_and_image_resolves(site: Path, crawled: dict) -> None:
    server, facts = crawled["server"], crawled["facts"][WIDTHS[0]]
    problems = list(crawled["load"])
    for rel, page in facts.items():
        url = urljoin(server, rel)
        for href in page["links"]:
            absolute = urljoin(url, href)
            if not absolute.startswith(server):
                continue  # another site: not checked (the site works offline, so it links out rarely)
            target, fragment = urldefrag(absolute)
            built = _target_file(site, urlparse(target).path)
            if built is None:
                problems.append(f"{rel}: link {href!r} -> {urlparse(target).path} does not exist in the build")
            elif fragment and built.suffix == ".html":
                target_rel = _rel(site, built)
                if target_rel in facts and unquote(fragment) not in facts[target_rel]["ids"]:
                    problems.append(f"{rel}: link {href!r}: no id {unquote(fragment)!r} on {target_rel or 'index'}")
        problems += [f"{rel}: image {image['src']} did not load" for image in page["images"] if not image["ok"]]
    assert not problems, _report(problems, f"load or link problems on {len(facts)} pages")


@pytest.mark.parametrize("width", WIDTHS)
def test_code_blocks_scroll_instead_of_wrapping(crawled: dict, width: int) -> None:
    problems = [f"{rel}: {block['problem']}: {block['first']!r}"
                for rel, page in crawled["facts"][width].items() for block in page["code"]]
    assert not problems, _report(problems, f"code blocks wrap or overflow at {width} px")


@pytest.mark.parametrize("width", WIDTHS)
def test_tables_and_pages_fit_the_column(crawled: dict, width: int) -> None:
    problems = [f"{rel}: table {table}" for rel, page in crawled["facts"][width].items() for table in page["tables"]]
    problems += [f"{rel}: the page is {page['page_overflow']} px wide"
                 for rel, page in crawled["facts"][width].items() if page["page_overflow"]]
    assert not problems, _report(problems, f"tables or pages wider than the column at {width} px")


def test_every_formula_is_typeset(crawled: dict) -> None:
    facts = crawled["facts"][WIDTHS[0]]
    problems = [f"{rel}: not typeset: {item['tex']!r}" for rel, page in facts.items() for item in page["maths"]
                if not item["typeset"]]
    problems += [f"{rel}: a formula in plain text ({item})" for rel, page in facts.items() for item in page["formulas"]]
    assert not problems, _report(problems, "formulas not typeset")
    typeset = sorted(rel for rel, page in facts.items() if page["maths"])
    expected = {"steps/step04_camera/", "steps/step06_lighting/", "steps/step07/pbr_model/",
                "steps/step07/pathtracer/", "steps/step07/parallax/"}
    assert expected <= set(typeset), f"pages with typeset maths: {typeset}; expected at least {sorted(expected)}"


def test_no_raw_sphinx_roles(crawled: dict) -> None:
    problems = [f"{rel}: {role}" for rel, page in crawled["facts"][WIDTHS[0]].items() for role in page["roles"]]
    assert not problems, _report(problems, "raw Sphinx roles shown")


def test_api_page_documents_every_public_class(crawled: dict) -> None:
    """Every class a package of gandalf_core exports (``__all__``) has its entry on the API page."""
    ids = set(crawled["facts"][WIDTHS[0]]["api/"]["ids"])
    missing = []
    for init in sorted((ROOT / "gandalf_core").rglob("__init__.py")):
        package = ".".join(init.parent.relative_to(ROOT).parts)
        module = importlib.import_module(package)
        for name in getattr(module, "__all__", ()):
            obj = getattr(module, name)
            if inspect.isclass(obj) and f"{obj.__module__}.{obj.__qualname__}" not in ids:
                missing.append(f"{package}.{name} ({obj.__module__}.{obj.__qualname__})")
    assert not missing, _report(missing, "public classes missing from the API page")


def test_diagrams_explain_with_alt_text(crawled: dict) -> None:
    shown: dict[str, str] = {}
    problems = []
    for rel, page in crawled["facts"][WIDTHS[0]].items():
        for diagram in page["diagrams"]:
            shown.setdefault(diagram["name"], rel)
            if len(diagram["alt"]) < 10:
                problems.append(f"{rel}: {diagram['name']} has no alt text worth the name ({diagram['alt']!r})")
    assert not problems, _report(problems, "diagrams without alt text")
    assert len(shown) >= MIN_DIAGRAMS, f"{len(shown)} diagrams shown ({sorted(shown)}); at least {MIN_DIAGRAMS} wanted"


def test_previous_next_on_every_page_and_recap_on_every_step_page(crawled: dict) -> None:
    facts = crawled["facts"][WIDTHS[0]]
    problems = [f"{rel or 'index'}: no previous/next link" for rel, page in facts.items()
                if not (page["prev"] or page["next"])]
    for rel, page in facts.items():
        if rel.startswith("steps/"):
            missing = [h for h in ("Recap", "Try next") if h not in page["headings"]]
            if missing:
                problems.append(f"{rel}: no {' and no '.join(missing)} section (h2 headings: {page['headings']})")
    assert not problems, _report(problems, "pages without previous/next or a step's recap")


def test_sitemap_lists_every_page_and_the_repository_is_linked(site: Path, crawled: dict) -> None:
    sitemap = (site / "sitemap.xml").read_text()
    locs = re.findall(r"<loc>([^<]+)</loc>", sitemap)
    assert locs and all(loc.startswith("http") for loc in locs), "sitemap.xml has no absolute <loc>: set site_url"
    listed = {urlparse(loc).path[1:] for loc in locs}  # site_url is a root: "/steps/step04_camera/"
    missing = [rel or "index" for rel in crawled["pages"] if rel not in listed]
    assert not missing, f"sitemap.xml lacks {missing}"
    index = (site / "index.html").read_text()
    assert f'href="{REPO_URL}"' in index and 'class="md-source"' in index, (
        "no repository link in the header: mkdocs.yml's repo_url must come from GANDALF_REPO_URL")


def test_notebooks_are_pages_with_pictures_linked_from_the_curriculum(site: Path, crawled: dict) -> None:
    facts = crawled["facts"][WIDTHS[0]]
    notebooks = sorted(p.stem for p in (ROOT / "notebooks").glob("*.ipynb"))
    curriculum = facts["curriculum/"]
    for name in notebooks:
        rel = f"notebooks/{name}/"
        assert rel in facts, f"notebook {name} is not a page of the site (expected {rel})"
        pictures = [img for img in facts[rel]["images"] if "/notebooks/" in img["src"]]
        assert pictures, f"the page of {name} shows none of the notebook's pictures"
        assert any(rel in urljoin(crawled["server"] + "curriculum/", href) for href in curriculum["links"]), (
            f"the curriculum does not link {name}")


def test_notebook_pages_show_the_notebooks_code() -> None:
    """docs/notebooks/NN.md is its notebook run by scripts/export_notebooks.py: its code blocks are the notebook's
    code cells, in order, so a changed notebook without a re-exported page fails here (no browser needed)."""
    nbformat = pytest.importorskip("nbformat", reason="needs the dev extra (nbformat)")
    for path in sorted((ROOT / "notebooks").glob("*.ipynb")):
        page = ROOT / "docs" / "notebooks" / f"{path.stem}.md"
        assert page.exists(), f"{path.name} has no page: run python scripts/export_notebooks.py --only {path.stem}"
        shown = re.findall(r"^```python\n(.*?)\n```$", page.read_text(), flags=re.DOTALL | re.MULTILINE)
        cells = [cell.source.rstrip() for cell in nbformat.read(path, as_version=4).cells if cell.cell_type == "code"]
        assert shown == cells, (f"{page.relative_to(ROOT)} is not {path.name} any more: "
                                f"run python scripts/export_notebooks.py --only {path.stem}")
        pictures = re.findall(r"\]\(\.\./images/notebooks/([^)]+)\)", page.read_text())
        assert pictures, f"{page.name} shows no picture"
        for name in pictures:
            assert (ROOT / "docs" / "images" / "notebooks" / name).exists(), f"{page.name}: {name} is missing"


def test_site_figures(crawled: dict) -> None:
    """Prints what was measured (run with -s to see it); the assertions are in the tests above."""
    for width in WIDTHS:
        facts = crawled["facts"][width]
        figures = {
            "pages": len(facts),
            "code blocks": sum(p["code_blocks"] for p in facts.values()),
            "code wrapping/overflowing": sum(len(p["code"]) for p in facts.values()),
            "code blocks scrolling": sum(p["code_scrolling"] for p in facts.values()),
            "code lines > 90 cols": sum(p["long_lines"] for p in facts.values()),
            "tables": sum(p["table_count"] for p in facts.values()),
            "tables overflowing": sum(len(p["tables"]) for p in facts.values()),
            "tables scrolling in their box": sum(p["tables_scrolling"] for p in facts.values()),
            "pages wider than window": sum(bool(p["page_overflow"]) for p in facts.values()),
            "pages with typeset maths": sum(bool(p["maths"]) for p in facts.values()),
            "formulas untypeset": sum(len(p["formulas"]) + sum(not m["typeset"] for m in p["maths"])
                                      for p in facts.values()),
            "raw roles": sum(len(p["roles"]) for p in facts.values()),
            "diagrams": len({d["name"] for p in facts.values() for d in p["diagrams"]}),
            "pages without prev/next": sum(not (p["prev"] or p["next"]) for p in facts.values()),
        }
        print(f"\nsite at {width} px: " + ", ".join(f"{k} {v}" for k, v in figures.items()))
    print(f"load problems {len(crawled['load'])}")


def test_site_test_finds_the_browser_set_up_installs() -> None:
    """setup.sh installs Debian's chromium, the browser this test drives (not playwright's own download)."""
    setup = (ROOT / "scripts" / "setup.sh").read_text()
    assert "chromium" in setup, "scripts/setup.sh must install Debian's chromium for tests/core/test_site.py"
    if not Path(CHROMIUM).exists() and shutil.which("chromium") is None:
        pytest.skip(f"no Chromium at {CHROMIUM} on this machine")


def test_make_diagrams_helps_refuses_to_overwrite_and_draws(tmp_path: Path) -> None:
    """scripts/make_diagrams.py: --help only prints help; it keeps existing files unless --force; it draws every
    diagram, each an SVG of at most 100 KiB whose text stays text, the same bytes as the committed one and shown on
    a page of docs/."""
    pytest.importorskip("matplotlib", reason="the diagrams need the dev extra (matplotlib)")
    script = [sys.executable, str(ROOT / "scripts" / "make_diagrams.py")]
    helped = subprocess.run([*script, "--help", "--out", str(tmp_path)], capture_output=True, text=True, timeout=60)
    assert helped.returncode == 0 and "usage:" in helped.stdout, helped.stderr
    assert not list(tmp_path.iterdir()), "--help must not write anything"
    drawn = subprocess.run([*script, "--out", str(tmp_path)], capture_output=True, text=True, timeout=300)
    assert drawn.returncode == 0, drawn.stderr
    names = sorted(p.name for p in tmp_path.glob("diagram_*.svg"))
    assert len(names) >= MIN_DIAGRAMS, names
    committed = sorted(p.name for p in (ROOT / "docs" / "images").glob("diagram_*"))
    assert names == committed, f"drawn {names}, committed {committed}: run scripts/make_diagrams.py --force"
    before = {p: p.stat().st_mtime_ns for p in tmp_path.iterdir()}
    again = subprocess.run([*script, "--out", str(tmp_path), "--only", names[0]], capture_output=True, text=True,
                           timeout=60)
    assert again.returncode == 1 and "--force" in again.stderr, (again.returncode, again.stderr)
    assert before == {p: p.stat().st_mtime_ns for p in tmp_path.iterdir()}, "files changed without --force"
    pages = "\n".join(p.read_text() for p in (ROOT / "docs").rglob("*.md"))
    for name in names:
        drawn_svg = (tmp_path / name).read_bytes()
        assert len(drawn_svg) <= 100 * 1024, f"{name} is {len(drawn_svg) // 1024} KiB"
        assert b"<text" in drawn_svg, f"{name}: its text was drawn as paths"
        assert drawn_svg == (ROOT / "docs" / "images" / name).read_bytes(), (
            f"{name} differs from the committed one: run scripts/make_diagrams.py --force --only {name}")
        assert f"images/{name}" in pages, f"{name} is on no page of docs/"
