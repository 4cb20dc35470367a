"""step07 pbr_model: the textured glTF model with image-based light (what runs on the reference solution alone is
in ``test_pbr_model_reference.py``, which a student's release leaves out).

* Graded (``metallic_roughness``): a sphere under a constant environment (every prefiltered level and the
  irradiance map one colour; no lights) against a per-pixel numpy reference of the split sum, diffuse
  ``diffuse_albedo(base, metallic, F) · E`` plus specular ``L · (F0 · A + B)``, with
  ``F = fresnel_schlick_roughness(n·v, F0, roughness)`` and (A, B) read bilinearly from the same 8-bit table.
  The model's shader also includes ``normal_map.*`` (another exercise): the test gives it the reference's, so
  an unfinished normal map costs nothing here (the batch grader's sample class found that it did).
  Tolerance (8-bit steps, pixels 2 inside the silhouette): mean ≤ 1.0, 99th percentile ≤ 3; the reference
  solution measures at most 0.22 and 1 (largest error 2) in both APIs.
* The engine side: the validation of explicit cube-map mip levels, the IBL maths (a constant environment
  stays constant; the BRDF table against Karis' analytic fit), and the errors for a roughness outside [0, 1]
  and an environment that is not a cube map.
"""

from __future__ import annotations

import importlib

import numpy as np
import pytest
from light_reference import difference_sentence, pixel_errors
from step07_helpers import EYE, FOV, brdf_lut_texture, inner, to_srgb8, with_reference_files

from gandalf_core import Application, Scene, TransformComponent
from gandalf_core.components import CameraComponent, MaterialComponent, MeshComponent
from gandalf_core.math import look_at_rotation
from gandalf_core.resources import (
    CubeTextureData,
    MaterialData,
    ResourceError,
    TextureData,
    cube_face_directions,
    srgb_to_linear,
    uv_sphere,
)
from gandalf_core.resources.gltf import DEFAULT_TEXTURES
from gandalf_tools import testing
from gandalf_tools.grading.shader_box import on_shader_box
from step07_advanced.pbr_model import ibl
from step07_advanced.pbr_model.scene import IBL_TEXTURES, check_pbr_material

SIZE = (112, 84)
MAPS = ("gltf_white_srgb", "gltf_white_linear", "gltf_flat_normal", "gltf_white_linear", "gltf_white_srgb")


def make_app(backend: str, impl, size=SIZE) -> Application:
    app = Application(backend, *size, headless=True, fixed_dt=1 / 60)
    importlib.import_module(f"step07_advanced.pbr_model.{backend}").register_shaders(app, impl)
    return app


def solid_cube(rgb8, size: int = 1, **settings) -> CubeTextureData:
    face = np.empty((size, size, 4), np.uint8)
    face[...] = (*rgb8, 255)
    return CubeTextureData(tuple([face] * 6), **settings)


def sphere_scene(color, metallic: float, roughness: float, irradiance: CubeTextureData,
                 prefiltered: CubeTextureData, levels: int) -> Scene:
    scene = Scene("ibl sphere")
    for name in set(MAPS):
        scene.assets.texture(name, DEFAULT_TEXTURES[name])
    for name, texture in zip(IBL_TEXTURES, (irradiance, prefiltered, _lut_texture())):
        scene.assets.texture(name, texture)
    scene.assets.mesh("sphere", _sphere())
    params = {"metallic": metallic, "roughness": roughness, "normal_scale": 1.0, "occlusion_strength": 1.0,
              "emissive": (0.0, 0.0, 0.0, 1.0), "env_strength": 1.0, "prefiltered_levels": float(levels)}
    scene.assets.material("M", MaterialData("pbr_model", [*MAPS, *IBL_TEXTURES], color=color, params=params))
    scene.create_entity(TransformComponent(), MeshComponent("sphere"), MaterialComponent("M"))
    scene.create_entity(TransformComponent(EYE, quaternion=look_at_rotation(EYE, (0, 0, 0))),
                        CameraComponent(FOV, 0.1, 20.0))
    return scene


_cache: dict = {}


def _sphere():
    if "sphere" not in _cache:
        _cache["sphere"] = uv_sphere(1.0, 128, 64)
    return _cache["sphere"]


def _lut_texture() -> TextureData:
    if "lut" not in _cache:
        _cache["lut"] = brdf_lut_texture()  # = ibl.default_ibl().brdf_lut, without its 4 s environment
    return _cache["lut"]


def render(backend, impl, scene, size=SIZE) -> np.ndarray:
    with make_app(backend, impl, size) as app:
        app.add_scene(scene)
        app.run(frames=1)
        return app.capture()


# --- graded: the split sum against numpy -------------------------------------------------------------------
IRRADIANCE8, PREFILTERED8 = (150, 170, 200), (205, 190, 165)


def _bilinear_clamp(pixels: np.ndarray, uv: np.ndarray) -> np.ndarray:
    h, w = pixels.shape[:2]
    x = np.clip(uv[..., 0] * w - 0.5, 0.0, w - 1.0)
    y = np.clip(uv[..., 1] * h - 0.5, 0.0, h - 1.0)
    x0, y0 = np.minimum(np.floor(x).astype(int), w - 2), np.minimum(np.floor(y).astype(int), h - 2)
    fx, fy = (x - x0)[..., None], (y - y0)[..., None]
    top = pixels[y0, x0] * (1 - fx) + pixels[y0, x0 + 1] * fx
    bottom = pixels[y0 + 1, x0] * (1 - fx) + pixels[y0 + 1, x0 + 1] * fx
    return top * (1 - fy) + bottom * fy


def reference_ibl_sphere(color, metallic: float, roughness: float, size=SIZE):
    hit, p, _ = testing.sphere_hits(EYE, FOV, size)
    n = p / np.maximum(np.linalg.norm(p, axis=-1, keepdims=True), 1e-12)
    v = EYE - p
    v /= np.maximum(np.linalg.norm(v, axis=-1, keepdims=True), 1e-12)
    n_dot_v = np.clip(np.sum(n * v, axis=-1), 1e-4, 1.0)
    base = srgb_to_linear(np.asarray(color[:3], dtype=np.float64))
    f0 = 0.04 + (base - 0.04) * metallic
    f = f0 + (np.maximum(1.0 - roughness, f0) - f0) * ((1.0 - n_dot_v) ** 5)[..., None]
    irradiance = srgb_to_linear(np.asarray(IRRADIANCE8) / 255.0)
    radiance = srgb_to_linear(np.asarray(PREFILTERED8) / 255.0)
    lut = _lut_texture().pixels[..., :2].astype(np.float64) / 255.0
    ab = _bilinear_clamp(lut, np.stack([n_dot_v, np.full_like(n_dot_v, roughness)], axis=-1))
    color_linear = base * (1.0 - metallic) * (1.0 - f) * irradiance + radiance * (f0 * ab[..., :1] + ab[..., 1:])
    return to_srgb8(color_linear), hit


@on_shader_box  # the student's shaders run in the grader's shader process; the picture comes back
def _ibl_picture(backend: str, impl, color, metallic: float, roughness: float) -> np.ndarray:
    scene = sphere_scene(color, metallic, roughness, solid_cube(IRRADIANCE8, mipmaps=False),
                         solid_cube(PREFILTERED8, 8, levels=[np.full((6, s, s, 4), (*PREFILTERED8, 255), np.uint8)
                                                             for s in (4, 2, 1)]), 4)
    return render(backend, impl, scene)


@pytest.mark.exercise("metallic_roughness")
@pytest.mark.parametrize(("metallic", "roughness"), [(0.0, 0.5), (1.0, 0.3), (0.0, 1.0), (1.0, 0.0), (0.5, 0.8)])
def test_image_based_light_matches_the_split_sum(impl, backend, metallic, roughness):
    color = (0.9, 0.6, 0.35)
    # The model's shader also includes normal_map.*, another exercise: the reference's, so this one is graded alone.
    image = _ibl_picture(backend, with_reference_files(impl, ("normal_map",)), color, metallic, roughness)
    expected, hit = reference_ibl_sphere(color, metallic, roughness)
    mean, p99 = pixel_errors(image, expected, inner(hit))
    assert mean <= 1.0 and p99 <= 3.0, (
        difference_sentence(image, expected, inner(hit), mean, p99,
                            case=f"a sphere in {backend} lit by an image (metallic {metallic}, roughness {roughness})")
        + ". "
        "Hint: F0 = mix(0.04, base, metallic); diffuse = base (1 - metallic)(1 - F), F = fresnel_schlick_roughness")


# --- engine: explicit cube-map levels (their rendering: test_pbr_model_reference.py) --------------------
def test_cube_levels_are_validated():
    face = np.zeros((8, 8, 4), np.uint8)
    with pytest.raises(ResourceError, match=r"levels\[0\].*\(6, 4, 4, 4\)"):
        CubeTextureData((face,) * 6, levels=[np.zeros((6, 8, 8, 4), np.uint8)], name="env")
    with pytest.raises(ResourceError, match="at most 3"):
        CubeTextureData((face,) * 6, levels=[np.zeros((6, 1, 1, 4), np.uint8)] * 4, name="env")
    with pytest.raises(ResourceError, match="mipmaps=True"):
        CubeTextureData((face,) * 6, mipmaps=False, levels=[np.zeros((6, 4, 4, 4), np.uint8)], name="env")
    cube = CubeTextureData((face,) * 6, levels=[np.ones((6, 4, 4, 4), np.uint8)], name="env")
    assert cube.mip_levels == 2 and [a.shape for a in cube.mip_chain()] == [(6, 8, 8, 4), (6, 4, 4, 4)]
    assert cube.mip_chain()[1].max() == 1  # not recomputed from level 0


# --- IBL maths ----------------------------------------------------------------------------------------------
def test_a_constant_environment_stays_constant():
    def constant(d):
        return np.broadcast_to(np.array([0.2, 0.5, 0.9]), np.shape(d)).copy()

    irradiance = ibl.irradiance_map(constant, size=4, source_size=16, supersample=1)
    assert np.allclose(irradiance, [0.2, 0.5, 0.9], rtol=2e-3), "E/π of a constant L must be L"
    for level in ibl.prefilter_levels(constant, size=8, levels=4, samples=32):
        assert np.allclose(level, [0.2, 0.5, 0.9], rtol=1e-9)


def test_the_graded_tests_brdf_table_is_the_default_ibls():
    """The graded test builds only the BRDF table (``brdf_lut_texture``): it must be ``default_ibl``'s."""
    expected, got = ibl.default_ibl().brdf_lut, brdf_lut_texture()
    assert got.name == expected.name and got.srgb == expected.srgb and got.wrap == expected.wrap
    assert np.array_equal(got.pixels, expected.pixels)


def test_brdf_table_matches_karis_fit_and_the_rough_limit():
    lut = ibl.brdf_lut(size=16, samples=512)
    c = (np.arange(16) + 0.5) / 16
    nv, r = np.meshgrid(c, c)  # rows: roughness
    k = r[..., None] * np.array([-1.0, -0.0275, -0.572, 0.022]) + np.array([1.0, 0.0425, 1.04, -0.04])
    a004 = np.minimum(k[..., 0] ** 2, np.exp2(-9.28 * nv)) * k[..., 0] + k[..., 1]
    fit = np.stack([-1.04 * a004 + k[..., 2], 1.04 * a004 + k[..., 3]], axis=-1)
    assert np.all(lut >= 0.0) and np.all(lut.sum(axis=-1) <= 1.0 + 1e-9)
    # Karis' analytic fit (for mobile) is only a rough one: within 0.2 everywhere, 0.05 on average.
    assert np.abs(lut - fit).max() < 0.2 and np.abs(lut - fit).mean() < 0.05, np.abs(lut - fit).max()
    # Roughness 0: h = n, l = reflect(-v), G = 1, so A = 1 - (1 - n·v)^5 and B = (1 - n·v)^5 exactly.
    mirror = ibl.split_sum(c, 0.0, 16)
    assert np.allclose(mirror, np.stack([1.0 - (1.0 - c) ** 5, (1.0 - c) ** 5], axis=-1), atol=1e-12)
    # Roughness 1 seen head-on: D is uniform, half the samples are lit, and A + B = 1 - ln 2 (+ Fc's tiny part).
    a, b = ibl.split_sum(np.array([1.0]), 1.0, 4096)[0]
    assert a + b == pytest.approx(1.0 - np.log(2.0), abs=2e-3)


def test_prefiltering_converges_with_samples():
    d = cube_face_directions(4).reshape(-1, 3)
    reference = ibl.prefilter_directions(ibl.sky_radiance, d, 0.6, 4096)
    errors = [np.sqrt(np.mean((ibl.prefilter_directions(ibl.sky_radiance, d, 0.6, m) - reference) ** 2))
              for m in (16, 256)]
    assert errors[1] < errors[0] / 3, errors


# --- errors -------------------------------------------------------------------------------------------------
def _material(**params):
    values = {"metallic": 0.0, "roughness": 0.5, "occlusion_strength": 1.0, **params}
    return MaterialData("pbr_model", [*MAPS, *IBL_TEXTURES], params=values)


@pytest.mark.parametrize("param", ["roughness", "metallic", "occlusion_strength"])
def test_unit_params_outside_0_1_name_the_material(param):
    with pytest.raises(ResourceError, match=rf"material 'Chrome'.*{param}.*outside \[0, 1\]"):
        check_pbr_material("Chrome", _material(**{param: 1.5}), {})


def test_an_environment_that_is_not_a_cube_map_names_the_texture():
    flat = TextureData(np.zeros((4, 4, 4), np.uint8), name="panorama")
    with pytest.raises(ResourceError, match=r"texture 'ibl_prefiltered'.*material 'Chrome' prefiltered.*cube map"):
        check_pbr_material("Chrome", _material(), {"ibl_irradiance": solid_cube((0, 0, 0)),
                                                   "ibl_prefiltered": flat})
    with pytest.raises(ResourceError, match=r"texture 'panorama'.*cube map"):
        ibl.build_ibl(flat)


# --- scripts --------------------------------------------------------------------------------------------
def test_make_model_refuses_to_overwrite_and_help_only_prints(tmp_path, capsys):
    from step07_advanced.pbr_model import make_model, study

    target = tmp_path / "cell.glb"
    target.write_bytes(b"keep")
    assert make_model.main(["--out", str(target)]) == 1
    assert target.read_bytes() == b"keep" and "--force" in capsys.readouterr().err
    for module in (make_model, study):
        with pytest.raises(SystemExit) as info:
            module.main(["--help"])
        assert info.value.code == 0 and "usage" in capsys.readouterr().out
    assert not (tmp_path / "out").exists()
