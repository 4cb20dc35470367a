"""Step 02's API lesson in plain wgpu: one interleaved vertex buffer, its layout, one draw.

The buffer holds, per vertex, a 2D position and an RGB colour (5 float32, a stride of 20 bytes). WebGPU
describes that layout in the render pipeline: the stride, and per attribute a format, a byte offset and the
shader *location* it feeds; the buffer itself is only bound to a slot when the pass is recorded.
Compare with ``vertex_buffer_gl.py``, where the layout is a format string and inputs are bound by name.
"""

from __future__ import annotations

import numpy as np
import wgpu

from gandalf_tools import lesson

#: x, y, r, g, b per vertex, counter-clockwise.
VERTICES = np.array([
    [-0.8, -0.8, 1.0, 0.0, 0.0],
    [0.8, -0.8, 0.0, 1.0, 0.0],
    [0.0, 0.8, 0.0, 0.0, 1.0],
], dtype=np.float64)

SHADER = """
struct VertexOut { @builtin(position) position: vec4<f32>, @location(0) color: vec3<f32> };
@vertex fn vs_main(@location(0) position: vec2<f32>, @location(1) color: vec3<f32>) -> VertexOut {
    return VertexOut(vec4<f32>(position, 0.0, 1.0), color);
}
@fragment fn fs_main(in: VertexOut) -> @location(0) vec4<f32> { return vec4<f32>(in.color, 1.0); }
"""


def render(width: int = 64, height: int = 64) -> np.ndarray:
    """The triangle on black as (height, width, 4) uint8, top row first."""
    adapter = wgpu.gpu.request_adapter_sync(power_preference="high-performance")
    limits = lesson.webgpu_limits(adapter, "step02_triangle.vertex_buffer_wgpu")  # the defaults, not all it has
    device = adapter.request_device_sync(required_limits=limits)
    module = device.create_shader_module(code=SHADER)
    # --8<-- [start:buffer]
    buffer = device.create_buffer_with_data(data=VERTICES.astype(np.float32).tobytes(),
                                            usage=wgpu.BufferUsage.VERTEX)
    layout = {"array_stride": 20, "step_mode": "vertex", "attributes": [  # stride, then per attribute:
        {"format": "float32x2", "offset": 0, "shader_location": 0},  # format, byte offset, location
        {"format": "float32x3", "offset": 8, "shader_location": 1},
    ]}
    pipeline = device.create_render_pipeline(
        layout="auto", vertex={"module": module, "entry_point": "vs_main", "buffers": [layout]},
        fragment={"module": module, "entry_point": "fs_main", "targets": [{"format": "rgba8unorm"}]})
    # --8<-- [end:buffer]
    target = device.create_texture(size=(width, height, 1), format="rgba8unorm",
                                   usage=wgpu.TextureUsage.RENDER_ATTACHMENT | wgpu.TextureUsage.COPY_SRC)
    encoder = device.create_command_encoder()
    rpass = encoder.begin_render_pass(color_attachments=[{
        "view": target.create_view(), "clear_value": (0, 0, 0, 1), "load_op": "clear", "store_op": "store"}])
    # --8<-- [start:draw]
    rpass.set_pipeline(pipeline)
    rpass.set_vertex_buffer(0, buffer)  # slot 0 = the pipeline's first buffer layout
    rpass.draw(3)
    # --8<-- [end:draw]
    rpass.end()
    device.queue.submit([encoder.finish()])
    pixels = device.queue.read_texture({"texture": target}, {"bytes_per_row": 4 * width, "rows_per_image": height},
                                       (width, height, 1))
    device.destroy()
    return lesson.image(pixels, width, height, bottom_up=False)


main = lesson.command(render, __doc__, "vertex_buffer_wgpu.png")


if __name__ == "__main__":
    raise SystemExit(main())
