"""Step 03, OpenGL variant: ``python -m step03_textures.opengl``.

GLSL samples a ``sampler2D``: in OpenGL the texture object carries its own sampling state (filter, wrap,
mipmaps), set once when ``gandalf_core/render/opengl/libs.py`` builds it; the material binds it to a texture unit.
"""

from __future__ import annotations

from pathlib import Path

from gandalf_core.app.cli import run_variant, variant

from .scene import SHADERS as SHADER_TABLE
from .scene import build_scene

#: The shader folder (``tests/step03_textures/conftest.py`` reads it).
SHADERS = Path(__file__).resolve().parent / "shaders"

create_app = variant("opengl", __package__, build_scene, SHADER_TABLE)


if __name__ == "__main__":
    raise SystemExit(run_variant(create_app, description=__doc__))
