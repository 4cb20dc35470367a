"""Step 04's API lesson in plain moderngl: per-draw uniforms, a perspective camera and OpenGL's depth range.

One triangle is drawn twice, red at z = −2 and green behind it at z = −3, each with its own model-view-
projection matrix and colour. OpenGL keeps uniform values *in the program*: set them, draw, set them again,
draw again. Its clip space keeps depth in [−1, 1], so the projection maps the near plane to −1; a depth buffer
and ``DEPTH_TEST`` keep the red triangle in front though it is drawn first.
Compare with ``uniforms_wgpu.py``: a uniform buffer and a bind group per draw, and depth in [0, 1].
"""

from __future__ import annotations

import moderngl
import numpy as np

from gandalf_tools import lesson

TRIANGLE = np.array([[-0.8, -0.8, 0.0], [0.8, -0.8, 0.0], [0.0, 0.8, 0.0]])
#: (translation, colour) per draw: red in front, drawn first.
DRAWS = [((-0.25, 0.0, -2.0), (1.0, 0.0, 0.0, 1.0)), ((0.25, 0.0, -3.0), (0.0, 1.0, 0.0, 1.0))]
NEAR, FAR, FOV_Y = 1.5, 4.0, np.radians(60.0)

VERTEX_SHADER = """
#version 330 core
uniform mat4 u_mvp;
in vec3 a_position;
void main() { gl_Position = u_mvp * vec4(a_position, 1.0); }
"""
FRAGMENT_SHADER = """
#version 330 core
uniform vec4 u_color;
out vec4 f_color;
void main() { f_color = u_color; }
"""


# --8<-- [start:projection]
def perspective(aspect: float) -> np.ndarray:
    """OpenGL's perspective: z_ndc = -1 at the near plane, +1 at the far plane."""
    f = 1.0 / np.tan(FOV_Y / 2)
    return np.array([[f / aspect, 0, 0, 0], [0, f, 0, 0],
                     [0, 0, (FAR + NEAR) / (NEAR - FAR), 2 * FAR * NEAR / (NEAR - FAR)], [0, 0, -1, 0]])
# --8<-- [end:projection]


def render(width: int = 64, height: int = 64) -> np.ndarray:
    """Both triangles as (height, width, 4) uint8, top row first."""
    ctx = moderngl.create_standalone_context(backend="egl", require=330)
    try:
        program = ctx.program(vertex_shader=VERTEX_SHADER, fragment_shader=FRAGMENT_SHADER)
        vao = ctx.vertex_array(program, [(ctx.buffer(TRIANGLE.astype("f4").tobytes()), "3f", "a_position")])
        ctx.enable(moderngl.DEPTH_TEST)

        def draw() -> None:
            # --8<-- [start:draws]
            for translation, color in DRAWS:
                model = np.eye(4)
                model[:3, 3] = translation
                mvp = perspective(width / height) @ model  # float64 on the CPU
                program["u_mvp"].write(mvp.T.astype("f4").tobytes())  # column-major, like GLSL's mat4
                program["u_color"].value = color
                vao.render(moderngl.TRIANGLES)  # uses the values set just now
            # --8<-- [end:draws]

        return lesson.gl_frame(ctx, width, height, draw, depth=True)
    finally:
        ctx.release()


main = lesson.command(render, __doc__, "uniforms_gl.png")


if __name__ == "__main__":
    raise SystemExit(main())
