"""The built-in materials ``gandalf.unlit`` and ``gandalf.blinn_phong``, in both APIs, with no shader written.

A unit sphere (64 × 32 quads) seen from z = 4, lit by a directional light, a point light and an ambient light,
is compared per pixel with a numpy Blinn-Phong on the exact sphere (ray-traced through each pixel centre), on a
96 × 72 target. Tolerance, on the pixels whose ray meets the sphere at least 0.1 inside its silhouette: the
mean difference ≤ 1.5 steps and 99 % of pixels within 4 steps (8-bit sRGB), measured 0.43 mean and 1.2 max
on llvmpipe/lavapipe (the tessellated sphere's interpolated normals against the exact ones). The colour and the
texture variants (a solid-colour texture times the material colour) must give the same picture; the unlit
material shows its colour exactly (±1 step) and its texture's checker squares; the two APIs agree (PSNR ≥ 40
dB). Wrong params, values, texture counts and buffers are errors naming the material and the field; a mesh
without normals under gandalf.blinn_phong is an error naming the mesh.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from gandalf_core import Application, ClearColorComponent, Scene, TransformComponent
from gandalf_core.components import CameraComponent, LightComponent, MaterialComponent, MeshComponent
from gandalf_core.math import look_at_rotation
from gandalf_core.render.builtin_materials import BUILTIN_MATERIALS
from gandalf_core.resources import MaterialData, MeshData, ResourceError, checkerboard, quad, solid, uv_sphere
from gandalf_core.resources.color import srgb_rgba_to_linear
from gandalf_core.resources.texture_data import linear_to_srgb
from gandalf_tools.testing import psnr

W, H = 96, 72
EYE = np.array([0.0, 0.0, 4.0])
FOV = 40.0
COLOR = (0.8, 0.5, 0.3)
SPECULAR, SHININESS = 0.6, 24.0
SUN = np.array([3.0, 3.0, 3.0])  # a directional light here, shining at the origin
LAMP, LAMP_COLOR, LAMP_INTENSITY = np.array([-2.0, 1.0, 3.0]), (0.3, 0.4, 1.0), 0.5
AMBIENT = (0.3, 0.3, 0.3)
SHADERS = Path(__file__).resolve().parents[2] / "gandalf_core" / "render" / "shaders"


def sphere_scene(material: MaterialData, texture=None) -> Scene:
    scene = Scene("builtin")
    scene.assets.mesh("sphere", uv_sphere(1.0, 64, 32))
    if texture is not None:
        scene.assets.texture("albedo", texture)
    scene.assets.material("M", material)
    scene.create_entity(ClearColorComponent((0.0, 0.0, 0.0)))
    scene.create_entity(TransformComponent(), MeshComponent("sphere"), MaterialComponent("M"))
    scene.create_entity(TransformComponent(SUN, quaternion=look_at_rotation(SUN, (0, 0, 0))),
                        LightComponent("directional", (1, 1, 1), 1.0))
    scene.create_entity(TransformComponent(LAMP), LightComponent("point", LAMP_COLOR, LAMP_INTENSITY))
    scene.create_entity(TransformComponent(), LightComponent("ambient", AMBIENT))
    scene.create_entity(TransformComponent(EYE), CameraComponent(fov=FOV, near=0.1, far=100.0))
    return scene


def render(backend: str, scene: Scene, frames: int = 1) -> np.ndarray:
    with Application(backend, W, H, headless=True, fixed_dt=1 / 60) as app:
        app.add_scene(scene)
        app.run(frames=frames)
        return app.capture()[..., :3].astype(float)


def reference(albedo_srgb=COLOR, specular=SPECULAR, shininess=SHININESS) -> tuple[np.ndarray, np.ndarray]:
    """numpy Blinn-Phong on the exact unit sphere: (expected sRGB 0..255 per pixel, mask of pixels to compare)."""
    f = 1.0 / np.tan(np.radians(FOV) / 2)
    x = ((np.arange(W) + 0.5) / W * 2 - 1) * (W / H) / f
    y = (1 - (np.arange(H) + 0.5) / H * 2) / f
    d = np.stack(np.broadcast_arrays(x[None, :], y[:, None], -1.0), axis=-1)
    d /= np.linalg.norm(d, axis=-1, keepdims=True)
    b = d @ EYE
    disc = b * b - (EYE @ EYE - 1.0)
    hit = disc > 0
    t = -b - np.sqrt(np.where(hit, disc, 0.0))
    p = EYE + t[..., None] * d
    n = p / np.linalg.norm(p, axis=-1, keepdims=True)
    v = -d
    albedo = srgb_rgba_to_linear(albedo_srgb)[:3]
    color = srgb_rgba_to_linear(AMBIENT)[:3] * albedo + np.zeros_like(p)
    sun = SUN / np.linalg.norm(SUN)
    lamp = LAMP - p
    lamp /= np.linalg.norm(lamp, axis=-1, keepdims=True)
    lights = [(np.broadcast_to(sun, p.shape), np.ones(3)),
              (lamp, srgb_rgba_to_linear(LAMP_COLOR)[:3] * LAMP_INTENSITY)]
    for to_light, radiance in lights:
        h = to_light + v
        h /= np.linalg.norm(h, axis=-1, keepdims=True)
        lobe = np.clip(np.sum(n * h, axis=-1), 0, None) ** shininess
        diffuse = np.clip(np.sum(n * to_light, axis=-1), 0, None)
        color += (albedo + specular * lobe[..., None]) * radiance * diffuse[..., None]
    expected = 255 * linear_to_srgb(np.clip(color, 0, 1))
    expected[~hit] = 0.0
    # A ray's distance from the centre is sqrt(|o|² - b²); keep those at most 0.9 (0.1 inside the silhouette).
    inside = (EYE @ EYE - b * b) <= 0.9**2
    return expected, inside


def assert_close(image: np.ndarray, expected: np.ndarray, mask: np.ndarray, what: str) -> None:
    error = np.abs(image - expected).max(axis=-1)[mask]
    worst = np.unravel_index(np.argmax(np.where(mask, np.abs(image - expected).max(axis=-1), -1)), mask.shape)
    detail = (f"{what}: mean {error.mean():.2f} steps, 99th percentile {np.percentile(error, 99):.1f}; worst pixel "
              f"(row, col) {worst}: expected {np.round(expected[worst])}, got {image[worst]}")
    assert error.mean() <= 1.5 and np.percentile(error, 99) <= 4, detail


@pytest.fixture(scope="module")
def pictures() -> dict[str, np.ndarray]:
    material = MaterialData("gandalf.blinn_phong", color=COLOR, params={"specular": SPECULAR, "shininess": SHININESS})
    textured = MaterialData("gandalf.blinn_phong", ["albedo"], color=(1.0, 1.0, 1.0),
                            params={"specular": SPECULAR, "shininess": SHININESS})
    out = {}
    for backend in ("opengl", "webgpu"):
        out[backend] = render(backend, sphere_scene(material))
        out[backend + "+texture"] = render(backend, sphere_scene(textured, solid(COLOR, 4, mipmaps=False)))
    return out


@pytest.mark.parametrize("key", ["opengl", "webgpu", "opengl+texture", "webgpu+texture"])
def test_blinn_phong_matches_numpy_on_a_sphere(pictures, key):
    expected, mask = reference()
    assert mask.sum() > 1000
    assert_close(pictures[key], expected, mask, f"gandalf.blinn_phong ({key})")


def test_both_apis_agree(pictures):
    for key in ("", "+texture"):
        value = psnr(pictures["opengl" + key].astype(np.uint8), pictures["webgpu" + key].astype(np.uint8))
        assert value >= 40, f"gandalf.blinn_phong{key}: PSNR {value:.1f} dB between the APIs (need ≥ 40)"


@pytest.mark.parametrize("backend", ["opengl", "webgpu"])
def test_default_params_are_used_when_none_are_given(backend):
    image = render(backend, sphere_scene(MaterialData("gandalf.blinn_phong", color=COLOR)))
    defaults = BUILTIN_MATERIALS["gandalf.blinn_phong"]
    expected, mask = reference(specular=defaults["specular"][0], shininess=defaults["shininess"][0])
    assert_close(image, expected, mask, "gandalf.blinn_phong with default params")


@pytest.mark.parametrize("backend", ["opengl", "webgpu"])
def test_unlit_shows_its_colour_and_texture(backend):
    scene = sphere_scene(MaterialData("gandalf.unlit", color=COLOR))
    image = render(backend, scene)
    expected = 255 * np.array(COLOR)  # sRGB in, sRGB out: no light changes it
    _, mask = reference()
    got = image[mask]
    assert np.abs(got - expected).max() <= 1, f"gandalf.unlit: expected {expected} everywhere, got e.g. {got[0]}"

    scene = Scene("unlit textured")
    scene.assets.mesh("quad", quad(2.0))
    scene.assets.texture("checker", checkerboard(64, 2, (1.0, 1.0, 1.0), (0.0, 0.0, 0.0), filter="nearest"))
    scene.assets.material("M", MaterialData("gandalf.unlit", ["checker"], color=(1.0, 0.5, 0.0)))
    scene.create_entity(TransformComponent(), MeshComponent("quad"), MaterialComponent("M"))
    scene.create_entity(TransformComponent((0, 0, 2.0)), CameraComponent(fov=FOV))
    image = render(backend, scene)
    # The quad spans ±1 at distance 2: ±tan(20°)·2 = ±0.73 of it is in view vertically, so it fills the frame's
    # middle; its four checker squares meet at the centre. Sample the centre of each quarter of the view.
    quarters = [image[H // 4, W // 2 - 6], image[H // 4, W // 2 + 6], image[3 * H // 4, W // 2 - 6],
                image[3 * H // 4, W // 2 + 6]]
    colours = np.array(sorted(tuple(q) for q in quarters))
    expected = np.array([(0, 0, 0), (0, 0, 0), (255, 128, 0), (255, 128, 0)])  # black, and orange × white
    assert np.abs(colours - expected).max() <= 1, f"gandalf.unlit with a checker texture: quarters {colours}"


@pytest.mark.parametrize("backend", ["opengl", "webgpu"])
@pytest.mark.parametrize("material, field, message", [
    (MaterialData("gandalf.blinn_phong", params={"shine": 8.0}), "params['shine']", "no param 'shine'"),
    (MaterialData("gandalf.blinn_phong", params={"shininess": -1.0}), "params['shininess']", "must be ≥ 0"),
    (MaterialData("gandalf.blinn_phong", params={"specular": (1.0, 2.0)}), "params['specular']", "one number"),
    (MaterialData("gandalf.unlit", params={"specular": 1.0}), "params['specular']", "its params: none"),
    (MaterialData("gandalf.unlit", ["albedo", "albedo"]), "textures", "at most one texture"),
    (MaterialData("gandalf.blinn_phong", buffers=["data"]), "buffers", "no storage buffers"),
], ids=["unknown", "negative", "vector", "unlit-param", "two-textures", "buffers"])
def test_wrong_materials_are_named_errors(backend, material, field, message):
    scene = sphere_scene(material, texture=solid((1, 1, 1)))
    with pytest.raises(ResourceError, match=re.escape(f"material 'M': {field}: ") + ".*" + re.escape(message)):
        render(backend, scene)


def test_the_core_material_is_not_step06s_exercise():
    """Step 06's graded exercise is a ``blinn_phong`` shader function: the core must not provide one."""
    for path in sorted(SHADERS.glob("builtin_*")):
        text = path.read_text()
        assert not re.search(r"\bblinn_phong\s*\(", text), f"{path.name} defines or calls blinn_phong()"
        includes = re.findall(r'#include\s+"([^"]+)"', text)
        # Only the engine's own files (resolved beside the including file first) and the generated blocks.
        assert all(name in ("frame.glsl", "frame.wgsl", "material.glsl", "material.wgsl")
                   or (SHADERS / name).is_file() for name in includes), f"{path.name} includes {includes}"


@pytest.mark.parametrize("backend", ["opengl", "webgpu"])
def test_blinn_phong_on_a_mesh_without_normals_is_a_named_error(backend):
    scene = Scene("no normals")
    scene.assets.mesh("flat", MeshData([[0, 0, 0], [1, 0, 0], [0, 1, 0]], name="flat"))
    scene.assets.material("M", MaterialData("gandalf.blinn_phong"))
    scene.create_entity(TransformComponent(), MeshComponent("flat"), MaterialComponent("M"))
    scene.create_entity(TransformComponent((0, 0, 3)), CameraComponent())
    with pytest.raises(ResourceError, match=r"mesh 'flat': normals: .*needs attribute 'normal'"):
        render(backend, scene)
