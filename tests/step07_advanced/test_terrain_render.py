"""The step07 terrain rendered: the student's picture against the reference one, the tessellation following the
camera in both APIs, WebGPU's compute tessellator against its numpy twin (crack-free edges), and the errors for bad
levels, bad heightmaps and patch/program mismatches (the two APIs' agreement on the reference's tour picture is in
``test_terrain_render_reference.py``).

Tolerances: the student's picture against the reference solution's (committed, ``references/terrain-<api>.png``),
same API, 160×120: PSNR ≥ 35 dB (a correct solution differs only by float rounding; the reference measures inf on
llvmpipe/lavapipe). OpenGL's generated triangles (GL_PRIMITIVES_GENERATED) equal the count predicted from the numpy
levels within 1 % (measured: exactly equal); WebGPU's per-patch segment counts equal the numpy ones for ≥ 99 % of the
patches (measured: all).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from gandalf_core import Scene, TransformComponent
from gandalf_core.app.cli import load_impl
from gandalf_core.components import CameraComponent, MaterialComponent, MeshComponent
from gandalf_core.resources import ResourceError, cube
from gandalf_tools.grading.shader_box import on_shader_box
from gandalf_tools.testing import psnr
from step07_advanced.terrain import opengl, patches, scene, webgpu
from step07_advanced.terrain.heightfield import check_heights, encode_heights, fractal_heights, quantize

VARIANT = {"opengl": opengl, "webgpu": webgpu}
SMALL = (160, 120)
NEAR_EYE, NEAR_TARGET = (0.0, 2.6, 6.0), (0.0, 0.8, -2.0)
FAR_EYE, FAR_TARGET = (0.0, 14.0, 30.0), (0.0, 0.0, 0.0)


@on_shader_box  # the student's shaders run in the grader's shader process
def render(backend: str, impl, size=SMALL, frames: int = 2, **scene_args) -> np.ndarray:
    with VARIANT[backend].create_app(headless=True, impl=impl, width=size[0], height=size[1], **scene_args) as app:
        app.run(frames=frames)
        return app.capture()


#: The trusted pictures: the reference solutions' terrain at SMALL after 2 frames, per API, committed (so a student's
#: release, which has no solutions, grades against them too). On the instructor's side the graded test, run on the
#: solutions, checks that they are still the reference's pictures. To remake them after a deliberate change of the
#: scene: render(backend, solutions) saved as PNG (``PIL.Image.fromarray(picture, "RGBA").save(path)``).
REFERENCES = Path(__file__).resolve().parent / "references"


def reference_picture(backend: str) -> np.ndarray:
    """The reference solutions' picture of the terrain in ``backend`` (RGBA, SMALL)."""
    from PIL import Image

    return np.asarray(Image.open(REFERENCES / f"terrain-{backend}.png").convert("RGBA"))


# --- graded ----------------------------------------------------------------------------------------------------
@pytest.mark.exercise("terrain_height")
def test_terrain_picture_matches_the_reference(impl, backend):
    got = render(backend, impl)
    expected = reference_picture(backend)
    value = psnr(got, expected)
    assert value >= 35.0, (f"{backend}: the terrain differs from the reference picture (PSNR {value:.1f} dB < 35 dB; "
                           f"mean colour got {got[..., :3].mean((0, 1)).round(1).tolist()}, expected "
                           f"{expected[..., :3].mean((0, 1)).round(1).tolist()}). Hint: terrain_height lifts the "
                           "vertices, terrain_normal shades them; a flat or unlit terrain means one returns its stub")


#: A flat map for the level test: the levels then depend on tess_level alone, not on terrain_height too.
FLAT = np.zeros((64, 64))


def _predicted(eye) -> tuple[np.ndarray, np.ndarray]:
    return patches.patch_levels(FLAT, scene.PARAMS, np.asarray(eye, dtype=np.float64))


@on_shader_box  # the student's shaders run in the grader's shader process
def gl_triangles(impl, eye, target) -> int:
    """Triangles the OpenGL tessellator generated for one frame (a GL_PRIMITIVES_GENERATED query)."""
    with opengl.create_app(headless=True, impl=impl, width=96, height=72, eye=eye,
                           target=target, heights=FLAT) as app:
        app.run(frames=1)
        query = app.renderer.ctx.query(primitives=True)
        with query:
            app.run(frames=1)
        return int(query.primitives)


@on_shader_box  # the student's shaders run in the grader's shader process
def wgpu_segments(impl, eye, target) -> np.ndarray:
    """Segments per patch side (n) that WebGPU's compute pass chose, read back from its levels buffer."""
    with webgpu.create_app(headless=True, impl=impl, width=96, height=72, eye=eye,
                           target=target, heights=FLAT) as app:
        app.run(frames=1)
        tessellator = app.scene.get_system(scene.TessellationSystem).backend.tessellator
        return tessellator.read_levels()[2]


@pytest.mark.exercise("terrain_lod")
def test_tessellation_follows_the_camera(impl, backend):
    counts = {}
    for name, eye, target in (("near", NEAR_EYE, NEAR_TARGET), ("far", FAR_EYE, FAR_TARGET)):
        outer, inner = _predicted(eye)
        if backend == "opengl":
            got, expected = gl_triangles(impl, eye, target), patches.gl_triangle_count(outer, inner)
            assert abs(got - expected) <= 0.01 * expected, (
                f"camera {name} at {eye}: OpenGL generated {got} triangles, the reference levels give {expected}. "
                "Hint: tess_level = clamp(scale * |b - a| / distance(eye, midpoint), min, max)")
            counts[name] = got
        else:
            got = wgpu_segments(impl, eye, target)
            expected = np.ceil(inner).astype(np.int64)
            wrong = np.flatnonzero(got != expected)
            assert wrong.size <= 0.01 * got.size, (
                f"camera {name} at {eye}: {wrong.size} of {got.size} patches have another level than the reference; "
                f"e.g. patch {wrong[0]}: expected {expected[wrong[0]]} segments, got {got[wrong[0]]}. "
                "Hint: tess_level = clamp(scale * |b - a| / distance(eye, midpoint), min, max)")
            counts[name] = int((got.astype(np.int64) ** 2).sum())
    assert counts["near"] > 1.5 * counts["far"], f"near camera: {counts['near']}, far camera: {counts['far']}"


# --- the engine side (not graded) ---------------------------------------------------------------------------------
def test_compute_tessellator_matches_its_numpy_twin_and_has_no_cracks():
    params = patches.TerrainParams(patches=4, max_level=8, lod_scale=6.0)
    eye = np.array([1.0, 3.0, 6.0])
    with webgpu.create_app(headless=True, width=64, height=48, params=params, eye=eye) as app:
        app.run(frames=1)
        tessellator = app.scene.get_system(scene.TessellationSystem).backend.tessellator
        outer_gpu, inner_gpu, n_gpu = tessellator.read_levels()
        vertices = tessellator.read_vertices()
    heights = quantize(scene.terrain_heights())
    outer, inner = patches.patch_levels(heights, params, eye)
    np.testing.assert_allclose(outer_gpu, outer, rtol=1e-4)
    assert (n_gpu == np.ceil(inner)).all()
    assert len(set(n_gpu.tolist())) > 1, "the test needs patches of different levels"
    st, used = patches.patch_vertices(outer, inner, params.budget)
    assert ((vertices[..., 3] == 1.0) == used).all()
    corners = patches.patch_corner_uvs(params)
    s, t = st[..., :1], st[..., 1:]
    uv = (corners[:, None, 0] * (1 - s) + corners[:, None, 1] * s) * (1 - t) + \
         (corners[:, None, 3] * (1 - s) + corners[:, None, 2] * s) * t
    np.testing.assert_allclose(vertices[..., :2][used], uv[used], atol=1e-6)
    # No cracks: along every edge two neighbours share, both put their vertices at the same points.
    p = params.patches

    def on_line(k: int, axis: int, value: float) -> set[float]:
        points = uv[k][used[k]]
        return {round(float(x), 6) for x in points[np.isclose(points[:, axis], value), 1 - axis]}

    for k in range(p * p):
        j, i = divmod(k, p)
        if i + 1 < p:  # the right neighbour shares u = (i + 1) / p
            a, b = on_line(k, 0, (i + 1) / p), on_line(k + 1, 0, (i + 1) / p)
            assert a == b, f"patches {k} and {k + 1} disagree along u = {(i + 1) / p}: {sorted(a ^ b)}"
        if j + 1 < p:  # the neighbour above shares v = (j + 1) / p
            a, b = on_line(k, 1, (j + 1) / p), on_line(k + p, 1, (j + 1) / p)
            assert a == b, f"patches {k} and {k + p} disagree along v = {(j + 1) / p}: {sorted(a ^ b)}"


@pytest.mark.parametrize("max_level", [0.5, 65, float("nan")])
def test_levels_outside_the_device_range_are_refused(max_level):
    with pytest.raises(ValueError, match="max_level"):
        patches.check_levels(1.0, max_level, opengl.max_tess_level())
    with pytest.raises(ValueError, match="min_level"):
        patches.check_levels(0.0, 4.0, 64)


def test_a_max_level_above_the_device_limit_fails_when_the_program_is_built():
    params = patches.TerrainParams(max_level=80.0)
    with pytest.raises(ValueError, match="GL_MAX_TESS_GEN_LEVEL"):
        opengl.create_app(headless=True, width=32, height=24, params=params)
    with pytest.raises(ValueError, match="budget"):
        webgpu.create_app(headless=True, width=32, height=24, params=params)
    with pytest.raises(ValueError, match="min_level"):
        patches.TerrainParams(min_level=8.0, max_level=4.0)


def test_the_device_limit_is_at_least_the_guaranteed_one():
    assert opengl.max_tess_level() >= 64


@pytest.mark.parametrize(("heights", "message"), [
    (np.zeros((8, 8, 2)), "2-D"),
    (np.zeros((8, 9)), "square"),
    (np.full((8, 8), np.nan), "not finite"),
    (np.zeros((8, 8), dtype=np.int32), "dtype"),
    (np.full((8, 8), 1.5), r"\[0, 1\]"),
    ([[0.0, 1.0], [1.0, 0.0]], "numpy array"),
])
def test_bad_heightmaps_are_refused_naming_the_parameter(heights, message):
    with pytest.raises(ResourceError, match=message) as info:
        encode_heights(heights, name="bad")
    assert "heights" in str(info.value) and "bad" in str(info.value)


def test_heightmap_encoding_keeps_16_bits():
    heights = fractal_heights(32)
    texture = encode_heights(heights)
    decoded = (texture.pixels[..., 0].astype(np.float64) * 256 + texture.pixels[..., 1]) / 65535
    assert np.abs(decoded - heights).max() <= 0.5 / 65535 + 1e-12
    assert np.array_equal(check_heights(heights), heights)


def test_the_tessellation_program_refuses_a_triangle_mesh():
    impl = load_impl("step07_advanced", False)
    with opengl.create_app(headless=True, width=32, height=24) as app:
        opengl.GLTerrain(app, impl)
        bad = Scene("bad")
        bad.assets.texture("heightmap", encode_heights(scene.terrain_heights()))
        bad.assets.mesh("cube", cube(1.0))
        bad.assets.material("terrain", scene.terrain_material(scene.PARAMS))
        bad.create_entity(TransformComponent(), MeshComponent("cube"), MaterialComponent("terrain"))
        bad.create_entity(TransformComponent((0, 0, 3)), CameraComponent(50.0, 0.1, 10.0))
        app.add_scene(bad)
        app.switch_scene(bad)
        with pytest.raises(ResourceError, match="patch_size"):
            app.run(frames=1)


def test_webgpu_refuses_the_patch_mesh():
    with webgpu.create_app(headless=True, width=32, height=24) as app:
        app.scene.assets.mesh("patches", patches.patch_mesh(scene.PARAMS))
        app.scene.create_entity(TransformComponent(), MeshComponent("patches"), MaterialComponent("terrain"))
        with pytest.raises(ResourceError, match="no tessellation stage"):
            app.run(frames=1)


def test_the_pulled_mesh_draws_only_what_the_level_of_detail_produced():
    """The vertex buffer holds the whole budget; the indirect draw takes only the 6·n² vertices of each patch."""
    params = patches.TerrainParams(patches=4, max_level=8, lod_scale=6.0)
    eye = np.array([1.0, 3.0, 6.0])
    with webgpu.create_app(headless=True, width=32, height=24, params=params, eye=eye) as app:
        app.run(frames=1)
        backend = app.scene.get_system(scene.TessellationSystem).backend
        assert backend.tessellator.vertex_count == 4 * 4 * 6 * 64
        assert backend.mesh().indirect == webgpu.DRAW_BUFFER
        outer, inner = patches.patch_levels(quantize(scene.terrain_heights()), params, eye)
        drawn = backend.tessellator.read_draw_count()
    assert drawn == int((6 * np.ceil(inner) ** 2).sum()) < backend.tessellator.vertex_count
