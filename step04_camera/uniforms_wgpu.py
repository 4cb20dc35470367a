"""Step 04's API lesson in plain wgpu: per-draw uniforms, a perspective camera and WebGPU's depth range.

One triangle is drawn twice, red at z = −2 and green behind it at z = −3, each with its own model-view-
projection matrix and colour. WebGPU has no uniform state in a pipeline: the values live in a *uniform buffer*
and a *bind group* points the shader at it. All writes reach the GPU before the pass runs, so each draw needs
its own buffer (and bind group). Clip-space depth is [0, 1], so the projection maps the near plane to 0; the
pipeline's depth-stencil state keeps the red triangle in front though it is drawn first.
Compare with ``uniforms_gl.py``.
"""

from __future__ import annotations

import numpy as np
import wgpu

from gandalf_tools import lesson

TRIANGLE = np.array([[-0.8, -0.8, 0.0], [0.8, -0.8, 0.0], [0.0, 0.8, 0.0]])
#: (translation, colour) per draw: red in front, drawn first.
DRAWS = [((-0.25, 0.0, -2.0), (1.0, 0.0, 0.0, 1.0)), ((0.25, 0.0, -3.0), (0.0, 1.0, 0.0, 1.0))]
NEAR, FAR, FOV_Y = 1.5, 4.0, np.radians(60.0)

SHADER = """
struct Object { mvp: mat4x4<f32>, color: vec4<f32> };
@group(0) @binding(0) var<uniform> object: Object;
@vertex fn vs_main(@location(0) position: vec3<f32>) -> @builtin(position) vec4<f32> {
    return object.mvp * vec4<f32>(position, 1.0);
}
@fragment fn fs_main() -> @location(0) vec4<f32> { return object.color; }
"""


# --8<-- [start:projection]
def perspective(aspect: float) -> np.ndarray:
    """WebGPU's perspective: z_ndc = 0 at the near plane, 1 at the far plane."""
    f = 1.0 / np.tan(FOV_Y / 2)
    return np.array([[f / aspect, 0, 0, 0], [0, f, 0, 0],
                     [0, 0, FAR / (NEAR - FAR), FAR * NEAR / (NEAR - FAR)], [0, 0, -1, 0]])
# --8<-- [end:projection]


def render(width: int = 64, height: int = 64) -> np.ndarray:
    """Both triangles as (height, width, 4) uint8, top row first."""
    adapter = wgpu.gpu.request_adapter_sync(power_preference="high-performance")
    limits = lesson.webgpu_limits(adapter, "step04_camera.uniforms_wgpu")  # the defaults, not all it has
    device = adapter.request_device_sync(required_limits=limits)
    module = device.create_shader_module(code=SHADER)
    vertices = device.create_buffer_with_data(data=TRIANGLE.astype("f4").tobytes(), usage=wgpu.BufferUsage.VERTEX)
    pipeline = device.create_render_pipeline(
        layout="auto", vertex={"module": module, "entry_point": "vs_main", "buffers": [
            {"array_stride": 12, "attributes": [{"format": "float32x3", "offset": 0, "shader_location": 0}]}]},
        fragment={"module": module, "entry_point": "fs_main", "targets": [{"format": "rgba8unorm"}]},
        depth_stencil={"format": "depth24plus", "depth_write_enabled": True, "depth_compare": "less"})
    # --8<-- [start:draws]
    bind_groups = []
    for translation, color in DRAWS:
        model = np.eye(4)
        model[:3, 3] = translation
        mvp = perspective(width / height) @ model  # float64 on the CPU
        data = np.concatenate([mvp.T.ravel(), color]).astype("f4")  # column-major mat4, then vec4
        buffer = device.create_buffer_with_data(data=data.tobytes(), usage=wgpu.BufferUsage.UNIFORM)
        bind_groups.append(device.create_bind_group(layout=pipeline.get_bind_group_layout(0),
                                                    entries=[{"binding": 0, "resource": {"buffer": buffer}}]))
    # --8<-- [end:draws]

    def draw(rpass) -> None:
        rpass.set_pipeline(pipeline)
        rpass.set_vertex_buffer(0, vertices)
        for bind_group in bind_groups:
            rpass.set_bind_group(0, bind_group)  # this draw's uniforms
            rpass.draw(3)

    picture = lesson.wgpu_frame(device, width, height, draw, depth=True)
    device.destroy()
    return picture


main = lesson.command(render, __doc__, "uniforms_wgpu.png")


if __name__ == "__main__":
    raise SystemExit(main())
