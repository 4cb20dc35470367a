"""Step 03, OpenGL variant: ``python -m step03_textures.opengl``.

GLSL samples a ``sampler2D``: in OpenGL the texture object carries its own sampling state (filter, wrap,
mipmaps), set once when ``gandalf_core/render/opengl/libs.py`` builds it; the material binds it to a texture unit.
"""

from gandalf_core.app.cli import launcher

from .scene import PART

create_app, main = launcher(PART, "opengl", __doc__)


if __name__ == "__main__":
    raise SystemExit(main())
