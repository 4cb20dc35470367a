"""Step 07 image filter, OpenGL variant: ``python -m step07_advanced.filter.opengl [--student]``.

The filters are GLSL 4.30 compute shaders run once at start-up in the renderer's own moderngl context
(``compute_gl.py``); the four panels are drawn by the core's ready unlit material (gandalf.unlit). Where the renderer's
context is older than 4.3 (NVIDIA's EGL gives exactly the 3.3 the renderer asks for), the filters run on a
headless 4.3 context of their own: their results come back to the CPU as textures either way.
"""

from __future__ import annotations

from types import ModuleType

from gandalf_core import Application, Scene
from gandalf_core.app.cli import Backend, launcher

from .compute_gl import REQUIRED_VERSION, GLImageFilter
from .scene import PART, build_scene, panel_images


class OpenGL(Backend):
    """The panels filtered by GLSL compute shaders before the first frame."""

    api = "opengl"

    def scene(self, app: Application, impl: ModuleType) -> Scene:
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
        return build_scene(images)


create_app, main = launcher(PART, OpenGL(), __doc__)


if __name__ == "__main__":
    raise SystemExit(main())
