"""Step 02, WebGPU variant: ``python -m step02_triangle.webgpu``.

The renderer compiles one WGSL module holding both entry points, reflects which vertex inputs it reads
(locations 0 and 4), and describes the mesh's interleaved buffer to a render pipeline (stride, formats,
offsets, shader locations).
"""

from __future__ import annotations

from pathlib import Path

from gandalf_core import Application
from gandalf_core.app.cli import load_impl, run_variant

from .scene import SHADER, build_scene

SHADERS = Path(__file__).resolve().parent / "shaders"


def register_shaders(app: Application) -> None:
    """Build the step's WGSL shader in the app's renderer (under the name the scene's material uses)."""
    app.renderer.shaders.build(SHADER, SHADERS / "vertex_color.wgsl")


def create_app(headless: bool | None = None, student: bool = False, width: int = 640, height: int = 480) -> Application:
    app = Application("webgpu", width, height, title="step02 · WebGPU", headless=headless, fixed_dt=1 / 60)
    register_shaders(app)
    app.add_scene(build_scene(load_impl(__package__, student)))
    return app


if __name__ == "__main__":
    raise SystemExit(run_variant(create_app, description=__doc__))
