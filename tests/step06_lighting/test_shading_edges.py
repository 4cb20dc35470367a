"""The step's shader functions on their stated edge cases, run through the student's own GLSL and WGSL with the
shader harness (one expression per element in a compute shader), against float64 numpy:

* ``refract_direction`` returns the zero vector on total internal reflection (not the mirror direction), and
  bends by Snell's law otherwise;
* ``blinn_phong`` with shininess 0 is finite and equals "no falloff" (lobe 1) wherever n·h > 0, and light from
  behind the surface adds nothing.

Tolerance: 1e-5 per component (the reference measures below 1e-6). Non-finite values fail everywhere.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from shader_harness import evaluate

LANGUAGES = ("glsl", "wgsl")
TOLERANCE = 1e-5


def include(impl, language: str) -> tuple[str, list[Path]]:
    return f'#include "shading.{language}"', [Path(impl.__file__).resolve().parent]


def vec4(rows) -> np.ndarray:
    a = np.asarray(rows, dtype=np.float64)
    return np.concatenate([a, np.zeros((len(a), 1))], axis=1).astype(np.float32)


def refract_np(i: np.ndarray, n: np.ndarray, eta: float) -> np.ndarray:
    cos_i = float(np.dot(n, i))
    k = 1.0 - eta * eta * (1.0 - cos_i * cos_i)
    return np.zeros(3) if k < 0 else eta * i - (eta * cos_i + np.sqrt(k)) * n


@pytest.mark.exercise("reflect_refract")
@pytest.mark.parametrize("language", LANGUAGES)
def test_refract_direction_gives_zero_on_total_internal_reflection(impl, language):
    n = np.array([0.0, 0.0, 1.0])
    rays, etas = [], []
    for angle in (5.0, 30.0, 41.0, 42.0, 60.0, 89.0):  # from glass (1.5) into air: critical angle 41.8°
        a = np.radians(angle)
        rays.append([np.sin(a), 0.0, -np.cos(a)])
        etas.append(1.5)
    rays.append([0.6, 0.0, -0.8])
    etas.append(1.0 / 1.33)  # air into water: never total
    expr = "vec4(refract_direction(d.xyz, n.xyz, eta), 0.0)" if language == "glsl" else \
        "vec4<f32>(refract_direction(d.xyz, n.xyz, eta), 0.0)"
    prelude, dirs = include(impl, language)
    got = evaluate(language, prelude, expr, {"d": ("vec4", vec4(rays)), "n": ("vec4", vec4([n] * len(rays))),
                                             "eta": ("f32", np.array(etas, np.float32))}, "vec4", dirs)[:, :3]
    for ray, eta, out in zip(rays, etas, got):
        want = refract_np(np.asarray(ray), n, eta)
        assert np.all(np.isfinite(out)) and np.allclose(out, want, atol=TOLERANCE), (
            f"{language}: refract_direction(i={np.round(ray, 4).tolist()}, n=(0, 0, 1), eta={eta:.4f}) = "
            f"{out.tolist()}, expected {np.round(want, 6).tolist()}"
            + (" (total internal reflection: return the zero vector)" if not want.any() else ""))


@pytest.mark.exercise("blinn_phong")
@pytest.mark.parametrize("language", LANGUAGES)
def test_blinn_phong_with_shininess_0_and_light_from_behind(impl, language):
    n = [0.0, 0.0, 1.0]
    cases = [  # (l, v): the half vector leaning at various angles, one with n.h = 0 exactly, one from behind
        ([0.6, 0.0, 0.8], [0.0, 0.0, 1.0]),
        ([0.0, 0.6, 0.8], [0.6, 0.0, 0.8]),
        ([0.6, 0.0, 0.8], [0.6, 0.0, -0.8]),   # h = (1, 0, 0): n.h = 0, pow(0, 0)
        ([0.0, 0.0, -1.0], [0.0, 0.0, 1.0]),   # light from behind: n.l < 0
    ]
    radiance, albedo, specular = np.array([1.0, 0.8, 0.6]), np.array([0.5, 0.4, 0.3]), 0.7
    expr = ("vec4(blinn_phong(n.xyz, l.xyz, v.xyz, vec3(1.0, 0.8, 0.6), vec3(0.5, 0.4, 0.3), 0.7, 0.0), 0.0)"
            if language == "glsl" else
            "vec4<f32>(blinn_phong(n.xyz, l.xyz, v.xyz, vec3<f32>(1.0, 0.8, 0.6), vec3<f32>(0.5, 0.4, 0.3), 0.7, "
            "0.0), 0.0)")
    prelude, dirs = include(impl, language)
    got = evaluate(language, prelude, expr, {"n": ("vec4", vec4([n] * len(cases))),
                                             "l": ("vec4", vec4([c[0] for c in cases])),
                                             "v": ("vec4", vec4([c[1] for c in cases]))}, "vec4", dirs)[:, :3]
    for (light, view), out in zip(cases, got):
        n_dot_l = max(float(np.dot(n, light)), 0.0)
        want = (albedo + specular * 1.0) * radiance * n_dot_l  # shininess 0: no falloff, the lobe is 1
        assert np.all(np.isfinite(out)) and np.allclose(out, want, atol=TOLERANCE), (
            f"{language}: blinn_phong(n=(0, 0, 1), l={light}, v={view}, shininess=0) = {out.tolist()}, expected "
            f"{np.round(want, 6).tolist()} (shininess 0 means no falloff: guard pow(0, 0))")
