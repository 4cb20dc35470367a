"""The step's page (``docs/steps/step06_lighting.md``) shows excerpts, not whole files, that fit the site's width.

Every code excerpt it includes (a ``--8<--`` section or a line range) has no line over 100 columns. Shader files
are included by named sections (``// --8<-- [start:NAME]`` / ``// --8<-- [end:NAME]``), never by line range: each
section exists exactly once in its file, its start before its end, and the lights loop is shown in both languages.
The one line range left (a Python stub's docstring) still starts and ends where the page expects, so an edit that
shifts its lines fails here instead of showing the wrong lines. Every concept has its picture pair from the tour
(``docs/images/step06_lighting-<concept>-<api>.png``), and every picture the page shows exists. Not graded.
"""

from __future__ import annotations

import re
import textwrap
from pathlib import Path

import pytest

from step06_lighting import CONCEPTS

ROOT = Path(__file__).resolve().parents[2]
PAGE = ROOT / "docs" / "steps" / "step06_lighting.md"
SNIPPET = re.compile(r'--8<-- "([^":]+)(?::([^"]+))?"')
MAX_COLUMNS = 100
SHADER_SUFFIXES = (".glsl", ".wgsl", ".vert", ".frag", ".geom", ".tesc", ".tese", ".comp")
#: line-range excerpts: (first line starts with, last line starts with), stripped
RANGES = {
    ("step06_lighting/exercises/lights.py", "3:10"): ("The block (", "vec4  color[64];"),
}
#: sections the page must show: the lights loop in both languages, the glass shader in both
REQUIRED_SECTIONS = {
    ("step06_lighting/shaders/lighting.glsl", "lights"),
    ("step06_lighting/shaders/lighting.wgsl", "lights"),
    ("step06_lighting/shaders/glass.frag", "fragment"),
    ("step06_lighting/shaders/glass.wgsl", "fragment"),
}


def _snippets() -> list[tuple[str, str | None]]:
    return SNIPPET.findall(PAGE.read_text())


def excerpt(path: str, spec: str | None) -> list[str]:
    """The lines pymdownx.snippets includes for ``path[:spec]`` (a section name or line ranges)."""
    lines = (ROOT / path).read_text().splitlines()
    if not spec:
        return lines
    if re.fullmatch(r"\d+:\d+(,\d+:\d+)*", spec):
        out = []
        for part in spec.split(","):
            start, end = (int(v) for v in part.split(":"))
            out += lines[start - 1:end]
        return out
    start = next(i for i, line in enumerate(lines) if f"--8<-- [start:{spec}]" in line)
    end = next(i for i, line in enumerate(lines) if f"--8<-- [end:{spec}]" in line)
    return textwrap.dedent("\n".join(lines[start + 1:end])).splitlines()  # dedent_subsections: true


@pytest.mark.parametrize("path,spec", [s for s in _snippets() if not s[0].endswith(".md")],
                         ids=lambda v: v or "-")
def test_excerpts_fit_and_are_not_whole_files(path, spec):
    assert spec, f"{path}: the page includes the whole file; show an excerpt (a section or a line range)"
    lines = excerpt(path, spec)
    assert lines, f"{path}:{spec} is empty"
    wide = [(n, len(line)) for n, line in enumerate(lines, 1) if len(line) > MAX_COLUMNS]
    assert not wide, f"{path}:{spec}: lines over {MAX_COLUMNS} columns (excerpt line, columns): {wide}"
    if (path, spec) in RANGES:
        first, last = RANGES[(path, spec)]
        got = (lines[0].strip(), lines[-1].strip())
        assert got[0].startswith(first) and got[1].startswith(last), (
            f"{path}:{spec} now starts with {got[0]!r} and ends with {got[1]!r} (expected {first!r} ... {last!r}): "
            "the file changed; update the line range on the page")
    else:
        assert not re.fullmatch(r"[\d:,]+", spec), f"{path}:{spec}: a new line range; add it to RANGES"


@pytest.mark.parametrize("path,spec", [s for s in _snippets() if s[0].endswith(SHADER_SUFFIXES)],
                         ids=lambda v: v or "-")
def test_shader_excerpts_are_named_sections(path, spec):
    assert spec and not re.fullmatch(r"[\d:,]+", spec), (
        f"{path}:{spec}: include shader code by a named section (// --8<-- [start:NAME] ... [end:NAME]), "
        "not a line range or the whole file")
    lines = (ROOT / path).read_text().splitlines()
    starts = [i for i, line in enumerate(lines) if line.strip() == f"// --8<-- [start:{spec}]"]
    ends = [i for i, line in enumerate(lines) if line.strip() == f"// --8<-- [end:{spec}]"]
    assert len(starts) == 1 and len(ends) == 1, (
        f"{path}: section {spec!r} needs exactly one start and one end marker (found {len(starts)}, {len(ends)})")
    assert starts[0] + 1 < ends[0], f"{path}: section {spec!r} is empty or ends before it starts"


def test_the_page_shows_the_lights_loop_and_the_glass_shader_in_both_languages():
    missing = REQUIRED_SECTIONS - set(_snippets())
    assert not missing, f"the page does not include these shader sections: {sorted(missing)}"
    text = PAGE.read_text()
    for section, tab in (("lighting.glsl:lights", '=== "OpenGL'), ("lighting.wgsl:lights", '=== "WebGPU')):
        before = text[:text.index(section)]
        nearest = before[before.rindex("\n=== ") + 1:].split("\n", 1)[0]
        assert nearest.startswith(tab), f"{section} should sit in a {tab}\" tab (it is under {nearest!r})"


def test_the_page_shows_every_concept_in_both_apis_and_its_pictures_exist():
    text = PAGE.read_text()
    for concept in CONCEPTS:
        for api in ("opengl", "webgpu"):
            assert f"../images/step06_lighting-{concept}-{api}.png" in text, f"{concept} ({api}) has no picture"
    for image in re.findall(r"\]\(\.\./images/([^)]+)\)", text):
        assert (ROOT / "docs" / "images" / image).is_file(), image


def test_code_blocks_on_the_page_fit():
    inside, wide = False, []
    for n, line in enumerate(PAGE.read_text().splitlines(), 1):
        if line.strip().startswith("```"):
            inside = not inside
        elif inside and len(line.strip()) > MAX_COLUMNS:
            wide.append(n)
    assert not wide, f"code lines over {MAX_COLUMNS} columns on the page: {wide}"
