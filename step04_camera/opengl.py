"""Step 04, OpenGL variant: ``python -m step04_camera.opengl`` (drag to orbit, scroll to zoom, C to switch).

The projection is built with OpenGL's depth range: z_ndc in [-1, 1] (see ``gandalf_core.math.perspective``).
"""

from __future__ import annotations

from pathlib import Path

from gandalf_core import Application
from gandalf_core.app.cli import load_impl, run_variant

from .scene import SHADERS, build_scene

SHADER_DIR = Path(__file__).resolve().parent / "shaders"


def register_shaders(app: Application) -> None:
    """Build the step's shaders (GLSL) in the app's renderer."""
    for name in SHADERS:
        app.renderer.shaders.build(name, SHADER_DIR / f"{name}.vert", SHADER_DIR / f"{name}.frag")


def create_app(headless: bool | None = None, student: bool = False, width: int = 640, height: int = 480) -> Application:
    app = Application("opengl", width, height, title="step04 · OpenGL", headless=headless, fixed_dt=1 / 60)
    register_shaders(app)
    app.add_scene(build_scene(load_impl(__package__, student)))
    return app


if __name__ == "__main__":
    raise SystemExit(run_variant(create_app, description=__doc__))
