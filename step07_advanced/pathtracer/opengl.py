"""Step 07 path tracer, OpenGL variant: ``python -m step07_advanced.pathtracer.opengl [--student]``.

A GLSL 4.30 compute shader (``shaders/pathtrace.comp``) on the renderer's own context adds one sample per pixel
per frame to a storage buffer; a full-screen material (``display.vert`` / ``display.frag``) shows the mean.
"""

from __future__ import annotations

from types import ModuleType

from gandalf_core import Application, Scene
from gandalf_core.app.cli import Backend, launcher

from .compute_gl import GLPathTracer
from .scene import ACCUM_BUFFER, PART, build_scene
from .shaders import DISPLAY_MATERIAL, DISPLAY_SHADER, SHADER_DIR


# --8<-- [start:setup]
def create_tracer(app: Application, impl: ModuleType) -> GLPathTracer:
    """The display shader, the accumulation buffer (renderer.buffers) and the kernel writing it (with ``impl``'s
    shader functions)."""
    width, height = app.renderer.width, app.renderer.height
    accum = app.renderer.buffers.build(ACCUM_BUFFER, width * height * 16)  # vec4 per pixel, zeros
    tracer = GLPathTracer(app.renderer.ctx, impl, accum, width, height)  # first: it names a GL < 4.3 context
    app.renderer.shaders.build(DISPLAY_SHADER, SHADER_DIR / "display.vert", SHADER_DIR / "display.frag",
                               material=DISPLAY_MATERIAL)
    return tracer
# --8<-- [end:setup]


class OpenGL(Backend):
    """The scene traced by the GLSL kernel."""

    api = "opengl"

    def scene(self, app: Application, impl: ModuleType) -> Scene:
        return build_scene(create_tracer(app, impl))


create_app, main = launcher(PART, OpenGL(), __doc__)


if __name__ == "__main__":
    raise SystemExit(main())
