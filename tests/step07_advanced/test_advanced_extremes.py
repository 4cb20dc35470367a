"""Extreme inputs with the reference solutions, in both APIs: a flat normal map must equal no normal map,
grazing views of the parallax-mapped floor and the silhouettes of PBR spheres at roughness 0 and 1, metallic 0
and 1 (environment light on) must have no NaN/black speckles, and the numpy twin of the BRDF stays finite for
degenerate vectors."""

from __future__ import annotations

import numpy as np
import pytest
from cube_seams import near_cube_edge, seamless_cube_maps
from step07_helpers import (
    EYE,
    ambient,
    directional,
    ggx_specular_np,
    inner,
    pbr_material,
    render,
    small_sky,
    sphere_hits,
    sphere_scene,
)

from gandalf_core import Scene, TransformComponent
from gandalf_core.components import CameraComponent, LightComponent, MaterialComponent, MeshComponent
from gandalf_core.math import look_at_rotation
from gandalf_core.resources import MaterialData, TextureData, plane, solid
from step07_advanced import solutions
from step07_advanced.showcase.textures import brick_textures, encode_normals

LIGHTS = [directional((-1.0, 1.5, 2.0), (1.0, 0.95, 0.9), 2.5), ambient((0.05, 0.05, 0.05))]


#: A flat map's texel 128 decodes to 1/255, not 0, in x and y: the normal leans by atan(√2 / 255).
FLAT_MAP_TILT = float(np.arctan(np.sqrt(2.0) / 255.0))
#: How far the exact sphere's normal at a pixel centre may lie from the GPU's: the 128 × 64 sphere's facets
#: (π/64 apart) sag by 1 - cos(π/128) ≈ 3e-4 below the sphere, which moves a pixel's hit point along the surface
#: by the sag times tan(incidence), at most ~6 inside the eroded silhouette: 2e-3 rad.
NORMAL_ERROR = 0.002


def test_flat_normal_and_height_maps_equal_plain_pbr(backend):
    """Tolerance: no channel differs by more than 2 steps (the map's 128 decodes to 0.004, not 0), except where
    the implementation filters cube maps per face (wgpu's OpenGL backend): there a lookup within the tilt of a
    face edge may jump to the other face, so pixels whose normal (the diffuse lookup) lies within the tilt, or
    whose reflection (the specular lookup) within twice it, of a cube edge are left out — at most 6 %."""
    params = {"metallic": 0.0, "roughness": 0.4, "env_strength": 1.0}
    plain = render(backend, solutions, sphere_scene(pbr_material((0.8, 0.5, 0.3), **params), LIGHTS))
    scene = sphere_scene(MaterialData("bumpy", ["white", "flat", "top", "sky"], color=(0.8, 0.5, 0.3),
                                      params={**params, "height_scale": 0.08, "uv_scale": 3.0}), LIGHTS)
    scene.assets.texture("white", solid((1.0, 1.0, 1.0), 4))
    scene.assets.texture("flat", encode_normals(np.tile([0.0, 0.0, 1.0], (4, 4, 1)), "flat"))
    scene.assets.texture("top", TextureData.from_array(np.ones((4, 4)), srgb=False, name="top"))
    bumpy = render(backend, solutions, scene)
    hit, points = sphere_hits()
    compared = inner(hit)
    if not seamless_cube_maps(backend):
        normals = points  # a unit sphere at the origin
        towards_eye = (EYE - points) / np.linalg.norm(EYE - points, axis=-1, keepdims=True)
        reflected = 2.0 * np.sum(normals * towards_eye, axis=-1, keepdims=True) * normals - towards_eye
        seams = near_cube_edge(normals, FLAT_MAP_TILT + NORMAL_ERROR)
        seams |= near_cube_edge(reflected, 2.0 * (FLAT_MAP_TILT + NORMAL_ERROR))
        assert (seams & compared).sum() <= 0.06 * compared.sum(), "the seams would hide the sphere"
        compared &= ~seams
    assert np.abs(plain.astype(int) - bumpy.astype(int))[compared].max() <= 2


def _grazing_floor_scene(height_scale: float) -> Scene:
    scene = Scene("grazing")
    scene.assets.mesh("floor", plane(60.0, 1))
    scene.assets.texture("sky", small_sky())
    for name, texture in brick_textures(64).items():
        scene.assets.texture(name, texture)
    scene.assets.material("floor", MaterialData("bumpy", ["bricks_albedo", "bricks_normal", "bricks_height", "sky"],
                                                params={"metallic": 0.0, "roughness": 0.6, "env_strength": 1.0,
                                                        "height_scale": height_scale, "uv_scale": 30.0}))
    scene.create_entity(TransformComponent(), MeshComponent("floor"), MaterialComponent("floor"))
    for light, transform in LIGHTS:
        scene.create_entity(TransformComponent(transform.translation, quaternion=transform.quaternion),
                            LightComponent(light.kind, light.color, light.intensity))
    eye = (0.0, 0.12, 3.0)
    scene.create_entity(TransformComponent(eye, quaternion=look_at_rotation(eye, (0.0, 0.0, -30.0))),
                        CameraComponent(60.0, 0.05, 100.0))
    return scene


@pytest.mark.parametrize("height_scale", [0.0, 0.2])
def test_grazing_view_of_the_parallax_floor_has_no_black_speckles(backend, height_scale):
    image = render(backend, solutions, _grazing_floor_scene(height_scale)).astype(int)
    floor = image[image.shape[0] // 2 + 2:, :, :3]  # below the horizon: all floor
    # Ambient and sky light reach every floor pixel: a NaN (stored as 0) or a wrong sign would show as black.
    assert floor.sum(axis=-1).min() > 15


@pytest.mark.parametrize(("metallic", "roughness"), [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0)])
def test_silhouettes_have_no_speckles(backend, metallic, roughness):
    material = pbr_material((0.9, 0.6, 0.35), metallic, roughness, env_strength=1.0)
    image = render(backend, solutions, sphere_scene(material, LIGHTS)).astype(int)
    hit, _ = sphere_hits()
    rim = inner(hit, 1) & ~inner(hit, 4)  # the grazing ring just inside the silhouette
    assert image[rim][:, :3].sum(axis=-1).min() > 15
    # No isolated outliers: every rim pixel is within 60 steps of the mean of its ring neighbours.
    padded = np.pad(image[..., :3], ((1, 1), (1, 1), (0, 0)), mode="edge")
    neighbours = sum(padded[1 + dy:padded.shape[0] - 1 + dy, 1 + dx:padded.shape[1] - 1 + dx]
                     for dy in (-1, 0, 1) for dx in (-1, 0, 1) if dy or dx) / 8.0
    assert np.abs(image[..., :3] - neighbours)[rim].max() <= 60


def test_brdf_twin_is_finite_for_degenerate_vectors():
    rng = np.random.default_rng(5)
    n = rng.normal(size=(400, 3))
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    to_light = n.copy()
    to_light[::2] = -n[::2]
    v = -to_light  # l + v = 0: no half vector; n·v = -1 or 1
    for roughness in (0.045, 1.0):
        out = ggx_specular_np(n, v, to_light, roughness, np.full(3, 0.04))
        assert np.all(np.isfinite(out)) and out.min() >= 0.0
