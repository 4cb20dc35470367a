"""Exercises ``ggx_distribution``, ``smith_geometry``, ``fresnel``, ``metallic_roughness`` and ``ggx_specular``
(step07 pbr_model): the student's GLSL and WGSL BRDF functions (``brdf.glsl`` / ``brdf.wgsl``), run per input on
the GPU through the shader harness and compared with float64 numpy twins on the same float32-rounded inputs.

The inputs include every edge the stub's comments name: roughness 0 and 1 (and out of range), n·v and n·l at 0, just
above 0 and negative, cos θ outside [0, 1], l = -v (no half vector), black base colours and f0 = 0. A result must be
finite and within a relative tolerance of 2e-3 plus an absolute 1e-6, widened where float32 arithmetic itself cannot
do better (:func:`distribution_bound`, :func:`specular_bound`): GGX's denominator ``d = (n·h)² (alpha² - 1) + 1``
cancels near n·h = 1 and small roughness (d falls to alpha² = 4.1e-6 at roughness 0.045), so a correct float32
evaluation is off by up to about ``8 u / d`` relative (u = 2^-24, float32's unit roundoff: 12 % at the peak; an
NVIDIA GPU measured 0.6 % there, Mesa 2e-5), and by ``4 c (1 - alpha²) / d`` times the error of a float32 n·h made
from vectors; likewise 1 / (n·v) and 1 / (n·l) near their 1e-4 clamp and Schlick's (1 - v·h)^5. Every check also runs
on plausible wrong implementations (mutants, in ``test_pbr_model_brdf_mutants.py``), each of which must fail at least
one of them.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest
from shader_checks import grade
from shader_harness import evaluate, gl_context

RTOL, ATOL = 2e-3, 1e-6
#: float32's unit roundoff: one rounding changes a value by at most this much, relatively.
U = 2.0**-24
MIN_ROUGHNESS, MIN_COSINE = 0.045, 1e-4


def _vec4(language: str, expression: str) -> str:
    return f"vec4({expression}, 0.0)" if language == "glsl" else f"vec4<f32>({expression}, 0.0)"


def run(language: str, include_dir: Path, expression: str, inputs: dict, output: str) -> np.ndarray:
    """``expression`` per element through the harness, with brdf.<language> included."""
    prelude = f'#include "brdf.{language}"'
    if language == "glsl":
        with gl_context():  # another context may be current on this thread
            return evaluate(language, prelude, expression, inputs, output, include_dirs=[include_dir])
    return evaluate(language, prelude, expression, inputs, output, include_dirs=[include_dir])


def _f32(a) -> np.ndarray:
    return np.asarray(a, dtype=np.float32).astype(np.float64)


def _compare(name: str, got: np.ndarray, expected: np.ndarray, cases: dict, hint: str,
             float32_error: np.ndarray | float = 0.0) -> str | None:
    """None when every case is within RTOL·|expected| + ATOL + ``float32_error`` (the most a correct float32
    evaluation can be off by, per case: see the module docstring); else one sentence naming the worst case."""
    got = np.asarray(got, dtype=np.float64).reshape(len(expected), -1)
    expected = np.asarray(expected, dtype=np.float64).reshape(len(expected), -1)
    float32_error = np.asarray(float32_error, dtype=np.float64)
    allowed = RTOL * np.abs(expected) + ATOL + (float32_error.reshape(len(expected), -1) if float32_error.ndim
                                                else float32_error)
    finite = np.all(np.isfinite(got), axis=1)
    error = np.where(finite, np.max(np.abs(np.nan_to_num(got) - expected) - allowed, axis=1), np.inf)
    if np.all(error <= 0.0):
        return None
    worst = int(np.argmax(error))
    case = ", ".join(f"{k}={np.round(np.asarray(v)[worst], 6).tolist()}" for k, v in cases.items())
    return (f"{name}: {int(np.sum(error > 0))} of {len(expected)} cases wrong; e.g. {case}: expected "
            f"{np.round(expected[worst], 6).tolist()}, got {got[worst].tolist()}. Hint: {hint}")


# --- numpy twins ------------------------------------------------------------------------------------------
def _ggx_denominator(n_dot_h, roughness):
    """alpha² and d = (n·h)² (alpha² - 1) + 1, GGX's denominator before squaring."""
    a2 = np.clip(roughness, MIN_ROUGHNESS, 1.0) ** 4
    c = np.clip(n_dot_h, 0.0, 1.0)
    return a2, c * c * (a2 - 1.0) + 1.0


def distribution_np(n_dot_h, roughness):
    a2, d = _ggx_denominator(n_dot_h, roughness)
    return a2 / (np.pi * d**2)


def distribution_bound(n_dot_h, roughness):
    """The most a correct float32 D can be off by (absolute), from exact inputs: d's roundings (≤ 4 u absolute)
    become 8 u / d relative in 1 / d², and a few more roundings add 12 u; times 2 for other orders of the
    same operations (fused multiply-adds, a2 as (r²)²)."""
    _, d = _ggx_denominator(n_dot_h, roughness)
    return 2.0 * (8.0 / d + 12.0) * U * distribution_np(n_dot_h, roughness)


def k_direct_np(roughness):
    return (np.clip(roughness, 0.0, 1.0) + 1.0) ** 2 / 8.0


def k_ibl_np(roughness):
    return np.clip(roughness, 0.0, 1.0) ** 2 / 2.0


def geometry_np(n_dot_v, n_dot_l, k):
    v = np.clip(n_dot_v, MIN_COSINE, 1.0)
    lo = np.clip(n_dot_l, MIN_COSINE, 1.0)
    return v / (v * (1.0 - k) + k) * lo / (lo * (1.0 - k) + k)


def fresnel_np(cos_theta, f0):
    return f0 + (1.0 - f0) * (1.0 - np.clip(cos_theta, 0.0, 1.0))[:, None] ** 5


def fresnel_roughness_np(cos_theta, f0, roughness):
    top = np.maximum(1.0 - np.clip(roughness, 0.0, 1.0)[:, None], f0)
    return f0 + (top - f0) * (1.0 - np.clip(cos_theta, 0.0, 1.0))[:, None] ** 5


def base_reflectance_np(base, metallic):
    m = np.clip(metallic, 0.0, 1.0)[:, None]
    return 0.04 * (1.0 - m) + base * m


def diffuse_albedo_np(base, metallic, fresnel):
    return base * (1.0 - np.clip(metallic, 0.0, 1.0))[:, None] * (1.0 - fresnel)


def _specular_cosines(n, v, light):
    """n·v, n·l, n·h and v·h, h the half vector (n when l + v = 0)."""
    def dot(a, b):
        return np.sum(a * b, axis=-1)

    s = light + v
    length = np.linalg.norm(s, axis=-1, keepdims=True)
    h = np.where(length > 1e-6, s / np.maximum(length, 1e-6), n)
    return dot(n, v), dot(n, light), dot(n, h), dot(v, h)


def _specular_from(cosines, roughness, f0):
    n_dot_v, n_dot_l, n_dot_h, v_dot_h = cosines
    n_dot_v = np.clip(n_dot_v, MIN_COSINE, 1.0)
    n_dot_l = np.clip(n_dot_l, MIN_COSINE, 1.0)
    d = distribution_np(n_dot_h, roughness)
    g = geometry_np(n_dot_v, n_dot_l, k_direct_np(roughness))
    f = fresnel_np(v_dot_h, f0)
    return (d * g / (4.0 * n_dot_v * n_dot_l))[:, None] * f


def ggx_specular_np(n, v, light, roughness, f0):
    return _specular_from(_specular_cosines(n, v, light), roughness, f0)


def specular_bound(n, v, light, roughness, f0):
    """The most a correct float32 ggx_specular can be off by (absolute, per channel): each cosine made from
    float32 unit vectors (a dot product, and a normalised half vector for n·h and v·h) is within 8 u of its exact
    value, so the result moves by up to |f(cos + 8u) - f(cos - 8u)| / 2 for each; D's own roundings add
    8 u / d relative (see :func:`distribution_bound`) and the remaining products 24 u; times 2 for margin."""
    cosines = _specular_cosines(n, v, light)
    spec = _specular_from(cosines, roughness, f0)
    moved = np.zeros_like(spec)
    for i in range(4):
        up, down = list(cosines), list(cosines)
        up[i], down[i] = cosines[i] + 8.0 * U, cosines[i] - 8.0 * U
        moved += np.abs(_specular_from(up, roughness, f0) - _specular_from(down, roughness, f0)) / 2.0
    _, d = _ggx_denominator(cosines[2], roughness)
    return 2.0 * (moved + ((8.0 / d + 24.0) * U)[:, None] * np.abs(spec))


# --- inputs ---------------------------------------------------------------------------------------------
ROUGHNESS = np.array([-0.1, 0.0, 0.02, 0.045, 0.25, 0.5, 0.8, 1.0, 1.3])
COSINES = np.array([-0.4, 0.0, 1e-5, 1e-3, 0.2, 0.5, 0.9, 0.999, 1.0, 1.2])
F0S = np.array([[0.04, 0.04, 0.04], [0.0, 0.0, 0.0], [0.95, 0.64, 0.54], [1.0, 1.0, 1.0]])
BASES = np.array([[0.0, 0.0, 0.0], [1.0, 1.0, 1.0], [0.95, 0.64, 0.54], [0.2, 0.5, 0.9]])


def _pad(a: np.ndarray) -> np.ndarray:
    a = np.asarray(a, dtype=np.float32).reshape(-1, 3)
    return np.c_[a, np.zeros(len(a), np.float32)]


def check_distribution(language: str, include_dir: Path) -> str | None:
    c, r = (a.ravel() for a in np.meshgrid(COSINES, ROUGHNESS))
    c, r = _f32(c), _f32(r)
    got = run(language, include_dir, "distribution_ggx(c, r)", {"c": ("f32", c), "r": ("f32", r)}, "f32")
    return _compare("distribution_ggx(n_dot_h, roughness)", got, distribution_np(c, r), {"n_dot_h": c, "roughness": r},
                    "alpha = clamp(roughness, 0.045, 1)², D = alpha² / (pi ((n·h)² (alpha² - 1) + 1)²), n·h in [0, 1]",
                    distribution_bound(c, r))


def check_k(language: str, include_dir: Path) -> str | None:
    r = _f32(np.linspace(-0.5, 1.5, 21))
    got = run(language, include_dir, "vec2(k_direct(r), k_ibl(r))" if language == "glsl"
              else "vec2<f32>(k_direct(r), k_ibl(r))", {"r": ("f32", r)}, "vec2")
    expected = np.stack([k_direct_np(r), k_ibl_np(r)], axis=-1)
    return _compare("(k_direct(roughness), k_ibl(roughness))", got, expected, {"roughness": r},
                    "direct light: k = (roughness + 1)² / 8; image-based light: k = roughness² / 2; clamp roughness "
                    "to [0, 1]")


def check_geometry(language: str, include_dir: Path) -> str | None:
    v, lo, k = (a.ravel() for a in np.meshgrid(COSINES, COSINES, np.array([0.0, 0.02, 0.125, 0.3, 0.5])))
    v, lo, k = _f32(v), _f32(lo), _f32(k)
    got = run(language, include_dir, "geometry_smith(v, l, k)", {"v": ("f32", v), "l": ("f32", lo), "k": ("f32", k)},
              "f32")
    return _compare("geometry_smith(n_dot_v, n_dot_l, k)", got, geometry_np(v, lo, k),
                    {"n_dot_v": v, "n_dot_l": lo, "k": k},
                    "G1(x) = x / (x (1 - k) + k) for x = n·v and n·l, each clamped to [1e-4, 1] first; G = G1 G1")


def check_fresnel(language: str, include_dir: Path) -> str | None:
    c, i = (a.ravel() for a in np.meshgrid(COSINES, np.arange(len(F0S))))
    c, f0 = _f32(c), _f32(F0S[i])
    got = run(language, include_dir, _vec4(language, "fresnel_schlick(c, f0.xyz)"),
              {"c": ("f32", c), "f0": ("vec4", _pad(f0))}, "vec4")[:, :3]
    return _compare("fresnel_schlick(cos_theta, f0)", got, fresnel_np(c, f0), {"cos_theta": c, "f0": f0},
                    "f0 + (1 - f0) (1 - cos_theta)^5 with cos_theta clamped to [0, 1] (pow of a negative is NaN)")


def check_fresnel_roughness(language: str, include_dir: Path) -> str | None:
    c, i, r = (a.ravel() for a in np.meshgrid(COSINES, np.arange(len(F0S)), np.array([-0.2, 0.0, 0.3, 0.7, 1.0])))
    c, f0, r = _f32(c), _f32(F0S[i]), _f32(r)
    got = run(language, include_dir, _vec4(language, "fresnel_schlick_roughness(c, f0.xyz, r)"),
              {"c": ("f32", c), "f0": ("vec4", _pad(f0)), "r": ("f32", r)}, "vec4")[:, :3]
    return _compare("fresnel_schlick_roughness(cos_theta, f0, roughness)", got, fresnel_roughness_np(c, f0, r),
                    {"cos_theta": c, "f0": f0, "roughness": r},
                    "f0 + (max(1 - roughness, f0) - f0) (1 - cos_theta)^5; clamp cos_theta and roughness to [0, 1]")


def check_base_reflectance(language: str, include_dir: Path) -> str | None:
    i, m = (a.ravel() for a in np.meshgrid(np.arange(len(BASES)), np.array([-0.3, 0.0, 0.25, 0.5, 1.0, 1.4])))
    base, m = _f32(BASES[i]), _f32(m)
    got = run(language, include_dir, _vec4(language, "base_reflectance(base.xyz, m)"),
              {"base": ("vec4", _pad(base)), "m": ("f32", m)}, "vec4")[:, :3]
    return _compare("base_reflectance(base, metallic)", got, base_reflectance_np(base, m),
                    {"base": base, "metallic": m},
                    "F0 = mix(vec3(0.04), base, metallic): dielectrics reflect 4 % whatever their colour; "
                    "clamp metallic")


def check_diffuse_albedo(language: str, include_dir: Path) -> str | None:
    i, m, j = (a.ravel() for a in np.meshgrid(np.arange(len(BASES)), np.array([-0.3, 0.0, 0.4, 1.0, 1.4]),
                                              np.arange(len(F0S))))
    base, m, fresnel = _f32(BASES[i]), _f32(m), _f32(F0S[j])
    got = run(language, include_dir, _vec4(language, "diffuse_albedo(base.xyz, m, f.xyz)"),
              {"base": ("vec4", _pad(base)), "m": ("f32", m), "f": ("vec4", _pad(fresnel))}, "vec4")[:, :3]
    return _compare("diffuse_albedo(base, metallic, fresnel)", got, diffuse_albedo_np(base, m, fresnel),
                    {"base": base, "metallic": m, "fresnel": fresnel},
                    "base (1 - metallic) (1 - fresnel), metallic clamped to [0, 1] (no division by pi here)")


def _specular_cases() -> dict[str, np.ndarray]:
    """Unit n, v, l, with grazing v, l at the horizon, l = -v, l = v = n, and random directions."""
    rng = np.random.default_rng(4)
    n = np.tile([0.0, 0.0, 1.0], (12, 1))
    v = np.array([[0, 0, 1], [1, 0, 0], [0.6, 0, 0.8], [0.6, 0, 0.8], [0.0, 0.6, 0.8], [0, 0, 1],
                  [0.8, 0, 0.6], [0.3, 0.4, np.sqrt(0.75)], [1, 0, 0], [0, 0, 1], [0.6, 0, 0.8], [0, 1, 0]], float)
    light = np.array([[0, 0, 1], [0, 0, 1], [1, 0, 0], [-0.6, 0, 0.8], [0.0, -0.6, -0.8], [0, 0, 1],
                      [-0.8, 0, 0.6], [0, 0.6, 0.8], [-1, 0, 0], [0.6, 0, 0.8], [0, 0, -1], [0, -1, 0]], float)
    rand = rng.normal(size=(24, 3, 3))
    rand /= np.linalg.norm(rand, axis=-1, keepdims=True)
    n = np.r_[n, rand[:, 0]]
    v = np.r_[v, rand[:, 1]]
    light = np.r_[light, rand[:, 2]]
    return {"n": n, "v": v, "l": light}


def check_specular(language: str, include_dir: Path) -> str | None:
    dirs = _specular_cases()
    count = len(dirs["n"])
    rows = []
    for r in (0.0, 0.3, 1.0):
        for f0 in (F0S[0], F0S[1], F0S[2]):
            rows.append((np.full(count, r), np.tile(f0, (count, 1))))
    r = _f32(np.concatenate([a for a, _ in rows]))
    f0 = _f32(np.concatenate([b for _, b in rows]))
    n, v, light = (_f32(np.tile(dirs[k], (len(rows), 1))) for k in ("n", "v", "l"))
    got = run(language, include_dir, _vec4(language, "ggx_specular(n.xyz, v.xyz, l.xyz, r, f0.xyz)"),
              {"n": ("vec4", _pad(n)), "v": ("vec4", _pad(v)), "l": ("vec4", _pad(light)), "r": ("f32", r),
               "f0": ("vec4", _pad(f0))}, "vec4")[:, :3]
    return _compare("ggx_specular(n, v, l, roughness, f0)", got, ggx_specular_np(n, v, light, r, f0),
                    {"n": n, "v": v, "l": light, "roughness": r, "f0": f0},
                    "D G F / (4 (n·v)(n·l)) with n·v, n·l clamped to [1e-4, 1], G with k_direct, h = n when l + v = 0",
                    specular_bound(n, v, light, r, f0))


CHECKS: dict[str, Callable[[str, Path], str | None]] = {
    "distribution": check_distribution,
    "k": check_k,
    "geometry": check_geometry,
    "fresnel": check_fresnel,
    "fresnel_roughness": check_fresnel_roughness,
    "base_reflectance": check_base_reflectance,
    "diffuse_albedo": check_diffuse_albedo,
    "specular": check_specular,
}


def _grade(name: str, impl, backend: str) -> None:
    grade(CHECKS[name], impl, backend, "brdf")


@pytest.mark.exercise("ggx_distribution")
def test_distribution_ggx(impl, backend):
    _grade("distribution", impl, backend)


@pytest.mark.exercise("smith_geometry")
def test_k_for_direct_and_image_based_light(impl, backend):
    _grade("k", impl, backend)


@pytest.mark.exercise("smith_geometry")
def test_geometry_smith(impl, backend):
    _grade("geometry", impl, backend)


@pytest.mark.exercise("fresnel")
def test_fresnel_schlick(impl, backend):
    _grade("fresnel", impl, backend)


@pytest.mark.exercise("fresnel")
def test_fresnel_schlick_roughness(impl, backend):
    _grade("fresnel_roughness", impl, backend)


@pytest.mark.exercise("metallic_roughness")
def test_base_reflectance(impl, backend):
    _grade("base_reflectance", impl, backend)


@pytest.mark.exercise("metallic_roughness")
def test_diffuse_albedo(impl, backend):
    _grade("diffuse_albedo", impl, backend)


@pytest.mark.exercise("ggx_specular")
def test_ggx_specular_on_edge_inputs(impl, backend):
    _grade("specular", impl, backend)
