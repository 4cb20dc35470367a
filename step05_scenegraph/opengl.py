"""Step 05, OpenGL variant: ``python -m step05_scenegraph.opengl`` (keys 1/2/3 or TAB switch scenes).

The scenes are the same for both APIs; only the shaders differ: GLSL 330 (``shaders/*.vert``/``*.frag``).
"""

from __future__ import annotations

from pathlib import Path

from gandalf_core import Application
from gandalf_core.app.cli import load_impl, run_variant

from .scene import SHADERS, build_scenes

SHADER_DIR = Path(__file__).resolve().parent / "shaders"


def create_app(headless: bool | None = None, student: bool = False, width: int = 640, height: int = 480) -> Application:
    app = Application("opengl", width, height, title="step05 · OpenGL", headless=headless, fixed_dt=1 / 60)
    for name in SHADERS:
        app.renderer.shaders.build(name, SHADER_DIR / f"{name}.vert", SHADER_DIR / f"{name}.frag")
    for scene in build_scenes(load_impl(__package__, student)):
        app.add_scene(scene)
    return app


if __name__ == "__main__":
    raise SystemExit(run_variant(create_app, description=__doc__))
