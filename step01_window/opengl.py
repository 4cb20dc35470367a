"""Step 01, OpenGL variant: ``python -m step01_window.opengl``.

The OpenGL renderer clears an sRGB framebuffer (``GL_SRGB8_ALPHA8`` with ``GL_FRAMEBUFFER_SRGB`` on)
to the scene's clear colour; compare ``gandalf_core/render/opengl/renderer.py``.
"""

from gandalf_core.app.cli import launcher

from .scene import PART

create_app, main = launcher(PART, "opengl", __doc__)


if __name__ == "__main__":
    raise SystemExit(main())
