"""Step 03's API lesson in plain wgpu: a texture, a sampler, and a shader that samples them.

A 2×2 RGBA texture is drawn over the whole frame with texture coordinates from 0 to 2, so the sampler's
*repeat* address mode tiles it twice each way and its *nearest* filter keeps hard texel edges. In WebGPU the
shader declares a ``texture_2d`` and a ``sampler`` as two bindings; a bind group hands it the texture's view
and the sampler. Compare with ``texture_gl.py``, where both are bound to one texture unit.
"""

from __future__ import annotations

import numpy as np
import wgpu

from gandalf_tools import lesson

#: The texture, top row first: red, green / blue, white.
TEXELS = np.array([[[255, 0, 0, 255], [0, 255, 0, 255]], [[0, 0, 255, 255], [255, 255, 255, 255]]], np.uint8)

SHADER = """
struct VertexOut { @builtin(position) position: vec4<f32>, @location(0) uv: vec2<f32> };
@group(0) @binding(0) var t_texture: texture_2d<f32>;
@group(0) @binding(1) var s_sampler: sampler;
@vertex fn vs_main(@builtin(vertex_index) i: u32) -> VertexOut {  // a full-frame quad as a triangle strip
    let corner = vec2<f32>(f32(i & 1u), f32(i >> 1u)) * 2.0 - 1.0;
    return VertexOut(vec4<f32>(corner, 0.0, 1.0), vec2<f32>(corner.x + 1.0, 1.0 - corner.y));  // 0..2, v = 0 on top
}
@fragment fn fs_main(in: VertexOut) -> @location(0) vec4<f32> { return textureSample(t_texture, s_sampler, in.uv); }
"""


def render(width: int = 64, height: int = 64) -> np.ndarray:
    """The tiled texture as (height, width, 4) uint8, top row first."""
    adapter = wgpu.gpu.request_adapter_sync(power_preference="high-performance")
    limits = lesson.webgpu_limits(adapter, "step03_textures.texture_wgpu")  # the defaults, not all it has
    device = adapter.request_device_sync(required_limits=limits)
    module = device.create_shader_module(code=SHADER)
    pipeline = device.create_render_pipeline(
        layout="auto", vertex={"module": module, "entry_point": "vs_main"},
        fragment={"module": module, "entry_point": "fs_main", "targets": [{"format": "rgba8unorm"}]},
        primitive={"topology": "triangle-strip"})
    # --8<-- [start:texture]
    texture = device.create_texture(size=(2, 2, 1), format="rgba8unorm",
                                    usage=wgpu.TextureUsage.TEXTURE_BINDING | wgpu.TextureUsage.COPY_DST)
    device.queue.write_texture({"texture": texture}, TEXELS.tobytes(),  # row 0 of the data is v = 0
                               {"bytes_per_row": 2 * 4, "rows_per_image": 2}, (2, 2, 1))
    sampler = device.create_sampler(mag_filter="nearest", min_filter="nearest",
                                    address_mode_u="repeat", address_mode_v="repeat")
    bind_group = device.create_bind_group(layout=pipeline.get_bind_group_layout(0), entries=[
        {"binding": 0, "resource": texture.create_view()},  # the shader's t_texture
        {"binding": 1, "resource": sampler},  # the shader's s_sampler
    ])
    # --8<-- [end:texture]

    def draw(rpass) -> None:
        rpass.set_pipeline(pipeline)
        rpass.set_bind_group(0, bind_group)  # the texture and sampler
        rpass.draw(4)

    picture = lesson.wgpu_frame(device, width, height, draw)
    device.destroy()
    return picture


main = lesson.command(render, __doc__, "texture_wgpu.png")


if __name__ == "__main__":
    raise SystemExit(main())
