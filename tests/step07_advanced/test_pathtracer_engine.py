"""The step07 path tracer's engine side (not graded): the same random numbers in GLSL, WGSL and numpy, camera
rays and the cube-map sky against a float64 numpy reference, the display's tonemap, accumulation and restart,
the BVH against brute force (on the CPU and through the GPU kernels), the two APIs' pictures, and the errors.

Tolerances: random numbers bit-exact; sky-only accumulation within 2e-3 (linear) of numpy on at least 99.5 % of
the pixels (the rest sit on cube-face edges where float32 and float64 may pick neighbouring faces); displayed
pixels within 2 of 255 of ``linear_to_srgb(tonemap(mean))``; the GPU BVH's hit mask equal to numpy's brute force
on all but 0.5 % of the pixels; OpenGL against WebGPU on the showcase scene at 48×36 after 16 samples per pixel
with the same seed: PSNR ≥ 30 dB (measured: the two pictures are identical, PSNR ∞, on llvmpipe/lavapipe).
"""

from __future__ import annotations

import contextlib
import importlib
from pathlib import Path

import numpy as np
import pytest
import shader_harness

from gandalf_core import Application, Scene, TransformComponent
from gandalf_core.app.cli import load_impl
from gandalf_core.components import ClearColorComponent, InfoComponent, SkyboxComponent
from gandalf_core.resources import MeshData, ResourceError, TextureData, linear_to_srgb, sky_cube
from gandalf_tools.testing import psnr
from step07_advanced.pathtracer import bvh as bvh_mod
from step07_advanced.pathtracer import scene as pt
from step07_advanced.pathtracer.shaders import SHADER_DIR

SIZE = (48, 36)
PSNR_MIN = 30.0
AGREEMENT_SAMPLES = 16


def tracer_app(backend: str, build, size=SIZE, student: bool = False):
    """A headless app with the path tracer's kernel and display; ``build(kernel)`` returns the scene."""
    app = Application(backend, *size, headless=True, fixed_dt=1 / 60)
    variant = importlib.import_module(f"step07_advanced.pathtracer.{backend}")
    kernel = variant.create_tracer(app, load_impl("step07_advanced", student))
    app.add_scene(build(kernel))
    return app, kernel


@contextlib.contextmanager
def traced(backend: str, build, frames: int):
    """The app of :func:`tracer_app` after ``frames`` frames, open: ``(app, kernel, the accumulation it read)``."""
    app, kernel = tracer_app(backend, build)
    with app:
        app.run(frames=frames)
        yield app, kernel, kernel.read()


def sky_scene(kernel, samples: int = 3) -> Scene:
    scene = Scene("sky only")
    scene.assets.texture("sky", sky_cube(16))
    scene.create_entity(InfoComponent("sky"), SkyboxComponent("sky"))
    scene.create_entity(InfoComponent("settings"), pt.PathTracerComponent(samples=samples, seed=7))
    pt.camera_entity(scene, eye=(0.0, 0.5, 0.0), target=(1.0, 0.9, -1.0), fov=100.0)  # sees three cube faces
    pt.add_tracer(scene, kernel)
    return scene


def _glsl_first(language: str) -> None:
    if language == "glsl":  # creating the harness's wgpu device leaves its EGL context un-current
        shader_harness.gl_context().__enter__()


# --- random numbers ----------------------------------------------------------------------------------------------
@pytest.mark.parametrize("language", ["glsl", "wgsl"])
def test_random_numbers_are_the_same_in_glsl_wgsl_and_numpy(language):
    values = np.r_[np.array([0, 1, 2, 0x7FFFFFFF, 0x80000000, 0xFFFFFFFF], np.uint64),
                   np.random.default_rng(3).integers(0, 2**32, 250)].astype(np.uint32)
    _glsl_first(language)
    prelude = f'#include "rng.{language}"'
    got = shader_harness.evaluate(language, prelude, "pcg_hash(x)", {"x": ("u32", values)}, "u32",
                                  include_dirs=[SHADER_DIR])
    np.testing.assert_array_equal(got, pt.pcg_hash_np(values), err_msg=f"pcg_hash in {language}")
    third = {"glsl": "float third(uint p) { uint s = rng_seed(p, 5u, 9u); rng_next(s); rng_next(s); "
                     "return rng_next(s); }",
             "wgsl": "fn third(p: u32) -> f32 { var s = rng_seed(p, 5u, 9u); rng_next(&s); rng_next(&s); "
                     "return rng_next(&s); }"}[language]
    _glsl_first(language)
    got = shader_harness.evaluate(language, prelude + "\n" + third, "third(x)", {"x": ("u32", values)}, "f32",
                                  include_dirs=[SHADER_DIR])
    state = pt.rng_seed_np(values, 5, 9)
    for _ in range(3):
        state, number = pt.rng_next_np(state)
    np.testing.assert_array_equal(got.astype(np.float64), number, err_msg=f"rng_next in {language}")


# --- the sky, the camera and the display ------------------------------------------------------------------------
@pytest.mark.parametrize("backend", ["opengl", "webgpu"])
def test_sky_only_picture_matches_numpy_and_accumulation_stops_and_restarts(backend):
    with traced(backend, sky_scene, frames=2) as (app, kernel, acc):
        assert np.all(acc[..., 3] == 2.0), f"{backend}: after 2 frames every pixel must hold 2 samples"
        packed = kernel.packed
        texels = pt.sky_texels(app.scene.assets.textures["sky"])
        w, h = SIZE
        expected = sum(pt.sample_sky_np(texels, pt.camera_rays_np(packed, w, h, s)) for s in range(2)) / 2.0
        mean = acc[..., :3] / acc[..., 3:]
        err = np.abs(mean - expected).max(axis=-1)
        assert np.mean(err <= 2e-3) >= 0.995, (f"{backend}: sky mean differs from numpy by up to {err.max():.3g} "
                                              f"on {np.mean(err > 2e-3):.1%} of the pixels")
        shown = app.capture()[..., :3].astype(np.float64)
        want = linear_to_srgb(pt.tonemap_np(mean)) * 255.0
        diff = np.abs(shown - want).max(axis=-1)
        assert np.mean(diff <= 2.0) >= 0.995, f"{backend}: displayed pixels differ by up to {diff.max():.1f}/255"
        app.run(frames=3)
        assert np.all(kernel.read()[..., 3] == 3.0), f"{backend}: the accumulation must stop at samples=3"
        camera = next(e for e, _ in app.scene.view(pt.CameraComponent))
        app.scene.get_component(camera, TransformComponent).translation = (0.0, 0.6, 0.0)
        app.run(frames=1)
        assert np.all(kernel.read()[..., 3] == 1.0), f"{backend}: moving the camera must restart the accumulation"


# --- the BVH ------------------------------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def bunny_triangles() -> np.ndarray:
    mesh = pt.load_mesh(pt.BUNNY_PATH)
    return mesh.positions.astype(np.float64)[mesh.triangles()]


def test_bvh_covers_every_triangle_once_and_finds_the_closest_hit(bunny_triangles):
    tree = bvh_mod.build_bvh(bunny_triangles, "bunny")
    assert sorted(tree.order.tolist()) == list(range(len(bunny_triangles)))
    assert tree.depth <= bvh_mod.MAX_DEPTH
    packed = tree.packed().reshape(-1, 8)
    for i, node in enumerate(tree.nodes):
        if node[7] > 0:
            tris = bunny_triangles[tree.order[int(node[3]):int(node[3] + node[7])]].astype(np.float32)
            assert np.all(tris >= packed[i, 0:3]) and np.all(tris <= packed[i, 4:7]), f"leaf {i} box too small"
    rng = np.random.default_rng(5)
    for _ in range(60):
        origin = rng.normal(0.0, 2.5, 3)
        direction = np.array([0.0, 0.9, 0.0]) + rng.normal(0.0, 0.4, 3) - origin
        t, _index = bvh_mod.closest_hit_np(tree, bunny_triangles, origin, direction)
        brute = _brute_force_t(bunny_triangles, origin, direction)
        assert t == pytest.approx(brute, rel=1e-12), \
            f"BVH hit {t} but brute force {brute} for origin {origin}, direction {direction}"


def _brute_force_t(triangles: np.ndarray, origin: np.ndarray, d: np.ndarray) -> float:
    """The closest t > 1e-4 over all triangles (Möller–Trumbore, vectorised), inf for none."""
    e1, e2 = triangles[:, 1] - triangles[:, 0], triangles[:, 2] - triangles[:, 0]
    tv = origin - triangles[:, 0]
    p, q = np.cross(d, e2), np.cross(tv, e1)
    det = np.sum(e1 * p, axis=1)
    with np.errstate(divide="ignore", invalid="ignore"):
        u, v, t = np.sum(tv * p, axis=1) / det, (q @ d) / det, np.sum(e2 * q, axis=1) / det
    ok = (np.abs(det) > 1e-300) & (u >= 0) & (v >= 0) & (u + v <= 1) & (t > 1e-4)
    return float(t[ok].min()) if ok.any() else np.inf


def _brute_force_mask(triangles: np.ndarray, origin: np.ndarray, dirs: np.ndarray) -> np.ndarray:
    hit = np.zeros(len(dirs), bool)
    e1, e2 = triangles[:, 1] - triangles[:, 0], triangles[:, 2] - triangles[:, 0]
    tv = origin - triangles[:, 0]
    q = np.cross(tv, e1)
    for i, d in enumerate(dirs):
        p = np.cross(d, e2)
        det = np.sum(e1 * p, axis=1)
        with np.errstate(divide="ignore", invalid="ignore"):
            u = np.sum(tv * p, axis=1) / det
            v = (q @ d) / det
            t = np.sum(e2 * q, axis=1) / det
        hit[i] = np.any((np.abs(det) > 1e-300) & (u >= 0) & (v >= 0) & (u + v <= 1) & (t > 1e-4))
    return hit


def bunny_scene(kernel) -> Scene:
    scene = Scene("bunny mask")
    scene.assets.mesh("bunny", pt.load_mesh(pt.BUNNY_PATH))
    scene.create_entity(InfoComponent("white"), ClearColorComponent((1.0, 1.0, 1.0)))
    scene.create_entity(InfoComponent("settings"), pt.PathTracerComponent(samples=1, max_bounces=1, seed=3))
    scene.create_entity(InfoComponent("bunny"), TransformComponent((0.1, -0.9, 0.0), rotation=(0.0, 30.0, 0.0)),
                        pt.TracedMeshComponent("bunny", pt.lambert((0.0, 0.0, 0.0), "black")))
    pt.camera_entity(scene, eye=(0.0, 0.2, 3.0), target=(0.0, 0.0, 0.0), fov=45.0)
    pt.add_tracer(scene, kernel)
    return scene


@pytest.mark.parametrize("backend", ["opengl", "webgpu"])
def test_gpu_bvh_traversal_matches_brute_force(backend):
    with traced(backend, bunny_scene, frames=1) as (app, kernel, acc):
        trace = pt.gather(app.scene)
        w, h = SIZE
        dirs = pt.camera_rays_np(kernel.packed, w, h, 0).reshape(-1, 3)
        expected = _brute_force_mask(trace.triangles, trace.origin, dirs).reshape(h, w)
        got = acc[..., :3].max(axis=-1) == 0.0  # black albedo: a hit carries no light
        wrong = np.mean(got != expected)
        assert expected.mean() > 0.1, "the bunny should cover part of the picture"
        assert wrong <= 0.005, f"{backend}: the GPU's hits differ from brute force on {wrong:.1%} of the pixels"


# --- the two APIs agree ------------------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def showcase_pictures() -> dict[str, np.ndarray]:
    pictures = {}
    for backend in ("opengl", "webgpu"):
        app, _ = tracer_app(backend, lambda k: pt.build_scene(k, samples=AGREEMENT_SAMPLES, sky_size=32))
        with app:
            app.run(frames=AGREEMENT_SAMPLES + 2)  # stops adding after AGREEMENT_SAMPLES
            pictures[backend] = app.capture()
    return pictures


def test_opengl_and_webgpu_pictures_agree(showcase_pictures):
    value = psnr(showcase_pictures["opengl"][..., :3], showcase_pictures["webgpu"][..., :3])
    assert value >= PSNR_MIN, f"OpenGL vs WebGPU after {AGREEMENT_SAMPLES} spp (seed 1): PSNR {value:.1f} dB"


def test_showcase_shows_the_objects(showcase_pictures):
    img = showcase_pictures["opengl"][..., :3].astype(np.float64)
    assert img.std() > 20.0, "the showcase picture should not be flat"


@pytest.mark.parametrize("backend", ["opengl", "webgpu"])
def test_the_stubs_do_not_crash_the_tracer(backend):
    app, kernel = tracer_app(backend, lambda k: pt.build_scene(k, samples=2, sky_size=8, bunny=False),
                             student=True)
    with app:
        app.run(frames=2)
        acc = kernel.read()
        assert np.all(np.isfinite(acc)) and np.all(acc[..., 3] == 2.0)


# --- errors -------------------------------------------------------------------------------------------------------
def test_bvh_over_an_empty_or_degenerate_mesh_is_an_error():
    with pytest.raises(ResourceError, match="at least one triangle"):
        bvh_mod.usable_triangles(np.zeros((0, 3, 3)), "mesh 'empty'")
    flat = MeshData(np.array([[0.0, 0, 0], [1, 1, 1], [2, 2, 2], [0, 0, 0], [0, 0, 0], [0, 0, 0]]), name="flat")
    with pytest.raises(ResourceError, match=r"mesh 'flat'.*zero area"):
        pt.world_triangles(flat, np.eye(4), "mesh 'flat'")
    with pytest.raises(ResourceError, match="T >= 1"):
        bvh_mod.build_bvh(np.zeros((0, 3, 3)), "mesh 'none'")


def test_degenerate_mesh_in_a_scene_names_the_mesh():
    scene = Scene("bad mesh")
    scene.assets.mesh("sliver", MeshData(np.array([[0.0, 0, 0], [1, 0, 0], [2, 0, 0]]), name="sliver"))
    scene.create_entity(InfoComponent("thing"), TransformComponent(), pt.TracedMeshComponent("sliver", pt.lambert(
        (0.5, 0.5, 0.5))))
    pt.camera_entity(scene)
    with pytest.raises(ResourceError, match="mesh 'sliver'.*zero area"):
        pt.gather(scene)


@pytest.mark.parametrize("samples", [0, -3, 2.5])
def test_zero_samples_per_pixel_is_an_error(samples):
    with pytest.raises(ValueError, match="PathTracerComponent.samples"):
        pt.PathTracerComponent(samples=samples)


@pytest.mark.parametrize("fuzz", [-0.1, 1.5, float("nan")])
def test_fuzz_outside_0_1_is_an_error(fuzz):
    with pytest.raises(ResourceError, match=r"path material 'metal': fuzz"):
        pt.metal((0.8, 0.8, 0.8), fuzz)


@pytest.mark.parametrize("ior", [0.0, -1.5, float("inf")])
def test_ior_not_positive_is_an_error(ior):
    with pytest.raises(ResourceError, match=r"path material 'glass': ior"):
        pt.glass(ior)


def test_environment_that_is_not_a_cube_map_is_an_error():
    scene = Scene("flat sky")
    scene.assets.texture("photo", TextureData(np.full((4, 4, 4), 200, np.uint8), name="photo"))
    scene.create_entity(InfoComponent("sky"), SkyboxComponent("photo"))
    pt.camera_entity(scene)
    with pytest.raises(ResourceError, match=r"SkyboxComponent.texture.*cube map"):
        pt.gather(scene)


def test_sphere_needs_a_uniform_scale_and_scene_needs_a_camera():
    scene = Scene("squashed")
    scene.create_entity(InfoComponent("egg"), TransformComponent(scale=(1.0, 2.0, 1.0)),
                        pt.TracedSphereComponent(1.0, pt.lambert((0.5, 0.5, 0.5))))
    with pytest.raises(ResourceError, match="camera"):
        pt.gather(scene)
    pt.camera_entity(scene)
    scene.add_system(pt.TransformSystem())
    scene.update(0.0)
    with pytest.raises(ResourceError, match="egg.*uniform world scale"):
        pt.gather(scene)


def test_scene_files_import_no_gpu_library():
    for name in ("scene.py", "bvh.py", "shaders.py"):
        text = (Path(pt.__file__).parent / name).read_text()
        assert "import moderngl" not in text and "import wgpu" not in text, name


