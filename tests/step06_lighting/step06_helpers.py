"""Shared helpers of the step 06 tests: headless apps, a lit sphere scene, and the numpy reference renderer.

The reference traces one ray per pixel centre against the exact sphere with the camera the app uses and
shades the hit point with a numpy twin of the step's shaders (``lighting.glsl`` + the reference
``blinn_phong``), in float64 and linear light, then encodes to 8-bit sRGB like the framebuffer.
"""

from __future__ import annotations

import functools
from pathlib import Path
from types import ModuleType

import numpy as np
from light_reference import incoming, radiance, to_srgb8

from gandalf_core import Application, Scene, TransformComponent
from gandalf_core.components import CameraComponent, LightComponent, MaterialComponent, MeshComponent
from gandalf_core.math import look_at_rotation
from gandalf_core.resources import MaterialData, MeshData, srgb_to_linear, uv_sphere
from gandalf_tools import testing
from step06_lighting.shaders import register_shaders

REFERENCES = Path(__file__).resolve().parent / "references"
SIZE = (112, 84)
EYE = np.array([0.0, 0.0, 3.2])
FOV = 45.0


def make_app(backend: str, impl: ModuleType, size: tuple[int, int] = SIZE) -> Application:
    """A headless app of ``backend`` with the step's shaders built from ``impl``'s shading include."""
    app = Application(backend, *size, headless=True, fixed_dt=1 / 60)
    register_shaders(app, impl)
    return app


@functools.cache
def _sphere() -> MeshData:
    """One shared sphere: scenes of one app must register the same data under one name."""
    return uv_sphere(1.0, 96, 48)


def sphere_scene(material: MaterialData, lights: list[tuple[LightComponent, TransformComponent]],
                 textures: dict | None = None, light_system=None) -> Scene:
    """A unit sphere at the origin seen from EYE, lit by ``lights``."""
    scene = Scene("sphere")
    scene.assets.mesh("sphere", _sphere())
    for name, data in (textures or {}).items():
        scene.assets.texture(name, data)
    scene.assets.material("M", material)
    scene.create_entity(TransformComponent(), MeshComponent("sphere"), MaterialComponent("M"))
    add_lights(scene, lights)
    scene.create_entity(TransformComponent(EYE, quaternion=look_at_rotation(EYE, (0, 0, 0))),
                        CameraComponent(FOV, 0.1, 20.0))
    if light_system is not None:
        scene.add_system(light_system)
    return scene


add_lights = testing.add_lights


def render(backend: str, impl: ModuleType, scene: Scene, size: tuple[int, int] = SIZE, frames: int = 1) -> np.ndarray:
    with make_app(backend, impl, size) as app:
        app.add_scene(scene)
        app.run(frames=frames)
        return app.capture()


directional = testing.directional_light


point = testing.point_light


ambient = testing.ambient_light


# --- the numpy reference ----------------------------------------------------------------------------
def sphere_hits(size: tuple[int, int] = SIZE) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(hit mask (H, W), hit points (H, W, 3), unit view rays (H, W, 3)) for the unit sphere at the origin."""
    return testing.sphere_hits(EYE, FOV, size)


inner = testing.inner


def blinn_phong_np(n, to_light, v, radiance, albedo, specular, shininess):
    """Numpy twin of the reference ``blinn_phong`` (arrays (..., 3))."""
    n_dot_l = np.maximum(np.sum(n * to_light, axis=-1, keepdims=True), 0.0)
    h = to_light + v
    length = np.linalg.norm(h, axis=-1, keepdims=True)
    h = np.where(length > 1e-6, h / np.maximum(length, 1e-6), n)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        lobe = np.power(np.maximum(np.sum(n * h, axis=-1, keepdims=True), 0.0), shininess) if shininess > 0 else 1.0
    return (albedo + specular * lobe) * radiance * n_dot_l


def shade_np(p, n, v, albedo_srgb, specular, shininess, lights):
    """Numpy twin of ``shade()`` in lighting.glsl; ``lights`` as (LightComponent, TransformComponent) pairs."""
    albedo = srgb_to_linear(np.asarray(albedo_srgb, dtype=np.float64))
    color = np.zeros(p.shape)
    for light, transform in lights:
        if light.kind == "ambient":
            color = color + radiance(light) * albedo
            continue
        to_light, rad = incoming(light, transform, p, n)
        color = color + blinn_phong_np(n, to_light, v, rad, albedo, specular, shininess)
    return color


def reference_sphere(material: MaterialData, lights, size: tuple[int, int] = SIZE) -> tuple[np.ndarray, np.ndarray]:
    """(expected 8-bit RGB (H, W, 3), hit mask) of the phong sphere."""
    hit, p, _ = sphere_hits(size)
    n = p / np.linalg.norm(p, axis=-1, keepdims=True)
    v = EYE - p
    v /= np.linalg.norm(v, axis=-1, keepdims=True)
    params = material.params
    color = shade_np(p, n, v, material.color[:3], params.get("specular", 0.0), params.get("shininess", 0.0), lights)
    return to_srgb8(color), hit



# --- the concepts' pictures ---------------------------------------------------------------------------
CONCEPT_SIZE = {"width": 160, "height": 120}


@functools.cache
def concept_picture(part: str, backend: str) -> np.ndarray:
    """The tour's picture of ``part`` (``step06_lighting.<concept>``, or the step's whole scene) at 160×120."""
    import importlib

    from gandalf_tools.testing import render_frames

    frames = getattr(importlib.import_module(f"{part}.scene"), "TOUR_FRAMES", 30)
    return render_frames(importlib.import_module(f"{part}.{backend}").create_app, frames, **CONCEPT_SIZE)


def check_concept_apis_agree(part: str, name: str) -> None:
    """The WebGPU and OpenGL tour pictures of ``part`` agree (PSNR at least 40 dB); ``name`` names the diff images."""
    testing.compare_images(concept_picture(part, "webgpu"), concept_picture(part, "opengl"),
                           f"step06-{name}-webgpu-vs-opengl", min_psnr=40.0)


def check_concept_reference(part: str, name: str) -> None:
    """The OpenGL tour picture of ``part`` matches ``references/step06_lighting-<name>-opengl.png`` (40 dB)."""
    testing.compare_to_reference(concept_picture(part, "opengl"), REFERENCES / f"step06_lighting-{name}-opengl.png",
                                 min_psnr=40.0)
