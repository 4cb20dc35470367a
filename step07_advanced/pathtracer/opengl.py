"""Step 07 path tracer, OpenGL variant: ``python -m step07_advanced.pathtracer.opengl [--student]``.

A GLSL 4.30 compute shader (``shaders/pathtrace.comp``) on the renderer's own context adds one sample per pixel
per frame to a storage buffer; a full-screen material (``display.vert`` / ``display.frag``) shows the mean.
"""

from __future__ import annotations

from gandalf_core import Application
from gandalf_core.app.cli import load_impl, run_variant

from . import STEP
from .compute_gl import GLPathTracer
from .scene import ACCUM_BUFFER, build_scene
from .shaders import DISPLAY_MATERIAL, DISPLAY_SHADER, SHADER_DIR


# --8<-- [start:setup]
def create_tracer(app: Application, student: bool = False) -> GLPathTracer:
    """The display shader, the accumulation buffer (renderer.buffers) and the kernel writing it."""
    impl = load_impl(STEP, student)
    width, height = app.renderer.width, app.renderer.height
    accum = app.renderer.buffers.build(ACCUM_BUFFER, width * height * 16)  # vec4 per pixel, zeros
    tracer = GLPathTracer(app.renderer.ctx, impl, accum, width, height)  # first: it names a GL < 4.3 context
    app.renderer.shaders.build(DISPLAY_SHADER, SHADER_DIR / "display.vert", SHADER_DIR / "display.frag",
                               material=DISPLAY_MATERIAL)
    return tracer
# --8<-- [end:setup]


def create_app(headless: bool | None = None, student: bool = False, width: int = 640, height: int = 480) -> Application:
    app = Application("opengl", width, height, title="step07 path tracer · OpenGL", headless=headless,
                      fixed_dt=1 / 60)
    app.add_scene(build_scene(create_tracer(app, student)))
    return app


def main(argv: list[str] | None = None) -> int:
    return run_variant(create_app, argv, description=__doc__)


if __name__ == "__main__":
    raise SystemExit(main())
