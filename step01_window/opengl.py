"""Step 01, OpenGL variant: ``python -m step01_window.opengl``.

The OpenGL renderer clears an sRGB framebuffer (``GL_SRGB8_ALPHA8`` with ``GL_FRAMEBUFFER_SRGB`` on)
to the scene's clear colour; compare ``gandalf_core/render/opengl/renderer.py``.
"""

from __future__ import annotations

from gandalf_core.app.cli import run_variant, variant

from .scene import build_scene

create_app = variant("opengl", __package__, build_scene)


if __name__ == "__main__":
    raise SystemExit(run_variant(create_app, description=__doc__))
