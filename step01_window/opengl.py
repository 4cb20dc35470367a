"""Step 01, OpenGL variant: ``python -m step01_window.opengl``.

The OpenGL renderer clears an sRGB framebuffer (``GL_SRGB8_ALPHA8`` with ``GL_FRAMEBUFFER_SRGB`` on)
to the scene's clear colour; compare ``gandalf_core/render/opengl/renderer.py``.
"""

from __future__ import annotations

from gandalf_core import Application
from gandalf_core.app.cli import load_impl, run_variant

from .scene import build_scene


def create_app(headless: bool | None = None, student: bool = False, width: int = 640, height: int = 480) -> Application:
    app = Application("opengl", width, height, title="step01 · OpenGL", headless=headless, fixed_dt=1 / 60)
    app.add_scene(build_scene(load_impl(__package__, student)))
    return app


if __name__ == "__main__":
    raise SystemExit(run_variant(create_app, description=__doc__))
