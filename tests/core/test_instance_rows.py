"""The instance rows reach the vertex shader by instance index (a buffer texture in OpenGL, a storage buffer in
WebGPU), in both APIs: each batch reads its own rows wherever they start in the frame's buffer, also after the buffer
grew and for an indirect draw that is not the frame's first batch; more rows than the API binds is an error that says
how many. (The speed of the way chosen: ``benchmarks/bench_instance_rows.py``.)
"""

from __future__ import annotations

import numpy as np
import pytest

from gandalf_core import Application, Scene, TransformComponent
from gandalf_core.components import CameraComponent, ClearColorComponent, MaterialComponent, MeshComponent
from gandalf_core.resources import MaterialData, MeshData, primitives

W, H = 64, 48


def _scene(entities: list[tuple[tuple[float, float, float], str, str]]) -> Scene:
    scene = Scene("rows")
    scene.assets.mesh("cube", primitives.cube())
    for name, color in (("red", (1.0, 0.0, 0.0)), ("green", (0.0, 1.0, 0.0))):
        scene.assets.material(name, MaterialData("gandalf.unlit", color=color))
    scene.create_entity(ClearColorComponent((0.0, 0.0, 0.0)))
    for position, mesh, material in entities:
        scene.create_entity(TransformComponent(position), MeshComponent(mesh), MaterialComponent(material))
    scene.create_entity(TransformComponent((0.0, 0.0, 10.0)), CameraComponent(40.0, 0.1, 100.0))
    return scene


def _x_of(picture: np.ndarray, channel: int) -> float:
    """Mean column of the pixels lit in ``channel`` (red 0, green 1)."""
    lit = (picture[..., channel] > 128) & (picture[..., 1 - channel] < 64)
    assert lit.any(), f"no pixel of channel {channel} drawn"
    return float(np.nonzero(lit)[1].mean())


def _gl_clean(app: Application) -> None:
    if app.renderer.backend == "opengl":
        assert app.renderer.ctx.error == "GL_NO_ERROR"


def test_each_batch_reads_its_own_rows(backend):
    # Two batches (green sorts after red): the green cube's rows start at row 1; read from row 0 it would be drawn
    # where the red one is.
    with Application(backend, W, H, headless=True, fixed_dt=1 / 60) as app:
        app.add_scene(_scene([((-2.0, 0.0, 0.0), "cube", "red"), ((2.0, 0.0, 0.0), "cube", "green")]))
        app.run(frames=1)
        picture = app.capture()
        _gl_clean(app)
    assert _x_of(picture, 0) < W / 2 - 4, "the red cube is not on the left"
    assert _x_of(picture, 1) > W / 2 + 4, "the green cube is not on the right"


def test_rows_are_read_from_the_new_buffer_after_it_grew(backend):
    # 4 KiB holds 85 rows: 200 more entities make a new instance buffer, which the draws must read from.
    with Application(backend, W, H, headless=True, fixed_dt=1 / 60) as app:
        scene = _scene([((-2.0, 0.0, 0.0), "cube", "red")])
        app.add_scene(scene)
        app.run(frames=1)
        created = app.renderer.stats["buffers_created"]
        for i in range(200):  # far behind the camera's far plane: not drawn, but rows in the buffer
            scene.create_entity(TransformComponent((0.0, 0.0, -500.0 - i)), MeshComponent("cube"),
                                MaterialComponent("red"))
        scene.create_entity(TransformComponent((2.0, 0.0, 0.0)), MeshComponent("cube"), MaterialComponent("green"))
        app.run(frames=2)
        assert app.renderer.stats["buffers_created"] > created, "the instance buffer did not grow"
        picture = app.capture()
        _gl_clean(app)
    assert _x_of(picture, 0) < W / 2 - 4
    assert _x_of(picture, 1) > W / 2 + 4


SHIFTED_VERT = """#version 330 core
#include "frame.glsl"
#include "instance.glsl"
void main() {
    vec2 corners[6] = vec2[6](vec2(0.0, 0.0), vec2(1.0, 0.0), vec2(1.0, 1.0),
                              vec2(0.0, 0.0), vec2(1.0, 1.0), vec2(0.0, 1.0));
    vec2 c = corners[gl_VertexID % 6];
    float x0 = -1.0 + 0.25 * float(gl_VertexID / 6) + instance_model()[3].x;
    gl_Position = vec4(x0 + 0.25 * c.x, -1.0 + 2.0 * c.y, 0.5, 1.0);
}
"""
SHIFTED_FRAG = """#version 330 core
out vec4 f_color;
void main() { f_color = vec4(1.0); }
"""
SHIFTED_WGSL = """
#include "frame.wgsl"
#include "instance.wgsl"
@vertex fn vs_main(@builtin(vertex_index) index: u32, inst: Instance) -> @builtin(position) vec4<f32> {
    var corners = array<vec2<f32>, 6>(vec2<f32>(0.0, 0.0), vec2<f32>(1.0, 0.0), vec2<f32>(1.0, 1.0),
                                      vec2<f32>(0.0, 0.0), vec2<f32>(1.0, 1.0), vec2<f32>(0.0, 1.0));
    let c = corners[index % 6u];
    let x0 = -1.0 + 0.25 * f32(index / 6u) + instance_model(inst)[3].x;
    return vec4<f32>(x0 + 0.25 * c.x, -1.0 + 2.0 * c.y, 0.5, 1.0);
}
@fragment fn fs_main() -> @location(0) vec4<f32> { return vec4<f32>(1.0); }
"""


def test_an_indirect_draw_that_is_not_the_first_batch_reads_its_own_rows(backend):
    # Strips shifted by the instance's x (camera-relative): the mesh "a" (3 placeholder vertices, drawn directly)
    # sits 5 units to the right, off the frame; the indirect strips at x = 0 come second, from row 1.
    with Application(backend, W, H, headless=True, fixed_dt=1 / 60) as app:
        if backend == "opengl":
            app.renderer.shaders.build("shifted", SHIFTED_VERT, SHIFTED_FRAG)
        else:
            app.renderer.shaders.build("shifted", SHIFTED_WGSL)
        app.renderer.buffers.build("draw", np.array([6 * 3, 0, 0, 0], dtype=np.uint32))
        scene = Scene("indirect second")
        scene.assets.mesh("a", MeshData(np.zeros((3, 3)), name="direct"))
        scene.assets.mesh("strips", MeshData(np.zeros((3, 3)), name="placeholder", indirect="draw"))
        scene.assets.material("white", MaterialData("shifted", cull="none"))
        for position, mesh in (((5.0, 0.0, 0.0), "a"), ((0.0, 0.0, 0.0), "strips")):
            scene.create_entity(TransformComponent(position), MeshComponent(mesh), MaterialComponent("white"))
        scene.create_entity(TransformComponent((0.0, 0.0, 0.0)), CameraComponent(50.0, 0.1, 10.0))
        app.add_scene(scene)
        app.run(frames=1)
        covered = app.capture()[..., 0] > 128
        _gl_clean(app)
    assert covered.sum() == 3 * (W // 8) * H, f"{backend}: {covered.sum()} pixels lit for 3 strips"
    assert covered[:, : 3 * W // 8].all()


def test_more_rows_than_the_api_binds_is_an_error_that_says_how_many(backend):
    with Application(backend, W, H, headless=True, fixed_dt=1 / 60) as app:
        app.add_scene(_scene([((float(i), 0.0, 0.0), "cube", "red") for i in range(10)]))
        if backend == "opengl":
            app.renderer._max_instance_texels = 27  # nine instances' rows
            needle = r"10 instances need 30 texels of instance rows, more than this OpenGL driver's buffer textures"
        else:
            app.renderer._max_instance_bytes = 9 * 48
            needle = r"10 instances need 480 bytes of instance rows, more than this device binds as one storage"
        with pytest.raises(ValueError, match=needle):
            app.run(frames=1)
