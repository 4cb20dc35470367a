"""Plausible wrong answers to ``parallax``, each of which must fail at least one graded check of ``test_parallax.py``
(the graded tests, which a student's release keeps). The tables are edits of the reference solution's shader text, so
a student's release leaves this module out; ``tests/mutants/step07_advanced.py`` reads them from here for the
mutation check (``python -m gandalf_tools.grading.mutants``).
"""

from __future__ import annotations

from pathlib import Path

import pytest
from test_parallax import APPLIES, CHECKS

# --- mutants: plausible wrong answers, each must fail at least one graded check ---------------------------
SOLUTIONS = Path(__file__).resolve().parents[2] / "step07_advanced" / "solutions"
# name -> (the function it breaks, [(old, new) in GLSL], [(old, new) in WGSL]), applied to the reference solution
_SAME = "same"
MUTANTS: dict[str, tuple[str, list[tuple[str, str]], list[tuple[str, str]] | str]] = {
    "offset: moves with the view, not against it": (
        "parallax_offset", [("return uv - view_ts.xy / max(view_ts.z, PARALLAX_MIN_Z) * (scale * depth)",
                             "return uv + view_ts.xy / max(view_ts.z, PARALLAX_MIN_Z) * (scale * depth)")], _SAME),
    "offset: divides by z without the floor": (
        "parallax_offset", [("max(view_ts.z, PARALLAX_MIN_Z) * (scale * depth)", "view_ts.z * (scale * depth)")],
        _SAME),
    "offset: offset limiting (no division by z)": (
        "parallax_offset", [("view_ts.xy / max(view_ts.z, PARALLAX_MIN_Z) * (scale * depth)",
                             "view_ts.xy * (scale * depth)")], _SAME),
    "offset: height for depth": ("parallax_offset", [("depth = 1.0 - height_at(uv)", "depth = height_at(uv)")],
                                 _SAME),
    "offset: clamps uv to the tile": (
        "parallax_offset", [("return uv - view_ts.xy / max(view_ts.z, PARALLAX_MIN_Z) * (scale * depth);",
                             "return clamp(uv - view_ts.xy / max(view_ts.z, PARALLAX_MIN_Z) * (scale * depth), "
                             "0.0, 1.0);")],
        [("return uv - view_ts.xy / max(view_ts.z, PARALLAX_MIN_Z) * (scale * depth);",
          "return clamp(uv - view_ts.xy / max(view_ts.z, PARALLAX_MIN_Z) * (scale * depth), vec2<f32>(0.0), "
          "vec2<f32>(1.0));")]),
    "march: moves with the view": (
        "parallax_steep", [("return view_ts.xy / max(view_ts.z, PARALLAX_MIN_Z) * (scale",
                            "return -view_ts.xy / max(view_ts.z, PARALLAX_MIN_Z) * (scale")], _SAME),
    "march: divides by z without the floor": (
        "parallax_steep", [("view_ts.xy / max(view_ts.z, PARALLAX_MIN_Z) * (scale / ",
                            "view_ts.xy / view_ts.z * (scale / ")], _SAME),
    "march: no clamp of layers": (
        "parallax_steep", [("int n = clamp(layers, 1, PARALLAX_MAX_LAYERS);", "int n = layers;")],
        [("let n = clamp(layers, 1, PARALLAX_MAX_LAYERS);", "let n = layers;")]),
    "march: only the lower clamp of layers": (
        "parallax_steep", [("int n = clamp(layers, 1, PARALLAX_MAX_LAYERS);", "int n = max(layers, 1);")],
        [("let n = clamp(layers, 1, PARALLAX_MAX_LAYERS);", "let n = max(layers, 1);")]),
    "march: layer depth 1 / (n + 1) (off by one)": (
        "parallax_steep", [("float(i) / float(n)", "float(i) / float(n + 1)")],
        [("f32(i) / f32(n)", "f32(i) / f32(n + 1)")]),
    "march: layer depth (i + 1) / n (off by one)": (
        "parallax_steep", [("float(i) / float(n)", "float(i + 1) / float(n)")],
        [("f32(i) / f32(n)", "f32(i + 1) / f32(n)")]),
    "steep: skips layer 0": (
        "parallax_steep", [("for (int i = 0; i < n; ++i) {", "for (int i = 1; i < n; ++i) {")],
        [("for (var i = 0; i < n; i++) {", "for (var i = 1; i < n; i++) {")]),
    "steep: the last layer above the surface": (
        "parallax_steep", [("            return p;", "            return p + step * float(min(i, 1));")],
        [("            return p;", "            return p + step * f32(min(i, 1));")]),
    "occlusion: no interpolation (steep)": (
        "parallax_occlusion", [("(float(i - 1) + above / (above - below))", "float(i)")],
        [("(f32(i - 1) + above / (above - below))", "f32(i)")]),
    "occlusion: interpolation weights swapped": (
        "parallax_occlusion", [("above / (above - below)", "below / (below - above)")], _SAME),
    "occlusion: midpoint of the last two layers": (
        "parallax_occlusion", [("above / (above - below)", "0.5")], _SAME),
}


def _mutant_source(language: str, name: str) -> str:
    _function, glsl, wgsl = MUTANTS[name]
    edits = glsl if language == "glsl" or wgsl == _SAME else wgsl
    text = (SOLUTIONS / f"parallax.{language}").read_text()
    for old, new in edits:
        assert old in text, f"mutant '{name}': {old!r} is not in the {language} solution"
        text = text.replace(old, new)
    return text


@pytest.mark.parametrize("language", ["glsl", "wgsl"])
@pytest.mark.parametrize("mutant", list(MUTANTS))
def test_every_mutant_fails_a_graded_check(tmp_path, mutant, language):
    (tmp_path / f"parallax.{language}").write_text(_mutant_source(language, mutant))
    function = MUTANTS[mutant][0]
    for name in APPLIES[function]:
        if CHECKS[name](language, tmp_path, function) is not None:
            return
    pytest.fail(f"mutant '{mutant}' ({language}) passes every check of {function}: {list(APPLIES[function])}")
