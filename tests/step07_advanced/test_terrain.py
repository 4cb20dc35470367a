"""Exercises ``tess_level``, ``terrain_height`` and ``terrain_normal`` (step07 terrain): the student's GLSL and WGSL
functions, run on the GPU through the shader harness (a compute shader per language) and compared with the float64
numpy twins in ``step07_advanced.terrain.heightfield`` on the same float32-rounded inputs.

The heightmap functions the exercise file relies on (``heightmap_size``, ``heightmap_texel``) are defined by each
test's prelude: small analytic maps (a hashed random field, a linear ramp, a flat map) computed exactly the same
way in numpy. A texel read outside [0, N − 1] returns −1000, so a missing clamp shows as a huge error.

Tolerances (absolute): ``tess_level`` ≤ 1e-4 · level (relative) and exactly the same level for both directions of
an edge; ``terrain_height`` ≤ 2e-5 (texel values in [0, 1]); ``terrain_normal`` ≤ 2e-4 per component, a flat map
within 1e-6 of (0, 1, 0). Every result must be finite. The reference solution measures at most 8e-7
(levels, relative), 1e-7 (heights) and 1.7e-6 (normals) on llvmpipe and lavapipe. Every check also runs on a set
of plausible wrong implementations (mutants, in ``test_terrain_mutants.py``), each of which must fail at least one.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest
from shader_checks import LANGUAGE, impl_dir
from shader_harness import evaluate, gl_context

from step07_advanced.showcase.particles import hash_u32  # lowbias32, the kernels' hash
from step07_advanced.terrain.heightfield import height_np, normal_np, tess_level_np

OUT_OF_RANGE = -1000.0
HINT = {
    "level": "level = clamp(scale * |b - a| / distance(eye, (a + b) / 2), min_level, max_level), "
             "lod = (scale, min, max)",
    "clamp": "clamp to [min_level, max_level]; the camera on the midpoint (distance < 1e-6) gives max_level, never NaN",
    "symmetric": "compute the midpoint as (a + b) / 2 so that tess_level(a, b) and tess_level(b, a) agree exactly: "
                 "two patches share each edge and walk it in opposite directions",
    "height": "bilinear between texel centres at (texel + 0.5) / N: st = uv * N - 0.5, base = floor(st), "
              "f = st - base; u picks the column, v the row",
    "edges": "clamp the texel indices to [0, N - 1] before calling heightmap_texel (clamp addressing)",
    "normal": "normalize(-height_scale / size * dh/du, 1, -height_scale / size * dh/dv) with central differences "
              "(terrain_height(uv + e) - terrain_height(uv - e)) / (2 e), e = 1 / N, scale = (size, height_scale)",
    "flat": "on a flat map both differences are 0: the normal is exactly (0, 1, 0)",
}


# --- heightmaps defined in the prelude (GLSL, WGSL) and in numpy ---------------------------------------------
MAPS = {  # name -> (N, GLSL expression, WGSL expression) of the texel p = (column, row)
    "random": (16, "float(hm_hash(uint(p.x + p.y * 16)) >> 8u) / 16777216.0",
               "f32(hm_hash(u32(p.x + p.y * 16)) >> 8u) / 16777216.0"),
    "ramp": (64, "(float(p.x) * 3.0 + float(p.y) * 5.0) / 512.0", "(f32(p.x) * 3.0 + f32(p.y) * 5.0) / 512.0"),
    "flat": (32, "0.375", "0.375"),
}


def map_np(name: str) -> np.ndarray:
    """The (N, N) float32 texel values (row, column) that the prelude's heightmap_texel returns."""
    n = MAPS[name][0]
    row, col = np.mgrid[0:n, 0:n]
    if name == "random":
        return ((hash_u32(col + row * n) >> np.uint32(8)).astype(np.float32) / np.float32(16777216.0))
    if name == "ramp":
        return (col.astype(np.float32) * np.float32(3) + row.astype(np.float32) * np.float32(5)) / np.float32(512)
    return np.full((n, n), 0.375, dtype=np.float32)


def prelude(language: str, heightmap: str) -> str:
    n, glsl, wgsl = MAPS[heightmap]
    if language == "glsl":
        return f"""uint hm_hash(uint x) {{
    x ^= x >> 16; x *= 0x7FEB352Du; x ^= x >> 15; x *= 0x846CA68Bu; x ^= x >> 16; return x;
}}
int heightmap_size() {{ return {n}; }}
float heightmap_texel(ivec2 p) {{
    if (p.x < 0 || p.y < 0 || p.x >= {n} || p.y >= {n}) {{ return {OUT_OF_RANGE:.1f}; }}
    return {glsl};
}}
#include "terrain.glsl"
"""
    return f"""fn hm_hash(v: u32) -> u32 {{
    var x = v;
    x ^= x >> 16u; x *= 0x7FEB352Du; x ^= x >> 15u; x *= 0x846CA68Bu; x ^= x >> 16u; return x;
}}
fn heightmap_size() -> i32 {{ return {n}; }}
fn heightmap_texel(p: vec2<i32>) -> f32 {{
    if (p.x < 0 || p.y < 0 || p.x >= {n} || p.y >= {n}) {{ return {OUT_OF_RANGE:.1f}; }}
    return {wgsl};
}}
#include "terrain.wgsl"
"""


def _run(language: str, include_dir: Path, heightmap: str, expression: dict[str, str], inputs: dict,
         output: str) -> np.ndarray:
    args = (language, prelude(language, heightmap), expression[language], inputs, output)
    if language == "glsl":
        # Another context (an app's) may be current on this thread: make the harness's own current for the call.
        with gl_context():
            return evaluate(*args, include_dirs=[include_dir])
    return evaluate(*args, include_dirs=[include_dir])


def _vec4(rows: np.ndarray) -> np.ndarray:
    rows = np.asarray(rows, dtype=np.float32)
    return np.c_[rows, np.zeros((len(rows), 4 - rows.shape[1]), np.float32)]


def _rounded(*arrays):
    """float32-rounded float64 copies: the reference sees exactly the numbers the shader sees."""
    return [np.asarray(a, np.float32).astype(np.float64) for a in arrays]


def _compare(kind: str, got: np.ndarray, expected: np.ndarray, tolerance, inputs: dict) -> str | None:
    """None when ``got`` matches; else a message with the worst case's inputs, expected, got and a hint."""
    got2 = got.reshape(len(got), -1)
    expected2 = np.asarray(expected, dtype=np.float64).reshape(len(got), -1)
    tolerance = np.broadcast_to(np.asarray(tolerance, dtype=np.float64), (len(got),))
    finite = np.all(np.isfinite(got2), axis=1)
    error = np.where(finite, np.abs(np.nan_to_num(got2) - expected2).max(axis=1), np.inf)
    worst = int(np.argmax(error - tolerance))
    if error[worst] <= tolerance[worst]:
        return None
    case = ", ".join(f"{k}={np.round(np.asarray(v, dtype=np.float64)[worst], 6).tolist()}" for k, v in inputs.items())
    return (f"{kind}: {int(np.sum(error > tolerance))} of {len(got)} cases wrong; e.g. {case}: expected "
            f"{np.round(expected2[worst], 6).tolist()}, got {got2[worst].tolist()} (tolerance "
            f"{tolerance[worst]:.2g}). Hint: {HINT[kind]}")


# --- tess_level -------------------------------------------------------------------------------------------------
LEVEL = {"glsl": "tess_level(a.xyz, b.xyz, eye.xyz, lod.xyz)", "wgsl": "tess_level(a.xyz, b.xyz, eye.xyz, lod.xyz)"}


def run_levels(language: str, include_dir: Path, a, b, eye, lod) -> np.ndarray:
    inputs = {"a": ("vec4", _vec4(a)), "b": ("vec4", _vec4(b)), "eye": ("vec4", _vec4(eye)),
              "lod": ("vec4", _vec4(lod))}
    return _run(language, include_dir, "flat", LEVEL, inputs, "f32")


def _random_lod(rng, n):
    low = rng.uniform(1.0, 4.0, n)
    return np.stack([rng.uniform(2.0, 64.0, n), low, low + rng.uniform(0.5, 60.0, n)], axis=1)


def check_level_random(language: str, include_dir: Path) -> str | None:
    rng = np.random.default_rng(5)
    n = 600
    a = rng.uniform(-10.0, 10.0, (n, 3))
    b = a + rng.normal(0.0, 1.0, (n, 3)) * rng.uniform(0.05, 3.0, (n, 1))
    eye = 0.5 * (a + b) + rng.normal(0.0, 1.0, (n, 3)) * 10.0 ** rng.uniform(-1.0, 2.0, (n, 1))
    lod = _random_lod(rng, n)
    a, b, eye, lod = _rounded(a, b, eye, lod)
    got = run_levels(language, include_dir, a, b, eye, lod)
    expected = tess_level_np(a, b, eye, lod)
    return _compare("level", got, expected, 1e-4 * expected, {"a": a, "b": b, "eye": eye, "lod": lod})


def check_level_clamps(language: str, include_dir: Path) -> str | None:
    a = np.array([[0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [1.0, 2.0, 3.0], [1.0, 2.0, 3.0],
                  [0.0, 1.0, 0.0], [0.0, 1.0, 0.0], [2.0, 0.0, 0.0], [5.0, 5.0, 5.0]])
    b = np.array([[1.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 2.0, 3.0], [1.0, 2.0, 3.0],
                  [0.0, 1.0, 1.0], [0.0, 1.0, 1.0], [2.0, 0.0, 2.0], [5.0, 5.0, 7.0]])
    eye = np.array([[0.5, 0.0, 0.0],      # exactly on the midpoint: max
                    [0.5, 1e6, 0.0],      # very far: min
                    [0.5, 1e-3, 0.0],     # very near: max
                    [1.0, 2.0, 3.0],      # a point-sized edge with the camera on it: max
                    [4.0, 2.0, 3.0],      # a point-sized edge seen from afar: length 0, so min
                    [0.0, 1.0, 4.5],      # edge-on: the camera on the edge's own line
                    [0.0, 1.0, -40.0],    # edge-on, far
                    [2.0, 0.0, 1.0],      # the camera on the midpoint of another edge
                    [5.0, 9.0, 6.0]])
    lod = np.tile([[16.0, 2.0, 24.0]], (len(a), 1))
    a, b, eye, lod = _rounded(a, b, eye, lod)
    got = run_levels(language, include_dir, a, b, eye, lod)
    expected = tess_level_np(a, b, eye, lod)
    return _compare("clamp", got, expected, 1e-4 * expected, {"a": a, "b": b, "eye": eye})


def check_level_symmetric(language: str, include_dir: Path) -> str | None:
    rng = np.random.default_rng(9)
    n = 400
    a = rng.uniform(-10.0, 10.0, (n, 3)) + rng.uniform(0, 1, (n, 1)) * 1e-3
    b = a + rng.normal(0.0, 1.3, (n, 3))
    eye = rng.uniform(-12.0, 12.0, (n, 3))
    lod = np.tile([[37.3, 1.0, 64.0]], (n, 1))
    a, b, eye, lod = _rounded(a, b, eye, lod)
    forward = run_levels(language, include_dir, a, b, eye, lod)
    backward = run_levels(language, include_dir, b, a, eye, lod)
    expected = tess_level_np(a, b, eye, lod)
    return (_compare("level", forward, expected, 1e-4 * expected, {"a": a, "b": b, "eye": eye})
            or _compare("symmetric", forward, backward, 0.0, {"a": a, "b": b, "eye": eye}))


# --- terrain_height ----------------------------------------------------------------------------------------------
HEIGHT = {"glsl": "terrain_height(uv)", "wgsl": "terrain_height(uv)"}


def run_heights(language: str, include_dir: Path, heightmap: str, uv) -> np.ndarray:
    return _run(language, include_dir, heightmap, HEIGHT, {"uv": ("vec2", np.asarray(uv, np.float32))}, "f32")


def check_height_random(language: str, include_dir: Path) -> str | None:
    rng = np.random.default_rng(2)
    messages = []
    for heightmap in ("random", "ramp"):
        (uv,) = _rounded(rng.uniform(0.0, 1.0, (500, 2)))
        got = run_heights(language, include_dir, heightmap, uv)
        expected = height_np(map_np(heightmap).astype(np.float64), uv)
        messages.append(_compare("height", got, expected, 2e-5, {"uv": uv}))
    return next((m for m in messages if m), None)


def check_height_texel_centres(language: str, include_dir: Path) -> str | None:
    n = MAPS["random"][0]
    row, col = np.mgrid[0:n, 0:n]
    (uv,) = _rounded(np.stack([(col + 0.5) / n, (row + 0.5) / n], -1).reshape(-1, 2))
    got = run_heights(language, include_dir, "random", uv)
    return _compare("height", got, map_np("random").reshape(-1), 2e-6, {"uv": uv})


def check_height_edges(language: str, include_dir: Path) -> str | None:
    edge = [0.0, 1.0, -0.05, 1.05, 0.5 / 16, 1.0 - 0.5 / 16, 0.3]
    (uv,) = _rounded(np.array([[u, v] for u in edge for v in edge]))
    got = run_heights(language, include_dir, "random", uv)
    expected = height_np(map_np("random").astype(np.float64), uv)
    return _compare("edges", got, expected, 2e-5, {"uv": uv})


# --- terrain_normal ----------------------------------------------------------------------------------------------
NORMAL = {"glsl": "vec4(terrain_normal(uv, scale), 0.0)", "wgsl": "vec4<f32>(terrain_normal(uv, scale), 0.0)"}


def run_normals(language: str, include_dir: Path, heightmap: str, uv, scale) -> np.ndarray:
    inputs = {"uv": ("vec2", np.asarray(uv, np.float32)), "scale": ("vec2", np.asarray(scale, np.float32))}
    return _run(language, include_dir, heightmap, NORMAL, inputs, "vec4")[:, :3]


def _normal_case(language, include_dir, heightmap, uv, scale, kind, tolerance) -> str | None:
    uv, scale = _rounded(uv, scale)
    got = run_normals(language, include_dir, heightmap, uv, scale)
    heights = map_np(heightmap).astype(np.float64)
    expected = np.stack([normal_np(heights, uv[i], scale[i, 0], scale[i, 1]) for i in range(len(uv))])
    return _compare(kind, got, expected, tolerance, {"uv": uv, "scale": scale})


def check_normal_random(language: str, include_dir: Path) -> str | None:
    rng = np.random.default_rng(4)
    n = 300
    uv = rng.uniform(0.0, 1.0, (n, 2))
    scale = np.stack([rng.uniform(5.0, 40.0, n), rng.uniform(0.2, 8.0, n)], -1)
    return (_normal_case(language, include_dir, "random", uv, scale, "normal", 2e-4)
            or _normal_case(language, include_dir, "ramp", uv, scale, "normal", 2e-4))


def check_normal_flat_and_steep(language: str, include_dir: Path) -> str | None:
    edge = np.array([0.0, 1.0, 0.5, 0.01, 0.99])
    uv = np.array([[u, v] for u in edge for v in edge])
    flat = _normal_case(language, include_dir, "flat", uv, np.tile([[20.0, 3.0]], (len(uv), 1)), "flat", 1e-6)
    # steep: 500 height units over a square of 2 (slopes of hundreds), also at the edges (clamped differences)
    steep = _normal_case(language, include_dir, "random", uv, np.tile([[2.0, 500.0]], (len(uv), 1)), "normal", 2e-4)
    return flat or steep


def check_normal_ramp_edges(language: str, include_dir: Path) -> str | None:
    edge = np.array([0.0, 1.0, -0.02, 1.02, 0.5 / 64, 0.25, 0.77])
    uv = np.array([[u, v] for u in edge for v in edge])
    return _normal_case(language, include_dir, "ramp", uv, np.tile([[20.0, 3.0]], (len(uv), 1)), "edges", 2e-4)


CHECKS: dict[str, tuple[str, Callable[[str, Path], str | None]]] = {
    "level_random": ("tess_level", check_level_random),
    "level_clamps": ("tess_level", check_level_clamps),
    "level_symmetric": ("tess_level", check_level_symmetric),
    "height_random": ("terrain_height", check_height_random),
    "height_texel_centres": ("terrain_height", check_height_texel_centres),
    "height_edges": ("terrain_height", check_height_edges),
    "normal_random": ("terrain_normal", check_normal_random),
    "normal_flat_and_steep": ("terrain_normal", check_normal_flat_and_steep),
    "normal_ramp_edges": ("terrain_normal", check_normal_ramp_edges),
}


def _grade(name: str, impl, backend: str) -> None:
    message = CHECKS[name][1](LANGUAGE[backend], impl_dir(impl))
    assert message is None, f"terrain.{LANGUAGE[backend]} {CHECKS[name][0]}: {message}"


@pytest.mark.exercise("terrain_lod")
def test_level_matches_numpy_on_random_edges(impl, backend):
    _grade("level_random", impl, backend)


@pytest.mark.exercise("terrain_lod")
def test_level_clamps_and_survives_distance_zero(impl, backend):
    _grade("level_clamps", impl, backend)


@pytest.mark.exercise("terrain_lod")
def test_level_is_the_same_for_both_directions_of_an_edge(impl, backend):
    _grade("level_symmetric", impl, backend)


@pytest.mark.exercise("terrain_height")
def test_height_matches_numpy_bilinear(impl, backend):
    _grade("height_random", impl, backend)


@pytest.mark.exercise("terrain_height")
def test_height_at_texel_centres_is_the_texel(impl, backend):
    _grade("height_texel_centres", impl, backend)


@pytest.mark.exercise("terrain_height")
def test_height_at_the_edges_reads_no_texel_outside_the_map(impl, backend):
    _grade("height_edges", impl, backend)


@pytest.mark.exercise("terrain_normal")
def test_normal_matches_numpy_central_differences(impl, backend):
    _grade("normal_random", impl, backend)


@pytest.mark.exercise("terrain_normal")
def test_normal_is_up_on_a_flat_map_and_finite_on_a_steep_one(impl, backend):
    _grade("normal_flat_and_steep", impl, backend)


@pytest.mark.exercise("terrain_normal")
def test_normal_of_a_ramp_also_at_the_edges(impl, backend):
    _grade("normal_ramp_edges", impl, backend)
