"""Step 07 image filter, OpenGL variant: ``python -m step07_advanced.filter.opengl [--student]``.

The filters are GLSL 4.30 compute shaders run once at start-up in the renderer's own moderngl context
(``compute_gl.py``); the four panels are drawn by the core's ready unlit material (gandalf.unlit). Where the renderer's
context is older than 4.3 (NVIDIA's EGL gives exactly the 3.3 the renderer asks for), the filters run on a
headless 4.3 context of their own: their results come back to the CPU as textures either way.
"""

from __future__ import annotations

from gandalf_core import Application
from gandalf_core.app.cli import load_impl, run_variant

from . import STEP
from .compute_gl import REQUIRED_VERSION, GLImageFilter
from .scene import build_scene, panel_images


def create_app(headless: bool | None = None, student: bool = False, width: int = 640, height: int = 480) -> Application:
    impl = load_impl(STEP, student)
    app = Application("opengl", width, height, title="step07 filter · OpenGL", headless=headless, fixed_dt=1 / 60)
    ctx = app.renderer.ctx
    if ctx.version_code >= REQUIRED_VERSION:
        image_filter = GLImageFilter(ctx, impl)
    else:
        image_filter = GLImageFilter.standalone(impl)
    try:
        images = panel_images(image_filter)
    finally:
        image_filter.release()
    ctx.__enter__()  # the renderer's context current again (a standalone one may have been made current)
    app.add_scene(build_scene(images))
    return app


def main(argv: list[str] | None = None) -> int:
    return run_variant(create_app, argv, description=__doc__)


if __name__ == "__main__":
    raise SystemExit(main())
