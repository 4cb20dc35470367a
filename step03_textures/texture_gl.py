"""Step 03's API lesson in plain moderngl: a texture, a sampler, and a shader that samples them.

A 2×2 RGBA texture is drawn over the whole frame with texture coordinates from 0 to 2, so the sampler's
*repeat* address mode tiles it twice each way and its *nearest* filter keeps hard texel edges. In OpenGL a
``sampler2D`` uniform holds a texture *unit*: the texture and the sampler object are bound to that unit.
Compare with ``texture_wgpu.py``, where the texture view and the sampler are two entries of a bind group.
"""

from __future__ import annotations

import moderngl
import numpy as np

from gandalf_tools import lesson

#: The texture, top row first: red, green / blue, white.
TEXELS = np.array([[[255, 0, 0, 255], [0, 255, 0, 255]], [[0, 0, 255, 255], [255, 255, 255, 255]]], np.uint8)

VERTEX_SHADER = """
#version 330 core
out vec2 v_uv;
void main() {  // a full-frame quad as a triangle strip, from the vertex index alone
    vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1) * 2.0 - 1.0;
    v_uv = vec2(corner.x + 1.0, 1.0 - corner.y);  // 0..2, v = 0 at the top
    gl_Position = vec4(corner, 0.0, 1.0);
}
"""
FRAGMENT_SHADER = """
#version 330 core
uniform sampler2D u_texture;
in vec2 v_uv;
out vec4 f_color;
void main() { f_color = texture(u_texture, v_uv); }
"""


def render(width: int = 64, height: int = 64) -> np.ndarray:
    """The tiled texture as (height, width, 4) uint8, top row first."""
    ctx = moderngl.create_standalone_context(backend="egl", require=330)
    try:
        program = ctx.program(vertex_shader=VERTEX_SHADER, fragment_shader=FRAGMENT_SHADER)
        # --8<-- [start:texture]
        texture = ctx.texture((2, 2), 4, TEXELS.tobytes())  # row 0 of the data is v = 0
        sampler = ctx.sampler(filter=(moderngl.NEAREST, moderngl.NEAREST), repeat_x=True, repeat_y=True)
        texture.use(location=0)  # texture unit 0 ...
        sampler.use(location=0)  # ... and the sampler on the same unit
        program["u_texture"] = 0  # the shader's sampler2D reads unit 0
        # --8<-- [end:texture]
        quad = ctx.vertex_array(program, [])
        return lesson.gl_frame(ctx, width, height, lambda: quad.render(moderngl.TRIANGLE_STRIP, vertices=4))
    finally:
        ctx.release()


main = lesson.command(render, __doc__, "texture_gl.png")


if __name__ == "__main__":
    raise SystemExit(main())
