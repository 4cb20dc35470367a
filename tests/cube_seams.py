"""Whether this machine filters cube maps across their face edges (seamless), probed once per API.

WebGPU requires seamless cube-map filtering and OpenGL offers it (``GL_TEXTURE_CUBE_MAP_SEAMLESS``, which
moderngl turns on), but wgpu's OpenGL backend samples each face on its own, clamped at its edge: a linear lookup
that crosses a face edge jumps from one face's colour to the other's instead of blending them. A picture test
whose lookup direction moves by a small angle must then allow a jump for the pixels that look within that angle
of a face edge (:func:`near_cube_edge`).

The probe: a 2 × 2 cube map whose faces are flat grey levels 0, 40, ..., 200, sampled linearly at level 0 along
21 directions crossing the edge between +X (0) and +Z (160). Seamless filtering ramps from 0 to 160 through
the middle; per-face filtering gives 0 up to the edge and 160 after it.
"""

from __future__ import annotations

import functools

import numpy as np

#: Directions swept around the +X/+Z edge (45° in the XZ plane), ±0.2 rad.
_ANGLES = np.pi / 4 + np.linspace(-0.2, 0.2, 21)
_FACES = [np.full((2, 2, 4), (40 * f, 40 * f, 40 * f, 255), np.uint8) for f in range(6)]


def _opengl_ramp() -> np.ndarray:
    from gandalf_core.render.opengl.renderer import _standalone_context

    ctx = _standalone_context()
    try:
        cube = ctx.texture_cube((2, 2), 4, b"".join(face.tobytes() for face in _FACES))
        cube.filter = (ctx.LINEAR, ctx.LINEAR)
        program = ctx.program(
            vertex_shader="#version 330\nin vec2 p; void main() { gl_Position = vec4(p, 0.0, 1.0); }",
            fragment_shader="""#version 330
uniform samplerCube t; out vec4 colour;
void main() {
    float a = 0.785398 + (gl_FragCoord.x - 0.5) / 20.0 * 0.4 - 0.2;
    colour = textureLod(t, vec3(cos(a), 0.0, sin(a)), 0.0);
}""")
        quad = ctx.buffer(np.array([-1, -1, 3, -1, -1, 3], "f4").tobytes())
        target = ctx.simple_framebuffer((len(_ANGLES), 1))
        target.use()
        cube.use(0)
        ctx.vertex_array(program, [(quad, "2f", "p")]).render()
        return np.frombuffer(target.read(components=4), np.uint8).reshape(-1, 4)[:, 0].astype(float)
    finally:
        ctx.release()


def _webgpu_ramp() -> np.ndarray:
    import wgpu

    from gandalf_core.render.webgpu.device import request_device

    _adapter, device = request_device()
    texture = device.create_texture(size=(2, 2, 6), format="rgba8unorm",
                                    usage=wgpu.TextureUsage.TEXTURE_BINDING | wgpu.TextureUsage.COPY_DST)
    for face, pixels in enumerate(_FACES):
        device.queue.write_texture({"texture": texture, "origin": (0, 0, face)}, pixels,
                                   {"bytes_per_row": 8, "rows_per_image": 2}, (2, 2, 1))
    sampler = device.create_sampler(mag_filter="linear", min_filter="linear")
    module = device.create_shader_module(code="""
@group(0) @binding(0) var t: texture_cube<f32>;
@group(0) @binding(1) var s: sampler;
@vertex fn vs(@builtin(vertex_index) i: u32) -> @builtin(position) vec4<f32> {
    return vec4<f32>(vec2<f32>(f32(i % 2u) * 4.0 - 1.0, f32(i / 2u) * 4.0 - 1.0), 0.0, 1.0);
}
@fragment fn fs(@builtin(position) p: vec4<f32>) -> @location(0) vec4<f32> {
    let a = 0.785398 + (p.x - 0.5) / 20.0 * 0.4 - 0.2;
    return textureSampleLevel(t, s, vec3<f32>(cos(a), 0.0, sin(a)), 0.0);
}""")
    pipeline = device.create_render_pipeline(
        layout="auto", vertex={"module": module, "entry_point": "vs"},
        fragment={"module": module, "entry_point": "fs", "targets": [{"format": "rgba8unorm"}]})
    target = device.create_texture(size=(len(_ANGLES), 1, 1), format="rgba8unorm",
                                   usage=wgpu.TextureUsage.RENDER_ATTACHMENT | wgpu.TextureUsage.COPY_SRC)
    group = device.create_bind_group(layout=pipeline.get_bind_group_layout(0), entries=[
        {"binding": 0, "resource": texture.create_view(dimension="cube")}, {"binding": 1, "resource": sampler}])
    encoder = device.create_command_encoder()
    render = encoder.begin_render_pass(color_attachments=[{"view": target.create_view(), "load_op": "clear",
                                                           "store_op": "store", "clear_value": (0, 0, 0, 0)}])
    render.set_pipeline(pipeline)
    render.set_bind_group(0, group)
    render.draw(3)
    render.end()
    device.queue.submit([encoder.finish()])
    pixels = device.queue.read_texture({"texture": target}, {"bytes_per_row": 4 * len(_ANGLES)},
                                       (len(_ANGLES), 1, 1))
    return np.frombuffer(pixels, np.uint8).reshape(-1, 4)[:, 0].astype(float)


@functools.cache
def seamless_cube_maps(api: str) -> bool:
    """True when ``api`` ('opengl' or 'webgpu') blends across cube-map face edges on this machine."""
    ramp = _opengl_ramp() if api == "opengl" else _webgpu_ramp()
    # Seamless: the middle of the sweep (on the edge) is half-way; per face it is one face's own level.
    return bool(40 < ramp[len(ramp) // 2] < 120 and np.abs(np.diff(ramp)).max() < 40)


def near_cube_edge(directions: np.ndarray, angle: float) -> np.ndarray:
    """Which of the (..., 3) unit ``directions`` lie within ``angle`` radians of an edge between two cube faces
    (where the two largest |components| are equal; the angle to that plane is asin((a - b) / √2))."""
    largest = np.sort(np.abs(directions), axis=-1)
    return (largest[..., 2] - largest[..., 1]) / np.sqrt(2.0) < np.sin(angle)
