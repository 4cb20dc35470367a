"""Shared helpers of the step 07 tests: headless apps with the step's shaders, small test scenes, and numpy
references (a ray-sphere PBR renderer and a normal-mapped quad), all in float64 and linear light, encoded to
8-bit sRGB like the framebuffer.
"""

from __future__ import annotations

import atexit
import functools
import importlib
import shutil
import tempfile
from pathlib import Path
from types import ModuleType, SimpleNamespace

import numpy as np
from light_reference import incoming, radiance, to_srgb8

from gandalf_core import Application, Scene, TransformComponent
from gandalf_core.app.cli import load_impl
from gandalf_core.components import CameraComponent, MaterialComponent, MeshComponent
from gandalf_core.math import look_at_rotation
from gandalf_core.resources import MaterialData, MeshData, TextureData, sky_cube, srgb_to_linear, uv_sphere
from gandalf_tools import testing

REFERENCES = Path(__file__).resolve().parent / "references"
SIZE = (112, 84)
EYE = np.array([0.0, 0.0, 3.2])
FOV = 45.0


_with_reference: dict[tuple[str, tuple[str, ...]], SimpleNamespace] = {}


def with_reference_files(impl: ModuleType, stems: tuple[str, ...]) -> SimpleNamespace:
    """``impl`` with the reference solution's ``<stem>.glsl`` / ``<stem>.wgsl`` for ``stems``: a shader that
    includes two exercises' files grades one of them alone (else an unfinished other exercise would cost this
    one its points). A copy of ``impl``'s shader files in a temporary folder, made once per run; it stands
    for ``impl`` wherever only its folder is read (``impl.__file__``). In a student's release, which has no
    solutions, the student's own files stand for the reference."""
    folder = Path(impl.__file__).resolve().parent
    key = (str(folder), tuple(stems))
    if key not in _with_reference:
        target = Path(tempfile.mkdtemp(prefix="gandalf-impl-"))
        atexit.register(shutil.rmtree, target, True)
        for path in folder.iterdir():
            if path.suffix in (".glsl", ".wgsl"):
                shutil.copy2(path, target / path.name)
        reference = Path(load_impl("step07_advanced").__file__).resolve().parent
        for stem in stems:
            for language in ("glsl", "wgsl"):
                shutil.copy2(reference / f"{stem}.{language}", target / f"{stem}.{language}")
        (target / "__init__.py").write_text("")
        _with_reference[key] = SimpleNamespace(__file__=str(target / "__init__.py"), __name__=impl.__name__)
    return _with_reference[key]


@functools.cache
def brdf_lut_texture(prefix: str = "ibl") -> TextureData:
    """The split sum's BRDF table as ``build_ibl`` makes it (the same texture as ``default_ibl().brdf_lut``),
    without the prefiltered environment that ``default_ibl`` also computes (about 4 s of a grading run)."""
    from step07_advanced.pbr_model import ibl

    lut = ibl.brdf_lut()
    rgba = np.concatenate([lut, np.zeros(lut.shape[:2] + (1,)), np.ones(lut.shape[:2] + (1,))], axis=-1)
    return TextureData.from_array(np.clip(rgba, 0.0, 1.0), srgb=False, wrap="clamp", mipmaps=False,
                                  name=f"{prefix}_brdf_lut")


def make_app(backend: str, impl: ModuleType, size: tuple[int, int] = SIZE) -> Application:
    """A headless app of ``backend`` with the step's render shaders built from ``impl``'s includes."""
    app = Application(backend, *size, headless=True, fixed_dt=1 / 60)
    importlib.import_module(f"step07_advanced.showcase.{backend}").register_shaders(app, impl)
    return app


def render(backend: str, impl: ModuleType, scene: Scene, size: tuple[int, int] = SIZE) -> np.ndarray:
    with make_app(backend, impl, size) as app:
        app.add_scene(scene)
        app.run(frames=1)
        return app.capture()


@functools.cache
def _sphere() -> MeshData:
    return uv_sphere(1.0, 128, 64)


@functools.cache
def small_sky():
    return sky_cube(8)


directional = testing.directional_light


point = testing.point_light


ambient = testing.ambient_light


add_lights = testing.add_lights


def pbr_material(color, metallic: float, roughness: float, env_strength: float = 0.0) -> MaterialData:
    return MaterialData("pbr", ["sky"], color=color,
                        params={"metallic": metallic, "roughness": roughness, "env_strength": env_strength})


def sphere_scene(material: MaterialData, lights) -> Scene:
    """A unit sphere at the origin seen from EYE, lit by ``lights`` (the sky is bound, used by env_strength)."""
    scene = Scene("sphere")
    scene.assets.mesh("sphere", _sphere())
    scene.assets.texture("sky", small_sky())
    scene.assets.material("M", material)
    scene.create_entity(TransformComponent(), MeshComponent("sphere"), MaterialComponent("M"))
    add_lights(scene, lights)
    scene.create_entity(TransformComponent(EYE, quaternion=look_at_rotation(EYE, (0, 0, 0))),
                        CameraComponent(FOV, 0.1, 20.0))
    return scene


# --- numpy references -------------------------------------------------------------------------------
def sphere_hits(size: tuple[int, int] = SIZE) -> tuple[np.ndarray, np.ndarray]:
    """(hit mask (H, W), hit points (H, W, 3)) of the unit sphere, one ray per pixel centre."""
    mask, points, _rays = testing.sphere_hits(EYE, FOV, size)
    return mask, points


inner = testing.inner


def _dot(a, b):
    return np.sum(a * b, axis=-1, keepdims=True)


def fresnel_np(cos_theta, f0):
    return f0 + (1.0 - f0) * np.clip(1.0 - cos_theta, 0.0, 1.0) ** 5


def ggx_specular_np(n, v, to_light, roughness, f0):
    """Numpy twin of the reference ``ggx_specular`` (arrays (..., 3))."""
    n_dot_v = np.maximum(_dot(n, v), 1e-4)
    n_dot_l = np.maximum(_dot(n, to_light), 1e-4)
    s = to_light + v
    length = np.linalg.norm(s, axis=-1, keepdims=True)
    h = np.where(length > 1e-6, s / np.maximum(length, 1e-6), n)
    n_dot_h = np.clip(_dot(n, h), 0.0, 1.0)
    alpha2 = roughness**4
    d = alpha2 / (np.pi * (n_dot_h**2 * (alpha2 - 1.0) + 1.0) ** 2)
    k = (roughness + 1.0) ** 2 / 8.0
    g = n_dot_v / (n_dot_v * (1 - k) + k) * n_dot_l / (n_dot_l * (1 - k) + k)
    return d * g * fresnel_np(np.clip(_dot(v, h), 0.0, 1.0), f0) / (4.0 * n_dot_v * n_dot_l)


def pbr_direct_np(p, n, v, base_srgb, metallic, roughness, lights):
    """Numpy twin of ``pbr_direct`` in pbr_lighting.glsl; ``lights`` as (LightComponent, TransformComponent)."""
    base = srgb_to_linear(np.asarray(base_srgb, dtype=np.float64))
    r = float(np.clip(roughness, 0.045, 1.0))
    f0 = 0.04 + (base - 0.04) * metallic
    color = np.zeros(p.shape)
    for light, transform in lights:
        if light.kind == "ambient":
            color = color + radiance(light) * (base * (1.0 - metallic) + f0)
            continue
        to_light, rad = incoming(light, transform, p, n)
        n_dot_l = _dot(n, to_light)
        h = to_light + v
        h = h / np.maximum(np.linalg.norm(h, axis=-1, keepdims=True), 1e-12)
        k_d = (1.0 - fresnel_np(np.maximum(_dot(h, v), 0.0), f0)) * (1.0 - metallic)
        lit = (k_d * base / np.pi + ggx_specular_np(n, v, to_light, r, f0)) * rad * n_dot_l
        color = color + np.where(n_dot_l > 0.0, lit, 0.0)
    return color


def reference_sphere(material: MaterialData, lights, size: tuple[int, int] = SIZE) -> tuple[np.ndarray, np.ndarray]:
    """(expected 8-bit RGB (H, W, 3), hit mask) of the PBR sphere without environment light."""
    hit, p = sphere_hits(size)
    n = p / np.linalg.norm(p, axis=-1, keepdims=True)
    v = EYE - p
    v /= np.linalg.norm(v, axis=-1, keepdims=True)
    params = material.params
    color = pbr_direct_np(p, n, v, material.color[:3], float(params["metallic"]), float(params["roughness"]), lights)
    return to_srgb8(color), hit



def sample_bilinear(texture: TextureData, uv: np.ndarray) -> np.ndarray:
    """Bilinear lookup (repeat wrap, level 0, values in [0, 1]) of ``texture`` at ``uv`` (..., 2)."""
    pixels = texture.pixels[..., :3].astype(np.float64) / 255.0
    h, w = pixels.shape[:2]
    x = uv[..., 0] * w - 0.5
    y = uv[..., 1] * h - 0.5
    x0, y0 = np.floor(x), np.floor(y)
    fx, fy = (x - x0)[..., None], (y - y0)[..., None]
    x0, y0 = x0.astype(int), y0.astype(int)

    def at(yy, xx):
        return pixels[np.mod(yy, h), np.mod(xx, w)]

    top = at(y0, x0) * (1 - fx) + at(y0, x0 + 1) * fx
    bottom = at(y0 + 1, x0) * (1 - fx) + at(y0 + 1, x0 + 1) * fx
    return top * (1 - fy) + bottom * fy


def check_tour_pictures_agree(technique: str, impl: ModuleType, frames: int) -> None:
    """The tour's picture of ``technique`` (``frames`` frames of ``step07_advanced.<technique>.opengl`` / ``webgpu``
    with ``impl``'s exercises or solutions) agrees between the two APIs (PSNR at least 35 dB)."""
    pictures = {}
    for backend in ("opengl", "webgpu"):
        variant = importlib.import_module(f"step07_advanced.{technique}.{backend}")
        with variant.create_app(headless=True, student=impl.__name__.endswith("exercises")) as app:
            app.run(frames=frames)
            pictures[backend] = app.capture()
    assert testing.compare_images(pictures["webgpu"], pictures["opengl"], f"{technique}-tour", min_psnr=35.0) >= 35.0
