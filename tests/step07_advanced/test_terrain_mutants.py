"""Plausible wrong answers to ``tess_level`` (``terrain_lod``), ``terrain_height`` and ``terrain_normal``, each of
which must fail at least one graded check of ``test_terrain.py`` (the graded tests, which a student's release keeps).
The tables are edits of the reference solution's shader text, so a student's release leaves this module out;
``tests/mutants/step07_advanced.py`` reads them from here for the mutation check (``python -m
gandalf_tools.grading.mutants``).
"""

from __future__ import annotations

from pathlib import Path

import pytest
from test_terrain import CHECKS

# --- mutants: plausible wrong answers, each must fail at least one graded check of its exercise -------------------
_GLSL = {
    "tess_level": ("float tess_level(vec3 a, vec3 b, vec3 eye, vec3 lod) {{ float d = distance(eye, 0.5 * (a + b)); "
                   "{body} }}"),
    "terrain_height": ("float terrain_height(vec2 uv) {{ int n = heightmap_size(); vec2 st = uv * float(n) - 0.5; "
                       "vec2 base = floor(st); vec2 f = st - base; ivec2 p0 = clamp(ivec2(base), ivec2(0), "
                       "ivec2(n - 1)); ivec2 p1 = clamp(ivec2(base) + 1, ivec2(0), ivec2(n - 1)); {body} }}"),
    "terrain_normal": ("vec3 terrain_normal(vec2 uv, vec2 scale) {{ float e = 1.0 / float(heightmap_size()); "
                       "float du = (terrain_height(uv + vec2(e, 0.0)) - terrain_height(uv - vec2(e, 0.0))) "
                       "/ (2.0 * e); float dv = (terrain_height(uv + vec2(0.0, e)) - "
                       "terrain_height(uv - vec2(0.0, e))) / (2.0 * e);"
                       " float k = scale.y / scale.x; {body} }}"),
}
_WGSL = {
    "tess_level": ("fn tess_level(a: vec3<f32>, b: vec3<f32>, eye: vec3<f32>, lod: vec3<f32>) -> f32 {{ "
                   "let d = distance(eye, 0.5 * (a + b)); {body} }}"),
    "terrain_height": ("fn terrain_height(uv: vec2<f32>) -> f32 {{ let n = heightmap_size(); "
                       "let st = uv * f32(n) - 0.5; let base = floor(st); let f = st - base; "
                       "let p0 = clamp(vec2<i32>(base), vec2<i32>(0), "
                       "vec2<i32>(n - 1)); let p1 = clamp(vec2<i32>(base) + 1, vec2<i32>(0), vec2<i32>(n - 1)); "
                       "{body} }}"),
    "terrain_normal": ("fn terrain_normal(uv: vec2<f32>, scale: vec2<f32>) -> vec3<f32> {{ "
                       "let e = 1.0 / f32(heightmap_size()); "
                       "let du = (terrain_height(uv + vec2<f32>(e, 0.0)) - terrain_height(uv - vec2<f32>(e, 0.0))) / "
                       "(2.0 * e); let dv = (terrain_height(uv + vec2<f32>(0.0, e)) - "
                       "terrain_height(uv - vec2<f32>(0.0, e))) / (2.0 * e); let k = scale.y / scale.x; {body} }}"),
}
_BILINEAR = ("return mix(mix(heightmap_texel(p0), heightmap_texel(ivec2(p1.x, p0.y)), f.x), "
             "mix(heightmap_texel(ivec2(p0.x, p1.y)), heightmap_texel(p1), f.x), f.y);")
_BILINEAR_WGSL = ("return mix(mix(heightmap_texel(p0), heightmap_texel(vec2<i32>(p1.x, p0.y)), f.x), "
                  "mix(heightmap_texel(vec2<i32>(p0.x, p1.y)), heightmap_texel(p1), f.x), f.y);")
_REFERENCE = {
    "tess_level": ("if (d < 1e-6) { return lod.z; } return clamp(lod.x * distance(a, b) / d, lod.y, lod.z);",
                   "if (d < 1e-6) { return lod.z; } return clamp(lod.x * distance(a, b) / d, lod.y, lod.z);"),
    "terrain_height": (_BILINEAR, _BILINEAR_WGSL),
    "terrain_normal": ("return normalize(vec3(-k * du, 1.0, -k * dv));",
                       "return normalize(vec3<f32>(-k * du, 1.0, -k * dv));"),
}
MUTANTS = {  # name -> (exercise, GLSL body, WGSL body)
    "level: no clamp": ("tess_level", "if (d < 1e-6) { return lod.z; } return lod.x * distance(a, b) / d;",
                        "if (d < 1e-6) { return lod.z; } return lod.x * distance(a, b) / d;"),
    "level: only the max clamp": ("tess_level", "if (d < 1e-6) { return lod.z; } return min(lod.x * distance(a, b) / "
                                  "d, lod.z);", "if (d < 1e-6) { return lod.z; } return min(lod.x * distance(a, b) / "
                                  "d, lod.z);"),
    "level: distance to the first corner": (
        "tess_level", "float d2 = distance(eye, a); if (d2 < 1e-6) { return lod.z; } return clamp(lod.x * "
        "distance(a, b) / d2, lod.y, lod.z);", "let d2 = distance(eye, a); if (d2 < 1e-6) { return lod.z; } return "
        "clamp(lod.x * distance(a, b) / d2, lod.y, lod.z);"),
    "level: squared distance": (
        "tess_level", "if (d < 1e-6) { return lod.z; } return clamp(lod.x * distance(a, b) / (d * d), lod.y, lod.z);",
        "if (d < 1e-6) { return lod.z; } return clamp(lod.x * distance(a, b) / (d * d), lod.y, lod.z);"),
    "level: min at distance zero": (
        "tess_level", "if (d < 1e-6) { return lod.y; } return clamp(lod.x * distance(a, b) / d, lod.y, lod.z);",
        "if (d < 1e-6) { return lod.y; } return clamp(lod.x * distance(a, b) / d, lod.y, lod.z);"),
    "level: no guard (0/0 for a point-sized edge)": (
        "tess_level", "return clamp(lod.x * distance(a, b) / d, lod.y, lod.z);",
        "return clamp(lod.x * distance(a, b) / d, lod.y, lod.z);"),
    "level: midpoint as a + (b - a) / 2 (not symmetric)": (
        "tess_level", "float m = distance(eye, a + 0.5 * (b - a)); if (m < 1e-6) { return lod.z; } "
        "return clamp(lod.x * distance(a, b) / m, lod.y, lod.z);",
        "let m = distance(eye, a + 0.5 * (b - a)); if (m < 1e-6) { return lod.z; } "
        "return clamp(lod.x * distance(a, b) / m, lod.y, lod.z);"),
    "height: no half-texel offset": (
        "terrain_height", "vec2 s2 = uv * float(n); vec2 b2 = floor(s2); vec2 g = s2 - b2; ivec2 q0 = clamp(ivec2(b2), "
        "ivec2(0), ivec2(n - 1)); ivec2 q1 = clamp(ivec2(b2) + 1, ivec2(0), ivec2(n - 1)); return mix(mix("
        "heightmap_texel(q0), heightmap_texel(ivec2(q1.x, q0.y)), g.x), mix(heightmap_texel(ivec2(q0.x, q1.y)), "
        "heightmap_texel(q1), g.x), g.y);",
        "let s2 = uv * f32(n); let b2 = floor(s2); let g = s2 - b2; let q0 = clamp(vec2<i32>(b2), vec2<i32>(0), "
        "vec2<i32>(n - 1)); let q1 = clamp(vec2<i32>(b2) + 1, vec2<i32>(0), vec2<i32>(n - 1)); return mix(mix("
        "heightmap_texel(q0), heightmap_texel(vec2<i32>(q1.x, q0.y)), g.x), mix(heightmap_texel(vec2<i32>(q0.x, "
        "q1.y)), heightmap_texel(q1), g.x), g.y);"),
    "height: no clamp": (
        "terrain_height", "ivec2 q0 = ivec2(base); ivec2 q1 = q0 + 1; return mix(mix(heightmap_texel(q0), "
        "heightmap_texel(ivec2(q1.x, q0.y)), f.x), mix(heightmap_texel(ivec2(q0.x, q1.y)), heightmap_texel(q1), f.x), "
        "f.y);",
        "let q0 = vec2<i32>(base); let q1 = q0 + 1; return mix(mix(heightmap_texel(q0), "
        "heightmap_texel(vec2<i32>(q1.x, q0.y)), f.x), mix(heightmap_texel(vec2<i32>(q0.x, q1.y)), "
        "heightmap_texel(q1), f.x), f.y);"),
    "height: nearest texel": (
        "terrain_height", "return heightmap_texel(clamp(ivec2(floor(uv * float(n))), ivec2(0), ivec2(n - 1)));",
        "return heightmap_texel(clamp(vec2<i32>(floor(uv * f32(n))), vec2<i32>(0), vec2<i32>(n - 1)));"),
    "height: u and v swapped": (
        "terrain_height", "return mix(mix(heightmap_texel(p0.yx), heightmap_texel(ivec2(p0.y, p1.x)), f.x), "
        "mix(heightmap_texel(ivec2(p1.y, p0.x)), heightmap_texel(p1.yx), f.x), f.y);",
        "return mix(mix(heightmap_texel(p0.yx), heightmap_texel(vec2<i32>(p0.y, p1.x)), f.x), "
        "mix(heightmap_texel(vec2<i32>(p1.y, p0.x)), heightmap_texel(p1.yx), f.x), f.y);"),
    "normal: not normalised": ("terrain_normal", "return vec3(-k * du, 1.0, -k * dv);",
                               "return vec3<f32>(-k * du, 1.0, -k * dv);"),
    "normal: wrong sign": ("terrain_normal", "return normalize(vec3(k * du, 1.0, k * dv));",
                           "return normalize(vec3<f32>(k * du, 1.0, k * dv));"),
    "normal: du and dv swapped": ("terrain_normal", "return normalize(vec3(-k * dv, 1.0, -k * du));",
                                  "return normalize(vec3<f32>(-k * dv, 1.0, -k * du));"),
    "normal: no world scale": ("terrain_normal", "return normalize(vec3(-du, 1.0, -dv));",
                               "return normalize(vec3<f32>(-du, 1.0, -dv));"),
    "normal: differences over e, not 2e": ("terrain_normal",
                                           "return normalize(vec3(-2.0 * k * du, 1.0, -2.0 * k * dv));",
                                           "return normalize(vec3<f32>(-2.0 * k * du, 1.0, -2.0 * k * dv));"),
}


#: Mutants whose result depends on the driver: where it gives the right answer, it is not wrong there.
DRIVER_DEPENDENT = {
    "level: no guard (0/0 for a point-sized edge)": "this driver's clamp turns NaN into max_level (NVIDIA's GLSL "
    "does), so the unguarded 0/0 happens to give the right level; llvmpipe and lavapipe do not",
}


def _write_mutant(folder: Path, language: str, exercise: str, body: str) -> None:
    heads = _GLSL if language == "glsl" else _WGSL
    column = 0 if language == "glsl" else 1
    parts = []
    for name, head in heads.items():
        parts.append(head.format(body=body if name == exercise else _REFERENCE[name][column]))
    (folder / f"terrain.{language}").write_text("\n".join(parts) + "\n")


@pytest.mark.parametrize("language", ["glsl", "wgsl"])
def test_the_mutant_frame_itself_passes(tmp_path, language):
    """The mutants' scaffold with the reference bodies passes every check (so a mutant fails for its change)."""
    _write_mutant(tmp_path, language, "", "")
    failures = [m for check in CHECKS.values() if (m := check[1](language, tmp_path)) is not None]
    assert not failures, failures


@pytest.mark.parametrize("language", ["glsl", "wgsl"])
@pytest.mark.parametrize("mutant", list(MUTANTS))
def test_every_mutant_fails_a_graded_check(tmp_path, mutant, language):
    exercise, glsl, wgsl = MUTANTS[mutant]
    _write_mutant(tmp_path, language, exercise, glsl if language == "glsl" else wgsl)
    for owner, check in CHECKS.values():
        if owner == exercise and check(language, tmp_path) is not None:
            return
    if mutant in DRIVER_DEPENDENT:
        pytest.xfail(DRIVER_DEPENDENT[mutant])
    pytest.fail(f"mutant '{mutant}' ({language}) passes every {exercise} check")
