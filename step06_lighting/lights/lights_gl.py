"""Step 06's API lesson in plain moderngl: an array of lights in a uniform block, bound to a binding point.

A sphere (drawn as a full-frame triangle whose fragment shader works out the sphere's normal) is lit by
directional lights with the Lambert term. The lights are one std140 block of bytes: a count, then up to
``MAX_LIGHTS`` (direction, colour) pairs (``light_block.py``). OpenGL binds the buffer to an indexed *binding
point* and tells the program which point its ``Lights`` block reads.
Compare with ``lights_wgpu.py``: the same bytes, bound through a bind group.
"""

from __future__ import annotations

import moderngl
import numpy as np

from gandalf_tools import lesson

from .light_block import light_block

VERTEX_SHADER = """
#version 330 core
out vec2 v_ndc;
void main() {  // one triangle that covers the frame
    v_ndc = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
    gl_Position = vec4(v_ndc, 0.0, 1.0);
}
"""
FRAGMENT_SHADER = """
#version 330 core
struct Light { vec4 direction; vec4 color; };
layout(std140) uniform Lights { uint count; Light lights[4]; };
in vec2 v_ndc;
out vec4 f_color;
void main() {
    vec2 p = v_ndc / 0.9;  // a sphere of radius 0.9 (NDC) facing the viewer
    float r2 = dot(p, p);
    if (r2 > 1.0) { f_color = vec4(0.0, 0.0, 0.0, 1.0); return; }
    vec3 n = vec3(p, sqrt(1.0 - r2));
    vec3 color = vec3(0.05);
    for (uint i = 0u; i < count; ++i) {
        color += max(dot(n, normalize(lights[i].direction.xyz)), 0.0) * lights[i].color.rgb;
    }
    f_color = vec4(min(color, 1.0), 1.0);
}
"""



def render(width: int = 64, height: int = 64) -> np.ndarray:
    """The lit sphere as (height, width, 4) uint8, top row first."""
    ctx = moderngl.create_standalone_context(backend="egl", require=330)
    try:
        program = ctx.program(vertex_shader=VERTEX_SHADER, fragment_shader=FRAGMENT_SHADER)
        # --8<-- [start:lights]
        lights = ctx.buffer(light_block())
        lights.bind_to_uniform_block(0)  # the buffer on binding point 0 ...
        program["Lights"].binding = 0  # ... and the program's block reads point 0
        # --8<-- [end:lights]
        triangle = ctx.vertex_array(program, [])
        return lesson.gl_frame(ctx, width, height, lambda: triangle.render(moderngl.TRIANGLES, vertices=3))
    finally:
        ctx.release()


main = lesson.command(render, __doc__, "lights_gl.png", "480x480")


if __name__ == "__main__":
    raise SystemExit(main())
