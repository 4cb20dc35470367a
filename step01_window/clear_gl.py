"""Step 01's API lesson in plain moderngl: clear a frame to one colour and read it back.

OpenGL keeps a *current* context and a *bound* framebuffer: ``fbo.use()`` makes it the draw target, ``clear``
acts at once on whatever is bound, and ``read`` waits for the GPU and copies the pixels. On a window the
"present" step is ``glfwSwapBuffers``; headless (EGL) we read the offscreen colour texture instead.
Compare with ``clear_wgpu.py``: the picture is the same, the route is not.
"""

from __future__ import annotations

import moderngl
import numpy as np

from gandalf_tools import lesson

#: The clear colour, linear RGBA; 0.2, 0.4 and 0.8 are exact multiples of 1/255 (51, 102, 204).
COLOR = (0.2, 0.4, 0.8, 1.0)


def render(width: int = 64, height: int = 48, color: tuple = COLOR) -> np.ndarray:
    """One cleared frame as (height, width, 4) uint8, top row first."""
    # --8<-- [start:frame]
    ctx = moderngl.create_standalone_context(backend="egl", require=330)  # no window: EGL
    try:
        target = ctx.texture((width, height), 4)  # RGBA8, the "back buffer"
        fbo = ctx.framebuffer(color_attachments=[target])
        fbo.use()  # global state: later calls act on it
        ctx.clear(*color)  # runs now
        pixels = fbo.read(components=4)  # waits for the GPU
    finally:
        ctx.release()
    # --8<-- [end:frame]
    return lesson.image(pixels, width, height, bottom_up=True)  # OpenGL's rows start at the bottom


main = lesson.command(render, __doc__, "clear_gl.png")


if __name__ == "__main__":
    raise SystemExit(main())
