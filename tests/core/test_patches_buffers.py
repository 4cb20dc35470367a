"""Tessellation patches (OpenGL) and storage buffers bound by materials (both APIs), and their errors.

A patch mesh drawn by a tessellation program must cover exactly what the same quad drawn as two triangles covers
(identical pixels); a triangle drawn by vertex pulling from a storage buffer must cover what the same triangle drawn
from a vertex buffer covers, in both APIs (identical pixels).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from gandalf_core import Application, ClearColorComponent, Scene, TransformComponent
from gandalf_core.components import CameraComponent, LightComponent, MaterialComponent, MeshComponent
from gandalf_core.math import look_at_rotation
from gandalf_core.render.errors import MissingResourceError, ShaderCompileError
from gandalf_core.resources import MaterialData, MeshData, ResourceError

SHADERS = Path(__file__).parent / "shaders"
W, H = 64, 48
QUAD = np.array([[-1.0, -0.8, 0.0], [1.0, -0.8, 0.0], [1.0, 0.8, 0.0], [-1.0, 0.8, 0.0]])
TRIANGLE = np.array([[-1.0, -0.8, 0.0, 1.0], [1.2, -0.5, 0.0, 1.0], [0.1, 0.9, 0.0, 1.0]], dtype=np.float32)


def scene_with(mesh: MeshData, material: MaterialData, shadows: bool = False) -> Scene:
    scene = Scene("patches")
    scene.assets.mesh("m", mesh)
    scene.assets.material("M", material)
    scene.create_entity(ClearColorComponent((0.0, 0.0, 0.0)))
    scene.create_entity(TransformComponent(), MeshComponent("m"), MaterialComponent("M"))
    eye = np.array([0.0, 0.0, 3.0])
    scene.create_entity(TransformComponent(eye, quaternion=look_at_rotation(eye, (0, 0, 0))),
                        CameraComponent(60.0, 0.1, 10.0))
    if shadows:
        scene.create_entity(TransformComponent((0, 3, 3), quaternion=look_at_rotation((0, 3, 3), (0, 0, 0))),
                            LightComponent("directional", cast_shadows=True))
    return scene


def draw(app: Application, scene: Scene) -> np.ndarray:
    app.add_scene(scene)
    app.run(frames=1)
    return app.capture()


def gl_app() -> Application:
    app = Application("opengl", W, H, headless=True)
    shaders = app.renderer.shaders
    shaders.build("tess", SHADERS / "patch.vert", SHADERS / "flat.frag",
                  tess_control=SHADERS / "patch.tesc", tess_evaluation=SHADERS / "patch.tese")
    shaders.build("flat", SHADERS / "unlit.vert", SHADERS / "flat.frag")
    return app


# --- patches -----------------------------------------------------------------------------------------
def test_a_patch_mesh_is_tessellated_and_covers_its_quad():
    with gl_app() as app:
        tessellated = draw(app, scene_with(MeshData(QUAD, indices=[0, 1, 2, 3], patch_size=4),
                                           MaterialData("tess", color=(0.2, 0.9, 0.4))))
        assert app.renderer.ctx.error == "GL_NO_ERROR"
    with gl_app() as app:
        triangles = draw(app, scene_with(MeshData(QUAD, uvs=np.zeros((4, 2)), indices=[0, 1, 2, 0, 2, 3]),
                                         MaterialData("flat", color=(0.2, 0.9, 0.4))))
    covered = tessellated[..., 1] > 0
    assert 0.1 < covered.mean() < 0.9, "the tessellated quad should cover a good part of the picture"
    assert np.array_equal(tessellated, triangles)


def test_the_program_reports_its_patch_size():
    with gl_app() as app:
        assert app.renderer.shaders.get("tess").patch_vertices == 4
        assert app.renderer.shaders.get("flat").patch_vertices is None


@pytest.mark.parametrize(("mesh", "material", "needle"), [
    (MeshData(QUAD, indices=[0, 1, 2, 0, 2, 3]), "tess", "give it MeshData(..., patch_size=4)"),
    (MeshData(QUAD, uvs=np.zeros((4, 2)), indices=[0, 1, 2, 3], patch_size=4), "flat", "no tessellation control"),
    (MeshData(QUAD[:3], indices=[0, 1, 2], patch_size=3), "tess", "the program expects 4"),
])
def test_patch_mismatches_name_material_shader_and_mesh(mesh, material, needle):
    with gl_app() as app, pytest.raises(ResourceError) as info:
        draw(app, scene_with(mesh, MaterialData(material)))
    message = str(info.value)
    assert needle in message and "material 'M'" in message and "mesh 'm'" in message and f"'{material}'" in message


def test_a_patch_mesh_cannot_cast_shadows():
    with gl_app() as app, pytest.raises(ValueError, match="patch mesh, which the shadow pass cannot draw"):
        draw(app, scene_with(MeshData(QUAD, indices=[0, 1, 2, 3], patch_size=4), MaterialData("tess"), shadows=True))


def test_webgpu_refuses_a_patch_mesh_and_points_to_compute():
    with pulled_app("webgpu") as app, pytest.raises(ResourceError, match="WebGPU has no tessellation stage"):
        draw(app, scene_with(MeshData(QUAD, indices=[0, 1, 2, 3], patch_size=4),
                             MaterialData("pulled", buffers=["triangle"])))


def test_tessellation_stages_come_in_pairs():
    with Application("opengl", W, H, headless=True) as app:
        with pytest.raises(ShaderCompileError, match="needs a tessellation control stage"):
            app.renderer.shaders.build("x", SHADERS / "patch.vert", SHADERS / "flat.frag",
                                       tess_evaluation=SHADERS / "patch.tese")
        with pytest.raises(ShaderCompileError, match="needs a tessellation evaluation stage"):
            app.renderer.shaders.build("y", SHADERS / "patch.vert", SHADERS / "flat.frag",
                                       tess_control=SHADERS / "patch.tesc")


@pytest.mark.parametrize(("kwargs", "needle"), [
    ({"indices": [0, 1, 2, 3, 0, 1], "patch_size": 4}, "not a positive multiple of 4"),
    ({"patch_size": 0}, "integer from 1 to 32"),
    ({"patch_size": 33}, "integer from 1 to 32"),
    ({"patch_size": 2.0}, "integer from 1 to 32"),
    ({"patch_size": 3}, "4 vertices without indices do not form whole patches of 3"),
])
def test_patch_mesh_validation(kwargs, needle):
    with pytest.raises(ResourceError, match=needle):
        MeshData(QUAD, **kwargs)


def test_a_patch_mesh_has_patches_not_triangles():
    mesh = MeshData(np.tile(QUAD, (2, 1)), patch_size=4)
    assert (mesh.patch_count, mesh.triangle_count) == (2, 0)
    with pytest.raises(ResourceError, match="has no triangles until it is tessellated"):
        mesh.triangles()


# --- storage buffers -----------------------------------------------------------------------------------
def pulled_app(backend: str, data=TRIANGLE) -> Application:
    app = Application(backend, W, H, headless=True)
    if backend == "opengl":
        app.renderer.shaders.build("pulled", SHADERS / "pulled.vert", SHADERS / "flat.frag")
        app.renderer.shaders.build("flat", SHADERS / "unlit.vert", SHADERS / "flat.frag")
    else:
        app.renderer.shaders.build("pulled", SHADERS / "pulled.wgsl")
    app.renderer.buffers.build("triangle", data)
    return app


def test_vertex_pulling_from_a_storage_buffer_draws_the_triangle(backend):
    # The mesh only gives the vertex count: the shader reads no attribute, so its positions are never uploaded.
    with pulled_app(backend) as app:
        pulled = draw(app, scene_with(MeshData(np.zeros((3, 3))), MaterialData("pulled", color=(1, 0.5, 0.2),
                                                                                buffers=["triangle"])))
    with Application("opengl", W, H, headless=True) as app:
        app.renderer.shaders.build("flat", SHADERS / "unlit.vert", SHADERS / "flat.frag")
        reference = draw(app, scene_with(MeshData(TRIANGLE[:, :3], uvs=np.zeros((3, 2))),
                                         MaterialData("flat", color=(1, 0.5, 0.2))))
    assert 0.05 < (pulled[..., 0] > 0).mean() < 0.8
    assert np.array_equal(pulled, reference)


def test_a_buffer_written_later_is_what_the_next_frame_draws(backend):
    with pulled_app(backend, TRIANGLE.nbytes) as app:  # zeros: a degenerate triangle
        app.add_scene(scene_with(MeshData(np.zeros((3, 3))), MaterialData("pulled", buffers=["triangle"])))
        app.run(frames=1)
        assert app.capture()[..., 0].max() == 0
        buffer = app.renderer.buffers.get("triangle")
        if backend == "opengl":
            buffer.write(TRIANGLE.tobytes())
        else:
            app.renderer.device.queue.write_buffer(buffer, 0, TRIANGLE.tobytes())
        app.run(frames=1)
        assert (app.capture()[..., 0] > 0).mean() > 0.05


def test_buffer_count_mismatch_names_material_and_shader(backend):
    with pulled_app(backend) as app, pytest.raises(ResourceError) as info:
        draw(app, scene_with(MeshData(np.zeros((3, 3))), MaterialData("pulled")))
    message = str(info.value)
    assert "material 'M'" in message and "0 buffer(s) given" in message and "'pulled'" in message


def test_an_unknown_buffer_is_named(backend):
    with pulled_app(backend) as app, pytest.raises(MissingResourceError, match="buffer 'nope'.*known: triangle"):
        draw(app, scene_with(MeshData(np.zeros((3, 3))), MaterialData("pulled", buffers=["nope"])))


@pytest.mark.parametrize(("data", "needle"), [
    (np.zeros(3, dtype=np.float64), "32-bit numbers"),
    (np.zeros(0, dtype=np.float32), "positive multiple of 4"),
    (6, "positive multiple of 4"),
    ("abc", "numpy array or a size"),
])
def test_buffer_data_is_checked(backend, data, needle):
    with Application(backend, W, H, headless=True) as app, pytest.raises(ResourceError, match=needle):
        app.renderer.buffers.build("b", data)


def test_material_buffers_are_validated():
    with pytest.raises(ResourceError, match="buffers"):
        MaterialData("x", buffers="abc")
    with pytest.raises(ResourceError, match=r"buffers\[0\]"):
        MaterialData("x", buffers=[""])


def test_patch_meshes_and_material_buffers_round_trip_through_usd(tmp_path):
    from step07_advanced.usd import load_scene, save_scene

    original = scene_with(MeshData(QUAD, indices=[0, 1, 2, 3], patch_size=4), MaterialData("tess", buffers=["b"]))
    loaded = load_scene(save_scene(original, tmp_path / "patches.usda"))
    mesh, material = loaded.assets.meshes["m"], loaded.assets.materials["M"]
    assert mesh.patch_size == 4 and np.array_equal(mesh.indices, [0, 1, 2, 3])
    assert material.buffers == ("b",)
