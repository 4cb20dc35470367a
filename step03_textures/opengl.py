"""Step 03, OpenGL variant: ``python -m step03_textures.opengl``.

GLSL samples a ``sampler2D``: in OpenGL the texture object carries its own sampling state (filter, wrap,
mipmaps), set once when ``gandalf_core/render/opengl/libs.py`` builds it; the material binds it to a texture unit.
"""

from __future__ import annotations

from pathlib import Path

from gandalf_core import Application
from gandalf_core.app.cli import load_impl, run_variant

from .scene import SHADER, build_scene

SHADERS = Path(__file__).resolve().parent / "shaders"


def create_app(headless: bool | None = None, student: bool = False, width: int = 640, height: int = 480) -> Application:
    app = Application("opengl", width, height, title="step03 · OpenGL", headless=headless, fixed_dt=1 / 60)
    app.renderer.shaders.build(SHADER, SHADERS / "textured.vert", SHADERS / "textured.frag")
    app.add_scene(build_scene(load_impl(__package__, student)))
    return app


if __name__ == "__main__":
    raise SystemExit(run_variant(create_app, description=__doc__))
