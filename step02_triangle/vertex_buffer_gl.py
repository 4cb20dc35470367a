"""Step 02's API lesson in plain moderngl: one interleaved vertex buffer, its layout, one draw.

The buffer holds, per vertex, a 2D position and an RGB colour (5 float32, a stride of 20 bytes). moderngl
describes that layout with a format string (``"2f 3f"``) and binds each part to a shader input by its
*name*; the draw reads the vertex array object (VAO) that ties the buffer, the layout and the program.
Compare with ``vertex_buffer_wgpu.py``, where the same layout is a stride, and per attribute a format, a byte
offset and a shader *location*, fixed in the pipeline.
"""

from __future__ import annotations

import moderngl
import numpy as np

from gandalf_tools import lesson

#: x, y, r, g, b per vertex, counter-clockwise.
VERTICES = np.array([
    [-0.8, -0.8, 1.0, 0.0, 0.0],
    [0.8, -0.8, 0.0, 1.0, 0.0],
    [0.0, 0.8, 0.0, 0.0, 1.0],
], dtype=np.float64)

VERTEX_SHADER = """
#version 330 core
in vec2 a_position;
in vec3 a_color;
out vec3 v_color;
void main() { v_color = a_color; gl_Position = vec4(a_position, 0.0, 1.0); }
"""
FRAGMENT_SHADER = """
#version 330 core
in vec3 v_color;
out vec4 f_color;
void main() { f_color = vec4(v_color, 1.0); }
"""


def render(width: int = 64, height: int = 64) -> np.ndarray:
    """The triangle on black as (height, width, 4) uint8, top row first."""
    ctx = moderngl.create_standalone_context(backend="egl", require=330)
    try:
        program = ctx.program(vertex_shader=VERTEX_SHADER, fragment_shader=FRAGMENT_SHADER)
        # --8<-- [start:buffer]
        buffer = ctx.buffer(VERTICES.astype(np.float32).tobytes())  # float64 on the CPU, float32 uploaded
        vao = ctx.vertex_array(program, [(buffer, "2f 3f", "a_position", "a_color")])  # layout + names
        # --8<-- [end:buffer]
        fbo = ctx.framebuffer(color_attachments=[ctx.texture((width, height), 4)])
        fbo.use()
        ctx.clear(0.0, 0.0, 0.0, 1.0)
        # --8<-- [start:draw]
        vao.render(moderngl.TRIANGLES, vertices=3)
        # --8<-- [end:draw]
        pixels = fbo.read(components=4)
    finally:
        ctx.release()
    return lesson.image(pixels, width, height, bottom_up=True)


main = lesson.command(render, __doc__, "vertex_buffer_gl.png")


if __name__ == "__main__":
    raise SystemExit(main())
