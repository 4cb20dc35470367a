"""Step 02, OpenGL variant: ``python -m step02_triangle.opengl``.

The renderer compiles the GLSL vertex and fragment shaders into one program, asks it which vertex inputs
it reads (locations 0 and 4), and binds the mesh's interleaved buffer to them with a vertex array object.
"""

from __future__ import annotations

from pathlib import Path

from gandalf_core import Application
from gandalf_core.app.cli import load_impl, run_variant

from .scene import SHADER, build_scene

SHADERS = Path(__file__).resolve().parent / "shaders"


def register_shaders(app: Application) -> None:
    """Build the step's GLSL shader in the app's renderer (under the name the scene's material uses)."""
    app.renderer.shaders.build(SHADER, SHADERS / "vertex_color.vert", SHADERS / "vertex_color.frag")


def create_app(headless: bool | None = None, student: bool = False, width: int = 640, height: int = 480) -> Application:
    app = Application("opengl", width, height, title="step02 · OpenGL", headless=headless, fixed_dt=1 / 60)
    register_shaders(app)
    app.add_scene(build_scene(load_impl(__package__, student)))
    return app


if __name__ == "__main__":
    raise SystemExit(run_variant(create_app, description=__doc__))
