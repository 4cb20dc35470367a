"""A triangle drawn with the raw APIs, from a vertex buffer and a layout you made yourself.

This is what the engine does for every mesh, without the engine: create a buffer from bytes, describe its
layout to the API, compile a shader, draw, read the pixels back. The two functions are deliberately written
side by side; compare how moderngl takes a format string (``"3f 4f"``) and attribute *names*, while WebGPU
takes a stride and, per attribute, a format, a byte offset and a shader *location*.

The target is a plain (linear) 8-bit RGBA texture and the shaders pass the colours through unchanged, so a
vertex colour ``c`` reads back as ``round(255 * c)``: there is no sRGB handling here (the engine's is in
``gandalf_core/render/color.py`` and the step's shaders).
"""

from __future__ import annotations

import numpy as np

from gandalf_core.resources import VertexLayout

#: The GLSL input variable for each engine attribute name (moderngl binds attributes by name).
GLSL_NAMES = {"position": "a_position", "color": "a_color"}

GLSL_VERTEX = """
#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 4) in vec4 a_color;
out vec4 v_color;
void main() {
    v_color = a_color;
    gl_Position = vec4(a_position, 1.0);
}
"""
GLSL_FRAGMENT = """
#version 330 core
in vec4 v_color;
out vec4 f_color;
void main() { f_color = v_color; }
"""
WGSL = """
struct VertexOut { @builtin(position) position: vec4<f32>, @location(0) color: vec4<f32> };
@vertex fn vs_main(@location(0) position: vec3<f32>, @location(4) color: vec4<f32>) -> VertexOut {
    var out: VertexOut;
    out.position = vec4<f32>(position, 1.0);
    out.color = color;
    return out;
}
@fragment fn fs_main(in: VertexOut) -> @location(0) vec4<f32> { return in.color; }
"""


def _vertex_bytes(data: np.ndarray, layout: VertexLayout) -> tuple[bytes, int]:
    """The buffer's bytes and its vertex count (whole strides only)."""
    raw = np.ascontiguousarray(data, dtype=np.float32).tobytes()
    if layout.stride <= 0:
        raise ValueError(f"layout.stride: must be a positive number of bytes, got {layout.stride}")
    return raw, len(raw) // layout.stride


def moderngl_format(layout: VertexLayout) -> tuple[str, list[str]]:
    """The moderngl buffer format (e.g. ``"3f 4f"``) and the attribute names it feeds, from ``layout``.

    Gaps between attributes, and after the last one up to the stride, become padding (``"8x"``).
    """
    parts, names, cursor = [], [], 0
    for attr in sorted(layout.attributes, key=lambda a: a.offset_bytes):
        if attr.offset_bytes < cursor:
            raise ValueError(f"layout: attribute {attr.name!r} at byte {attr.offset_bytes} overlaps the one before")
        if attr.offset_bytes > cursor:
            parts.append(f"{attr.offset_bytes - cursor}x")
        parts.append(attr.gl_format)
        names.append(GLSL_NAMES.get(attr.name, attr.name))
        cursor = attr.offset_bytes + 4 * attr.components
    if layout.stride < cursor:
        raise ValueError(f"layout.stride: {layout.stride} bytes is smaller than one vertex ({cursor} bytes)")
    if layout.stride > cursor:
        parts.append(f"{layout.stride - cursor}x")
    return " ".join(parts), names


def wgpu_buffer_layout(layout: VertexLayout) -> dict:
    """The WebGPU vertex buffer layout (stride, and per attribute its format, offset and location)."""
    return {
        "array_stride": layout.stride,
        "step_mode": "vertex",
        "attributes": [
            {"format": a.wgpu_format, "offset": a.offset_bytes, "shader_location": a.location}
            for a in layout.attributes
        ],
    }


def draw_opengl(data: np.ndarray, layout: VertexLayout, width: int = 64, height: int = 64) -> np.ndarray:
    """Draw ``data`` as a triangle list with moderngl; the picture as (height, width, 4) uint8, top row first."""
    import moderngl

    vertex_bytes, count = _vertex_bytes(data, layout)
    fmt, names = moderngl_format(layout)
    ctx = moderngl.create_standalone_context(backend="egl", require=330)
    try:
        program = ctx.program(vertex_shader=GLSL_VERTEX, fragment_shader=GLSL_FRAGMENT)
        buffer = ctx.buffer(vertex_bytes)
        vao = ctx.vertex_array(program, [(buffer, fmt, *names)])
        fbo = ctx.framebuffer([ctx.texture((width, height), 4)])
        fbo.use()
        fbo.clear(0.0, 0.0, 0.0, 1.0)
        vao.render(moderngl.TRIANGLES, vertices=count)
        pixels = np.frombuffer(fbo.read(components=4), dtype=np.uint8).reshape(height, width, 4)
        return pixels[::-1].copy()  # OpenGL's rows start at the bottom
    finally:
        ctx.release()


def draw_webgpu(data: np.ndarray, layout: VertexLayout, width: int = 64, height: int = 64) -> np.ndarray:
    """Draw ``data`` as a triangle list with wgpu; the picture as (height, width, 4) uint8, top row first."""
    import wgpu

    from gandalf_core.render.webgpu.device import request_device

    vertex_bytes, count = _vertex_bytes(data, layout)
    _adapter, device = request_device()
    try:
        buffer = device.create_buffer_with_data(data=vertex_bytes, usage=wgpu.BufferUsage.VERTEX)
        module = device.create_shader_module(code=WGSL)
        pipeline = device.create_render_pipeline(
            layout=device.create_pipeline_layout(bind_group_layouts=[]),
            vertex={"module": module, "entry_point": "vs_main", "buffers": [wgpu_buffer_layout(layout)]},
            fragment={"module": module, "entry_point": "fs_main", "targets": [{"format": "rgba8unorm"}]},
            primitive={"topology": "triangle-list", "front_face": "ccw", "cull_mode": "none"},
        )
        target = device.create_texture(
            size=(width, height, 1), format="rgba8unorm",
            usage=wgpu.TextureUsage.RENDER_ATTACHMENT | wgpu.TextureUsage.COPY_SRC,
        )
        encoder = device.create_command_encoder()
        rpass = encoder.begin_render_pass(color_attachments=[{
            "view": target.create_view(), "clear_value": (0.0, 0.0, 0.0, 1.0),
            "load_op": "clear", "store_op": "store",
        }])
        rpass.set_pipeline(pipeline)
        rpass.set_vertex_buffer(0, buffer)
        rpass.draw(count)
        rpass.end()
        device.queue.submit([encoder.finish()])
        pixels = device.queue.read_texture(
            {"texture": target, "origin": (0, 0, 0), "mip_level": 0},
            {"offset": 0, "bytes_per_row": width * 4, "rows_per_image": height},
            (width, height, 1),
        )
        return np.frombuffer(pixels, dtype=np.uint8).reshape(height, width, 4).copy()
    finally:
        device.destroy()


def draw(backend: str, data: np.ndarray, layout: VertexLayout, width: int = 64, height: int = 64) -> np.ndarray:
    """``draw_opengl`` or ``draw_webgpu`` by name (``"opengl"`` / ``"webgpu"``)."""
    if backend not in ("opengl", "webgpu"):
        raise ValueError(f"backend: expected 'opengl' or 'webgpu', got {backend!r}")
    return (draw_opengl if backend == "opengl" else draw_webgpu)(data, layout, width, height)
