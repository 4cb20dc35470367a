"""Exercise 3: reflection and refraction, in numpy (checked numerically) and in the shaders (the silver and
ice spheres rendered in both APIs against a per-pixel numpy reference).

The environment is a cube map whose colour is a linear function of the direction, c(d) = 0.5 + 0.5 d, so a
lookup anywhere is easy to predict. Tolerance (8-bit steps, pixels 2 inside the silhouette): mean <= 1.0 and
99th percentile <= 3; the reference solution measures 0.19-0.24 and 1 in both APIs.
"""

from __future__ import annotations

import numpy as np
import pytest
from light_reference import assert_near_reference
from step06_helpers import EYE, SIZE, inner, render, sphere_hits, sphere_scene, to_srgb8

from gandalf_core.resources import CubeTextureData, MaterialData, cube_face_directions, linear_to_srgb, srgb_to_linear
from gandalf_tools.grading.shader_box import on_shader_box


def _unit(v):
    v = np.asarray(v, dtype=np.float64)
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def _dot(a, b):
    return np.einsum("...k,...k->...", a, b)[..., None]


def _reflect(i, n):
    """The mirror image of ``i``: its part along ``n`` turned round, its part across ``n`` kept."""
    along = _dot(i, n) * n
    return (i - along) - along


def _refract(i, n, eta):
    """Snell's law split into parts: across ``n`` the direction scales by ``eta``; along ``-n`` it has what is left
    of unit length, sqrt(1 - sin²θt); none left (sin²θt > 1) is total internal reflection, the zero vector."""
    across = eta * (i - _dot(i, n) * n)
    sin2_t = eta**2 * (1.0 - _dot(i, n) ** 2)
    along = -np.sqrt(np.clip(1.0 - sin2_t, 0.0, None)) * n
    return np.where(sin2_t <= 1.0, across + along, 0.0)


# --- numpy ------------------------------------------------------------------------------------------
@pytest.mark.exercise("reflect_refract")
def test_reflect_mirrors_about_the_normal(impl):
    rng = np.random.default_rng(0)
    i, n = _unit(rng.normal(size=(50, 3))), _unit(rng.normal(size=(50, 3)))
    r = np.asarray(impl.reflect(i, n))
    assert r.shape == (50, 3)
    assert np.allclose(r, _reflect(i, n), atol=1e-12)
    assert np.allclose(np.linalg.norm(r, axis=1), 1.0)
    assert np.allclose(np.asarray(impl.reflect([1.0, -1.0, 0.0], [0.0, 1.0, 0.0])), [1.0, 1.0, 0.0])


@pytest.mark.exercise("reflect_refract")
@pytest.mark.parametrize("eta", [1.0, 1 / 1.5, 1 / 1.31, 1.5])
def test_refract_follows_snells_law(impl, eta):
    rng = np.random.default_rng(1)
    n = _unit(rng.normal(size=(200, 3)))
    i = _unit(rng.normal(size=(200, 3)))
    i = np.where(np.sum(i * n, axis=1, keepdims=True) > 0, -i, i)  # incident: against the normal
    t = np.asarray(impl.refract(i, n, eta))
    assert t.shape == (200, 3) and np.all(np.isfinite(t))
    assert np.allclose(t, _refract(i, n, eta), atol=1e-12)
    sin_i = np.linalg.norm(np.cross(i, n), axis=1)
    passing = np.linalg.norm(t, axis=1) > 0
    assert np.allclose(np.linalg.norm(t[passing], axis=1), 1.0)
    assert np.allclose(np.linalg.norm(np.cross(t[passing], n[passing]), axis=1), eta * sin_i[passing], atol=1e-9)
    if eta == 1.0:
        assert np.allclose(t, i)


@pytest.mark.exercise("reflect_refract")
def test_total_internal_reflection_gives_the_zero_vector(impl):
    n = np.array([0.0, 1.0, 0.0])
    grazing = _unit([1.0, -0.2, 0.0])  # 79° from the normal: past the critical angle of 1.5 -> 1 (41.8°)
    assert np.array_equal(np.asarray(impl.refract(grazing, n, 1.5)), np.zeros(3))
    straight = np.array([0.0, -1.0, 0.0])
    assert np.allclose(np.asarray(impl.refract(straight, n, 1.5)), straight)


# --- shaders: env-mapped spheres ---------------------------------------------------------------------
def _direction_cube(size: int = 64) -> CubeTextureData:
    d = cube_face_directions(size)
    d = d / np.linalg.norm(d, axis=-1, keepdims=True)
    rgb = linear_to_srgb(0.5 + 0.5 * d)
    rgba = np.concatenate([rgb, np.ones(rgb.shape[:-1] + (1,))], axis=-1)
    return CubeTextureData.from_arrays(list(rgba), mipmaps=False, name="directions")


def _env(d):
    return 0.5 + 0.5 * _unit(d)


def _expected(kind: str, tint, ior: float) -> tuple[np.ndarray, np.ndarray]:
    hit, p, ray = sphere_hits(SIZE)
    n = _unit(np.where(hit[..., None], p, (0.0, 0.0, 1.0)))
    i = _unit(p - EYE)
    r = _reflect(i, n)
    tint = srgb_to_linear(np.asarray(tint, dtype=np.float64))
    if kind == "mirror":
        return to_srgb8(tint * _env(r)), hit
    t = _refract(i, n, 1.0 / ior)
    t = np.where(np.sum(t * t, axis=-1, keepdims=True) > 1e-12, t, r)
    f0 = ((ior - 1) / (ior + 1)) ** 2
    cos_i = np.clip(-np.sum(i * n, axis=-1, keepdims=True), 0.0, 1.0)
    fresnel = f0 + (1 - f0) * (1 - cos_i) ** 5
    return to_srgb8((1 - fresnel) * tint * _env(t) + fresnel * _env(r)), hit


@on_shader_box  # the student's shaders run in the grader's shader process; the picture comes back
def _environment_picture(backend: str, impl, material: MaterialData) -> np.ndarray:
    return render(backend, impl, sphere_scene(material, [], textures={"directions": _direction_cube()}))


@pytest.mark.exercise("reflect_refract")
@pytest.mark.parametrize("kind,tint,ior", [("mirror", (0.95, 0.93, 0.9), 1.0), ("glass", (0.85, 0.95, 1.0), 1.31),
                                          ("glass", (1.0, 1.0, 1.0), 2.4)])
def test_environment_mapped_sphere_matches_the_numpy_reference(impl, backend, kind, tint, ior):
    params = {"ior": ior} if kind == "glass" else {}
    material = MaterialData(kind, ["directions"], color=tint, params=params)
    image = _environment_picture(backend, impl, material)
    expected, hit = _expected(kind, tint, ior)
    assert_near_reference(image, expected, inner(hit), f"a {kind} sphere in {backend} (tint {tint}, ior {ior})")
