"""Step 06's API lesson in plain wgpu: an array of lights in a uniform buffer, bound through a bind group.

A sphere (drawn as a full-frame triangle whose fragment shader works out the sphere's normal) is lit by
directional lights with the Lambert term. The lights are one block of bytes laid out as WGSL's uniform rules
ask (the same as std140 here): a count, then up to ``MAX_LIGHTS`` (direction, colour) pairs
(``light_block.py``). WebGPU puts the buffer in a bind group whose layout matches the shader's
``@group(0) @binding(0)``.
Compare with ``lights_gl.py``: the same bytes, bound to a binding point.
"""

from __future__ import annotations

import numpy as np
import wgpu

from gandalf_tools import lesson

from .light_block import light_block

SHADER = """
struct Light { direction: vec4<f32>, color: vec4<f32> };
struct Lights { count: u32, lights: array<Light, 4> };
@group(0) @binding(0) var<uniform> lights: Lights;
struct VertexOut { @builtin(position) position: vec4<f32>, @location(0) ndc: vec2<f32> };
@vertex fn vs_main(@builtin(vertex_index) i: u32) -> VertexOut {  // one triangle that covers the frame
    let ndc = vec2<f32>(select(-1.0, 3.0, i == 1u), select(-1.0, 3.0, i == 2u));
    return VertexOut(vec4<f32>(ndc, 0.0, 1.0), ndc);
}
@fragment fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
    let p = in.ndc / 0.9;  // a sphere of radius 0.9 (NDC) facing the viewer
    let r2 = dot(p, p);
    if (r2 > 1.0) { return vec4<f32>(0.0, 0.0, 0.0, 1.0); }
    let n = vec3<f32>(p, sqrt(1.0 - r2));
    var color = vec3<f32>(0.05);
    for (var i = 0u; i < lights.count; i++) {
        color += max(dot(n, normalize(lights.lights[i].direction.xyz)), 0.0) * lights.lights[i].color.rgb;
    }
    return vec4<f32>(min(color, vec3<f32>(1.0)), 1.0);
}
"""



def render(width: int = 64, height: int = 64) -> np.ndarray:
    """The lit sphere as (height, width, 4) uint8, top row first."""
    adapter = wgpu.gpu.request_adapter_sync(power_preference="high-performance")
    limits = lesson.webgpu_limits(adapter, "step06_lighting.lights.lights_wgpu")  # the defaults, not all it has
    device = adapter.request_device_sync(required_limits=limits)
    module = device.create_shader_module(code=SHADER)
    pipeline = device.create_render_pipeline(
        layout="auto", vertex={"module": module, "entry_point": "vs_main"},
        fragment={"module": module, "entry_point": "fs_main", "targets": [{"format": "rgba8unorm"}]})
    # --8<-- [start:lights]
    lights = device.create_buffer_with_data(data=light_block(), usage=wgpu.BufferUsage.UNIFORM)
    # The bind group's layout is the shader's @group(0); its entry 0 is @binding(0).
    bind_group = device.create_bind_group(layout=pipeline.get_bind_group_layout(0),
                                          entries=[{"binding": 0, "resource": {"buffer": lights}}])
    # --8<-- [end:lights]

    def draw(rpass) -> None:
        rpass.set_pipeline(pipeline)
        rpass.set_bind_group(0, bind_group)  # the lights' uniform buffer
        rpass.draw(3)

    picture = lesson.wgpu_frame(device, width, height, draw)
    device.destroy()
    return picture


main = lesson.command(render, __doc__, "lights_wgpu.png", "480x480")


if __name__ == "__main__":
    raise SystemExit(main())
