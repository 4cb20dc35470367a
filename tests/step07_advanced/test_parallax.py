"""Exercise ``parallax`` (step07 parallax): the student's ``parallax_offset``, ``parallax_steep`` and
``parallax_occlusion`` in GLSL and WGSL, run on the GPU through the shader harness (one compute invocation per
case) and compared with the float64 numpy references of ``step07_advanced.parallax.reference`` on the same
float32-rounded inputs.

The height field the functions sample (``height_at``) is defined by each check's prelude: smooth analytic bumps,
a step edge (a brick's border), or a constant, each with an exact numpy twin.

Tolerances (uv units, max over both components): ``5e-5 + 2e-5 · |shift|`` for every case, where ``shift`` is the
reference's uv shift (up to 10 · scale at a grazing view). The march's result jumps where the ray only grazes a
layer, so random cases whose surface-to-layer gap comes within 1e-3 of zero are left out (about 5 % of them).
The reference solution measures at most 3e-7 on llvmpipe and lavapipe; a LearnOpenGL-style march (adding 1/n up
and stepping uv by a running sum) passes too. Every rule the stub states is
checked; a set of plausible wrong implementations (mutants, in ``test_parallax_mutants.py``) must each fail a check.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest
from shader_checks import LANGUAGE, impl_dir
from shader_harness import evaluate, gl_context

from step07_advanced.parallax import reference as ref

FUNCTIONS = ("parallax_offset", "parallax_steep", "parallax_occlusion")
TAU = 2.0 * np.pi


def _bumps_np(uv: np.ndarray) -> np.ndarray:
    u, v = uv[:, 0], uv[:, 1]
    return 0.5 + 0.3 * np.sin(TAU * 1.3 * u) * np.cos(TAU * 0.9 * v) + 0.15 * np.sin(TAU * (0.7 * u + 1.9 * v) + 0.4)


def _step_np(uv: np.ndarray) -> np.ndarray:
    x = 2.0 * uv[:, 0]
    return np.where(x - np.floor(x) < 0.5, 0.9, 0.2)


def _constant(c: float) -> Callable[[np.ndarray], np.ndarray]:
    return lambda uv: np.full(len(uv), c)


_BUMPS = ("0.5 + 0.3 * sin(6.283185307179586 * 1.3 * uv.x) * cos(6.283185307179586 * 0.9 * uv.y)"
          " + 0.15 * sin(6.283185307179586 * (0.7 * uv.x + 1.9 * uv.y) + 0.4)")
#: name -> (GLSL body, WGSL body, numpy twin) of height_at(uv)
FIELDS: dict[str, tuple[str, str, Callable[[np.ndarray], np.ndarray]]] = {
    "bumps": (_BUMPS, _BUMPS, _bumps_np),
    "step": ("fract(2.0 * uv.x) < 0.5 ? 0.9 : 0.2", "select(0.2, 0.9, fract(2.0 * uv.x) < 0.5)", _step_np),
    "flat 0.37": ("0.37", "0.37", _constant(0.37)),
    "top": ("1.0", "1.0", _constant(1.0)),
    # Nearly the deepest everywhere: the march ends at its last layer. Not exactly 0, where the last layer's depth
    # ties with the surface and a march that adds 1/n up n times (and falls short of 1 by a rounding) may
    # legitimately take one step more.
    "deep": ("0.002", "0.002", _constant(0.002)),
}
HINT = {
    "random": "compare your code with the formulas in the stub: uv moves against view_ts.xy, by the depth "
              "1 - height_at, divided by max(view_ts.z, 0.1)",
    "still": "looking straight down (view_ts = (0, 0, 1)) or with scale 0 nothing may move",
    "top": "layer 0 counts: a point at height 1 is already on the surface and is not moved",
    "grazing": "divide by max(view_ts.z, 0.1), never by view_ts.z alone (z can be 0 or negative)",
    "layers": "n = clamp(layers, 1, 256); layer i lies at depth i / n; layer n (depth 1) always ends the march",
    "flat": "on a flat height field the interpolation of parallax_occlusion lands exactly on the surface: "
            "uv - (1 - h) * view_ts.xy / max(view_ts.z, 0.1) * scale, for any number of layers",
    "borders": "do not clamp or wrap uv (the texture repeats); a shifted uv may leave [0, 1]",
}


def _expression(function: str) -> str:
    if function == "parallax_offset":
        return "parallax_offset(uv, view.xyz, scale)"
    return f"{function}(uv, view.xyz, scale, layers)"


def _prelude(language: str, field: str) -> str:
    body = FIELDS[field][0 if language == "glsl" else 1]
    if language == "glsl":
        return f'float height_at(vec2 uv) {{ return {body}; }}\n#include "parallax.glsl"'
    return f'fn height_at(uv: vec2<f32>) -> f32 {{ return {body}; }}\n#include "parallax.wgsl"'


def _reference(function: str, field: str, uv, view, scale, layers) -> dict[str, np.ndarray]:
    height = FIELDS[field][2]
    if function == "parallax_offset":
        got = ref.parallax_offset_np(height, uv, view, scale)
        return {"uv": got, "margin": np.full(len(got), np.inf)}
    march = ref.march_np(height, uv, view, scale, layers)
    return {"uv": march["steep" if function == "parallax_steep" else "occlusion"], "margin": march["margin"]}


def run_cases(language: str, include_dir: Path, function: str, field: str, uv, view, scale, layers
              ) -> tuple[np.ndarray, dict[str, np.ndarray], dict[str, np.ndarray]]:
    """(GPU result (n, 2), float64 reference, the float32-rounded inputs) of ``function`` on the cases."""
    uv = np.asarray(uv, np.float32).reshape(-1, 2)
    n = len(uv)
    view = np.asarray(view, np.float32).reshape(-1, 3)
    view = np.broadcast_to(view, (n, 3))
    scale = np.broadcast_to(np.asarray(scale, np.float32), (n,))
    layers = np.broadcast_to(np.asarray(layers, np.int32), (n,))
    inputs = {"uv": ("vec2", uv), "view": ("vec4", np.c_[view, np.zeros(n, np.float32)]),
              "scale": ("f32", scale), "layers": ("i32", layers)}
    if language == "glsl":
        # Creating the harness's WebGPU device can leave another EGL context current: make the harness's own
        # OpenGL context current again (``with ctx``), or moderngl cannot create programs after a WGSL run.
        with gl_context():
            got = evaluate(language, _prelude(language, field), _expression(function), inputs, "vec2",
                           include_dirs=[include_dir])
    else:
        got = evaluate(language, _prelude(language, field), _expression(function), inputs, "vec2",
                       include_dirs=[include_dir])
    rounded = {"uv": uv.astype(np.float64), "view": view.astype(np.float64), "scale": scale.astype(np.float64),
               "layers": layers.astype(np.int64)}
    expected = _reference(function, field, rounded["uv"], rounded["view"], rounded["scale"], rounded["layers"])
    return got, expected, rounded


def _compare(kind: str, function: str, field: str, got: np.ndarray, expected: dict[str, np.ndarray],
             inputs: dict[str, np.ndarray], min_margin: float = 0.0) -> str | None:
    """None when ``got`` matches the reference; else the worst case's inputs, expected, got and a hint."""
    want = expected["uv"]
    keep = expected["margin"] >= min_margin
    shift = np.abs(want - inputs["uv"]).max(axis=1)
    tolerance = 5e-5 + 2e-5 * shift
    finite = np.all(np.isfinite(got), axis=1)
    error = np.where(finite, np.abs(np.nan_to_num(got) - want).max(axis=1), np.inf)
    bad = keep & (error > tolerance)
    if not bad.any():
        return None
    worst = int(np.argmax(np.where(keep, error - tolerance, -np.inf)))
    case = ", ".join(f"{k}={np.round(v[worst], 6).tolist()}" for k, v in inputs.items()
                     if not (function == "parallax_offset" and k == "layers"))
    return (f"{function}, {kind} (height field: {field}): {int(bad.sum())} of {int(keep.sum())} cases wrong; e.g. "
            f"{case}: expected uv {np.round(want[worst], 6).tolist()}, got {got[worst].tolist()} (tolerance "
            f"{tolerance[worst]:.2g}). Hint: {HINT[kind]}")


def _unit(v: np.ndarray) -> np.ndarray:
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


# --- the checks (each returns None or a failure message; the graded tests and the mutant test share them) ---
def check_random(language: str, include_dir: Path, function: str) -> str | None:
    """Random uv, views, scales and layer counts over smooth bumps; then nothing moves when it must not."""
    return (_random(language, include_dir, function) or _still(language, include_dir, function)
            or (None if function == "parallax_offset" else _top(language, include_dir, function)))


def _random(language: str, include_dir: Path, function: str) -> str | None:
    rng = np.random.default_rng(17)
    n = 768
    uv = rng.uniform(-1.0, 2.0, (n, 2))
    azimuth = rng.uniform(0.0, TAU, n)
    z = rng.uniform(0.12, 1.0, n)
    r = np.sqrt(1.0 - z * z)
    view = np.c_[r * np.cos(azimuth), r * np.sin(azimuth), z]
    scale = rng.uniform(0.0, 0.12, n)
    layers = rng.integers(1, 65, n)
    got, expected, inputs = run_cases(language, include_dir, function, "bumps", uv, view, scale, layers)
    return _compare("random", function, "bumps", got, expected, inputs, min_margin=1e-3)


def _still(language: str, include_dir: Path, function: str) -> str | None:
    """Straight down, or scale 0: uv comes back unmoved (bumps and a step edge)."""
    rng = np.random.default_rng(5)
    n = 64
    uv = np.r_[rng.uniform(-1.0, 2.0, (n, 2)), [[0.0, 0.0], [1.0, 1.0], [0.25, 0.5], [0.5, 0.75]]]
    m = len(uv)
    down = np.tile([0.0, 0.0, 1.0], (m, 1))
    slanted = _unit(np.c_[rng.normal(0.0, 1.0, (m, 2)), rng.uniform(0.0, 1.0, m)])
    layers = rng.integers(1, 65, m)
    for field in ("bumps", "step"):
        for view, scale in ((down, 0.08), (slanted, 0.0)):
            got, expected, inputs = run_cases(language, include_dir, function, field, uv, view, scale, layers)
            message = _compare("still", function, field, got, expected, inputs)
            if message:
                return message
    return None


def _top(language: str, include_dir: Path, function: str) -> str | None:
    """A height field at 1 everywhere: nothing is below the surface, nothing moves."""
    rng = np.random.default_rng(9)
    n = 48
    uv = rng.uniform(0.0, 1.0, (n, 2))
    view = _unit(np.c_[rng.normal(0.0, 1.0, (n, 2)), rng.uniform(0.2, 1.0, n)])
    got, expected, inputs = run_cases(language, include_dir, function, "top", uv, view, 0.1,
                                      rng.integers(1, 40, n))
    return _compare("top", function, "top", got, expected, inputs)


def check_grazing(language: str, include_dir: Path, function: str) -> str | None:
    """view_ts.z of 0, tiny, small and negative: finite, and the division floored at 0.1."""
    rng = np.random.default_rng(23)
    zs = np.array([0.0, 1e-7, 1e-3, 0.02, 0.05, 0.0999, -0.2, -1e-6])
    per = 12
    z = np.repeat(zs, per)
    n = len(z)
    azimuth = rng.uniform(0.0, TAU, n)
    r = np.sqrt(1.0 - z * z)
    view = np.c_[r * np.cos(azimuth), r * np.sin(azimuth), z]
    uv = rng.uniform(0.0, 1.0, (n, 2))
    for field, layers in (("bumps", rng.integers(1, 65, n)), ("flat 0.37", rng.integers(1, 65, n)),
                          ("deep", rng.integers(1, 65, n))):
        got, expected, inputs = run_cases(language, include_dir, function, field, uv, view, 0.06, layers)
        message = _compare("grazing", function, field, got, expected, inputs, min_margin=1e-3)
        if message:
            return message
    return None


def check_layers(language: str, include_dir: Path, function: str) -> str | None:
    """layers = 1, 2, 3, below 1 (counts as 1) and beyond the maximum (counts as 256)."""
    rng = np.random.default_rng(31)
    counts = np.array([1, 2, 3, 0, -4, 256, 257, 1000, 1 << 20])
    per = 16
    layers = np.repeat(counts, per)
    n = len(layers)
    uv = rng.uniform(0.0, 1.0, (n, 2))
    view = _unit(np.c_[rng.normal(0.0, 1.0, (n, 2)), rng.uniform(0.25, 1.0, n)])
    for field in ("bumps", "deep", "flat 0.37"):
        got, expected, inputs = run_cases(language, include_dir, function, field, uv, view, 0.08, layers)
        message = _compare("layers", function, field, got, expected, inputs, min_margin=1e-3)
        if message:
            return message
    return None


def check_flat(language: str, include_dir: Path, function: str) -> str | None:
    """Occlusion only: on a constant height field the interpolated hit is exact for every layer count."""
    rng = np.random.default_rng(41)
    n = 96
    uv = rng.uniform(-0.5, 1.5, (n, 2))
    view = _unit(np.c_[rng.normal(0.0, 1.0, (n, 2)), rng.uniform(0.15, 1.0, n)])
    layers = rng.integers(1, 12, n)
    got, expected, inputs = run_cases(language, include_dir, function, "flat 0.37", uv, view, 0.1, layers)
    exact = {"uv": ref.parallax_offset_np(_constant(0.37), inputs["uv"], inputs["view"], inputs["scale"]),
             "margin": expected["margin"]}
    return _compare("flat", function, "flat 0.37", got, exact, inputs)


def check_borders(language: str, include_dir: Path, function: str) -> str | None:
    """uv on and near the tile's borders, shifted across them over a step edge: no clamping, no wrapping."""
    corners = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.0], [0.0, 0.5], [1.0, 0.5], [0.5, 0.0],
                        [0.5, 1.0], [0.01, 0.99], [0.99, 0.01], [-0.01, 1.01]])
    views = _unit(np.array([[0.8, 0.3, 0.35], [-0.8, -0.3, 0.35], [0.5, -0.7, 0.3], [-0.6, 0.6, 0.4]]))
    uv = np.repeat(corners, len(views), axis=0)
    view = np.tile(views, (len(corners), 1))
    for field, layers in (("step", 24), ("deep", 7), ("bumps", 16)):
        got, expected, inputs = run_cases(language, include_dir, function, field, uv, view, 0.1, layers)
        message = _compare("borders", function, field, got, expected, inputs, min_margin=1e-3)
        if message:
            return message
    return None


CHECKS: dict[str, Callable[[str, Path, str], str | None]] = {
    "random": check_random,
    "grazing": check_grazing,
    "layers": check_layers,
    "flat": check_flat,
    "borders": check_borders,
}
#: Which checks grade which function (parallax_offset has no layers; "flat" is the interpolation's own).
APPLIES = {
    "parallax_offset": ("random", "grazing", "borders"),
    "parallax_steep": ("random", "grazing", "layers", "borders"),
    "parallax_occlusion": ("random", "grazing", "layers", "flat", "borders"),
}
GRADED = [(function, check) for function in FUNCTIONS for check in APPLIES[function]]


@pytest.mark.exercise("parallax")
@pytest.mark.parametrize(("function", "check"), GRADED, ids=[f"{f}-{c}" for f, c in GRADED])
def test_parallax_function(impl, backend, function, check):
    message = CHECKS[check](LANGUAGE[backend], impl_dir(impl), function)
    assert message is None, f"parallax.{LANGUAGE[backend]}: {message}"
