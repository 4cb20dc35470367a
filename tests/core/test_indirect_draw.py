"""Indirect draws (``MeshData(indirect=...)``), in both APIs: the GPU draws the vertex count a buffer holds.

A shader that pulls nothing draws, from its vertex index alone, vertical strips 1/8 of the frame wide (6 vertices
each). With the buffer's first uint32 set to 6·k the frame covers exactly k strips (k = 1, 3, 8), whatever
placeholder vertices the mesh has; the renderer writes the instance count. A missing or short buffer, a shader
that reads attributes, indices or patches with ``indirect``: errors that name the mesh and the buffer.
"""

from __future__ import annotations

import numpy as np
import pytest

from gandalf_core import Application, Scene, TransformComponent
from gandalf_core.components import CameraComponent, MaterialComponent, MeshComponent
from gandalf_core.resources import MaterialData, MeshData, ResourceError

STRIPS_WGSL = """
@vertex fn vs_main(@builtin(vertex_index) index: u32) -> @builtin(position) vec4<f32> {
    var corners = array<vec2<f32>, 6>(vec2<f32>(0.0, 0.0), vec2<f32>(1.0, 0.0), vec2<f32>(1.0, 1.0),
                                      vec2<f32>(0.0, 0.0), vec2<f32>(1.0, 1.0), vec2<f32>(0.0, 1.0));
    let c = corners[index % 6u];
    let x0 = -1.0 + 0.25 * f32(index / 6u);
    return vec4<f32>(x0 + 0.25 * c.x, -1.0 + 2.0 * c.y, 0.5, 1.0);
}
@fragment fn fs_main() -> @location(0) vec4<f32> { return vec4<f32>(1.0); }
"""
STRIPS_VERT = """#version 330 core
void main() {
    vec2 corners[6] = vec2[6](vec2(0.0, 0.0), vec2(1.0, 0.0), vec2(1.0, 1.0),
                              vec2(0.0, 0.0), vec2(1.0, 1.0), vec2(0.0, 1.0));
    vec2 c = corners[gl_VertexID % 6];
    float x0 = -1.0 + 0.25 * float(gl_VertexID / 6);
    gl_Position = vec4(x0 + 0.25 * c.x, -1.0 + 2.0 * c.y, 0.5, 1.0);
}
"""
STRIPS_FRAG = """#version 330 core
out vec4 f_color;
void main() { f_color = vec4(1.0); }
"""
W, H = 64, 16


def _app(backend: str, mesh: MeshData, args: np.ndarray | None) -> Application:
    app = Application(backend, W, H, headless=True, fixed_dt=1 / 60)
    if backend == "opengl":
        app.renderer.shaders.build("strips", STRIPS_VERT, STRIPS_FRAG)
    else:
        app.renderer.shaders.build("strips", STRIPS_WGSL)
    if args is not None:
        app.renderer.buffers.build("draw", args)
    scene = Scene("indirect")
    scene.assets.mesh("strips", mesh)
    scene.assets.material("white", MaterialData("strips", cull="none"))
    scene.create_entity(TransformComponent(), MeshComponent("strips"), MaterialComponent("white"))
    scene.create_entity(TransformComponent((0.0, 0.0, 3.0)), CameraComponent(50.0, 0.1, 10.0))
    app.add_scene(scene)
    return app


@pytest.mark.parametrize("strips", [1, 3, 8])
def test_the_gpu_draws_the_count_the_buffer_holds(backend, strips):
    mesh = MeshData(np.zeros((3, 3)), name="placeholder", indirect="draw")
    with _app(backend, mesh, np.array([6 * strips, 7, 7, 7], dtype=np.uint32)) as app:
        app.run(frames=1)
        covered = app.capture()[..., 0] > 128
        assert covered.sum() == strips * (W // 8) * H, f"{backend}: {covered.sum()} pixels for {strips} strips"
        assert covered[:, : strips * W // 8].all()
        args = app.renderer.buffers.get("draw")
        data = args.read() if backend == "opengl" else app.renderer.device.queue.read_buffer(args)
        assert np.frombuffer(data, np.uint32).tolist() == [6 * strips, 1, 0, 0]


def test_bad_indirect_draws_are_named(backend):
    mesh = MeshData(np.zeros((3, 3)), name="placeholder", indirect="draw")
    with _app(backend, mesh, None) as app, pytest.raises(Exception, match="draw"):
        app.run(frames=1)
    with _app(backend, mesh, np.zeros(2, np.uint32)) as app, \
            pytest.raises(ResourceError, match=r"mesh 'strips'.*indirect.*buffer 'draw' has 8 bytes"):
        app.run(frames=1)


def test_an_indirect_mesh_has_no_indices_or_patches():
    with pytest.raises(ResourceError, match="indirect"):
        MeshData(np.zeros((3, 3)), indices=[0, 1, 2], indirect="draw")
    with pytest.raises(ResourceError, match="indirect"):
        MeshData(np.zeros((3, 3)), patch_size=3, indirect="draw")
    with pytest.raises(ResourceError, match="indirect"):
        MeshData(np.zeros((3, 3)), indirect="")
