"""Storage buffers against the shaders that read them, in both APIs: a buffer smaller than the shader's
declaration (one array element, or a struct's fixed members plus one element) or not a whole number of elements
is an error naming the material, the buffer and both sizes when the material is built (never a read past its
end); building a buffer again under its name writes the new data into it (same size: the next frame draws it)
or is an error naming both sizes (never the old buffer handed back). A buffer is built for uses (``usage``:
storage, vertex, index, indirect, uniform; WebGPU's usage flags follow from them): a material that binds it as
storage, or a mesh drawn indirectly from it, when it was not built for that use is an error naming the buffer,
the use and what it was built for, from the engine in both APIs (OpenGL's buffers have no flags at all), as
is an unknown use or building the name again for other uses."""

from __future__ import annotations

import numpy as np
import pytest
from core_shaders import SHADERS

from gandalf_core import Scene, TransformComponent
from gandalf_core.components import CameraComponent, MaterialComponent, MeshComponent
from gandalf_core.render.capabilities import require_opengl
from gandalf_core.resources import MaterialData, MeshData, ResourceError

from .catalogue import error, params_per_backend, result, run

TRIANGLE = np.array([[-1.0, -0.8, 0.0, 1.0], [1.2, -0.5, 0.0, 1.0], [0.1, 0.9, 0.0, 1.0]], np.float32)

#: Vertex pulling from a struct with a fixed member before its runtime array: 16 + n × 16 bytes.
HEADED_VERT = """#version 430 core
#include "frame.glsl"
#include "instance.glsl"
layout(std430, binding = 0) readonly buffer Corners { vec4 offset; vec4 corners[]; };
void main() {
    gl_Position = u_projection * u_view * instance_model() * vec4(corners[gl_VertexID].xyz + offset.xyz, 1.0);
}
"""
HEADED_WGSL = """
#include "frame.wgsl"
#include "instance.wgsl"
#include "material.wgsl"
struct Corners { offset: vec4<f32>, corners: array<vec4<f32>>, };
@group(1) @binding(1) var<storage, read> pulled: Corners;
@vertex fn vs_main(@builtin(vertex_index) index: u32, inst: Instance) -> @builtin(position) vec4<f32> {
    return frame.projection * frame.view * instance_model(inst) * vec4<f32>(pulled.corners[index].xyz
        + pulled.offset.xyz, 1.0);
}
@fragment fn fs_main() -> @location(0) vec4<f32> { return material.color; }
"""


def ready(app):
    shaders = app.renderer.shaders
    if app.backend == "opengl":  # a machine of OpenGL 3.3 (softpipe, macOS) has no storage buffers: skipped, named
        require_opengl(app.renderer.ctx, 430, "storage buffers", "the storage-buffer check")
        shaders.build("pulled", SHADERS / "pulled.vert", SHADERS / "flat.frag")
        shaders.build("headed", HEADED_VERT, SHADERS / "flat.frag")
    else:
        shaders.build("pulled", SHADERS / "pulled.wgsl")
        shaders.build("headed", HEADED_WGSL)
    return app


_n = [0]


def drawn(shader: str, data, then=None, **build):
    """Build buffer 'B<n>' from ``data`` (and ``build``: its usage), draw one frame of a pulled triangle reading it
    (material 'M<n>'), then ``then(app, buffer name)``; returns the share of lit pixels in the last frame."""
    def action(app):
        _n[0] += 1
        buffer, material = f"B{_n[0]}", f"M{_n[0]}"
        ready(app).renderer.buffers.build(buffer, data, **build)
        scene = Scene(f"buffers-{_n[0]}")
        scene.create_entity(TransformComponent((0, 0, 3)), CameraComponent())
        scene.assets.mesh("three", MeshData(np.zeros((3, 3))))
        scene.assets.material(material, MaterialData(shader, color=(1, 0.5, 0.2), buffers=[buffer]))
        scene.create_entity(TransformComponent(), MeshComponent("three"), MaterialComponent(material))
        app.add_scene(scene)
        app.switch_scene(scene)
        app.step()
        if then is not None:
            then(app, buffer)
            app.step()
        return float((app.capture()[..., 0] > 0).mean())
    return action


def rebuilt(data, **build):
    return lambda app, name: app.renderer.buffers.build(name, data, **build)


def indirect_from(usage):
    """Draw a mesh indirectly from a buffer built for ``usage``."""
    def action(app):
        _n[0] += 1
        buffer = f"B{_n[0]}"
        ready(app).renderer.buffers.build(buffer, np.array([3, 1, 0, 0], np.uint32), usage=usage)
        scene = Scene(f"indirect-{_n[0]}")
        scene.create_entity(TransformComponent((0, 0, 3)), CameraComponent())
        scene.assets.mesh("drawn", MeshData(np.zeros((3, 3)), indirect=buffer))
        scene.assets.material("M", MaterialData("pulled", buffers=[f"T{_n[0]}"]))
        app.renderer.buffers.build(f"T{_n[0]}", TRIANGLE)
        scene.create_entity(TransformComponent(), MeshComponent("drawn"), MaterialComponent("M"))
        app.add_scene(scene)
        app.switch_scene(scene)
        app.step()
        return float((app.capture()[..., 0] > 0).mean())
    return action


def flags_of(usage):
    """The uses a buffer built for ``usage`` records, and in WebGPU the usage flags it was created with."""
    def action(app):
        _n[0] += 1
        buffers = app.renderer.buffers
        buffers.build(f"B{_n[0]}", TRIANGLE, usage=usage)
        flags = int(buffers.get(f"B{_n[0]}").usage) if app.backend == "webgpu" else None
        return buffers.uses_of(f"B{_n[0]}"), flags
    return action


def _storage_only(found):
    import wgpu

    uses, flags = found
    copies = wgpu.BufferUsage.COPY_SRC | wgpu.BufferUsage.COPY_DST
    return uses == ("storage",) and flags in (None, int(wgpu.BufferUsage.STORAGE | copies))


HEADED = np.concatenate([np.zeros((1, 4), np.float32), TRIANGLE])

CASES = [
    result("pulled-whole-elements-draw", drawn("pulled", TRIANGLE), lambda lit: 0.05 < lit < 0.8),
    error("pulled-smaller-than-one-element", drawn("pulled", np.zeros(2, np.float32)), ResourceError,
          "material 'M", "buffer 'B", "8 bytes", "16 bytes", "'pulled'"),
    error("pulled-part-of-an-element", drawn("pulled", np.zeros(6, np.float32)), ResourceError,
          "material 'M", "buffer 'B", "24 bytes", "16 bytes"),
    result("struct-fixed-and-array-draws", drawn("headed", HEADED), lambda lit: 0.05 < lit < 0.8),
    error("struct-only-its-fixed-part", drawn("headed", np.zeros(4, np.float32)), ResourceError,
          "material 'M", "buffer 'B", "16 bytes", "32 bytes", "'headed'"),
    error("struct-smaller-than-fixed-part", drawn("headed", np.zeros(2, np.float32)), ResourceError,
          "8 bytes", "32 bytes"),
    result("rebuilt-same-size-is-what-the-next-frame-draws", drawn("pulled", TRIANGLE.nbytes, rebuilt(TRIANGLE)),
           lambda lit: 0.05 < lit < 0.8),
    result("rebuilt-with-a-size-clears-it", drawn("pulled", TRIANGLE, rebuilt(TRIANGLE.nbytes)),
           lambda lit: lit == 0.0),
    error("rebuilt-other-size", drawn("pulled", TRIANGLE, rebuilt(np.zeros(24, np.float32))), ResourceError,
          "buffer 'B", "48 bytes", "96", "another name"),
    result("built-for-storage-only", flags_of(("storage",)), _storage_only),
    result("built-for-storage-draws", drawn("pulled", TRIANGLE, usage="storage"), lambda lit: 0.05 < lit < 0.8),
    error("vertex-buffer-bound-as-storage", drawn("pulled", TRIANGLE, usage=("vertex",)), ResourceError,
          "buffer 'B", "material 'M", "uses it for 'storage'", "built for vertex only", "usage=('vertex', 'storage')"),
    error("storage-buffer-drawn-indirectly", indirect_from(("storage",)), ResourceError,
          "buffer 'B", "mesh 'drawn' (indirect)", "uses it for 'indirect'", "built for storage only"),
    result("indirect-buffer-draws", indirect_from(("storage", "indirect")), lambda lit: 0.05 < lit < 0.8),
    error("unknown-use", drawn("pulled", TRIANGLE, usage=("storage", "texture")), ResourceError,
          "buffer 'B", "usage", "'texture' is not one of"),
    error("no-use", drawn("pulled", TRIANGLE, usage=()), ResourceError, "buffer 'B", "usage", "one or more"),
    error("rebuilt-for-other-uses", drawn("pulled", TRIANGLE, rebuilt(TRIANGLE, usage=("storage", "uniform"))),
          ResourceError, "buffer 'B", "built for storage, vertex, index, indirect", "again for storage, uniform"),
]


@pytest.mark.parametrize(("case", "backend"), params_per_backend(CASES))
def test_buffers(case, backend, apps):
    run(case, apps[backend])


@pytest.mark.parametrize(("glsl", "wgsl", "fixed", "stride"), [
    ("buffer B { vec4 v[]; };", "var<storage, read> v: array<vec4<f32>>;", 0, 16),
    ("buffer B { vec3 v[]; };", "var<storage, read> v: array<vec3<f32>>;", 0, 16),  # vec3: aligned as a vec4
    ("buffer B { float v[]; };", "var<storage, read> v: array<f32>;", 0, 4),  # no std140 padding in storage
    ("buffer B { uint n; vec2 v[]; };", "struct B { n: u32, v: array<vec2<f32>>, };\n"
     "@group(1) @binding(1) var<storage, read> b: B;", 8, 8),
    ("struct P { vec3 p; float w; vec3 q; }; buffer B { P v[]; };",  # w packs after p: 12 + 4, q at 16
     "struct P { p: vec3<f32>, w: f32, q: vec3<f32>, };\n@group(1) @binding(1) var<storage, read> v: array<P>;", 0, 32),
    ("buffer B { mat3 m; vec4 v[2]; };", "struct B { m: mat3x3<f32>, v: array<vec4<f32>, 2>, };\n"
     "@group(1) @binding(1) var<storage, read> b: B;", 80, 0),
])
def test_the_bytes_a_declaration_needs(glsl, wgsl, fixed, stride):
    """std430 and WGSL's storage rules, the same for the course's types: the fixed part and the element stride."""
    from gandalf_core.render.storage import glsl_storage_layouts, wgsl_storage_layouts

    (gl,) = glsl_storage_layouts([glsl]).values()
    source = wgsl if "@binding" in wgsl else f"@group(1) @binding(1) {wgsl}"
    (wg,) = wgsl_storage_layouts(source, 1).values()
    assert (gl.fixed, gl.stride) == (fixed, stride), glsl
    assert (wg.fixed, wg.stride) == (fixed, stride), wgsl
