"""Step 04, WebGPU variant: ``python -m step04_camera.webgpu`` (drag to orbit, scroll to zoom, C to switch).

The projection is built with WebGPU's depth range: z_ndc in [0, 1] (see ``gandalf_core.math.perspective``).
"""

from __future__ import annotations

from pathlib import Path

from gandalf_core import Application
from gandalf_core.app.cli import load_impl, run_variant

from .scene import SHADERS, build_scene

SHADER_DIR = Path(__file__).resolve().parent / "shaders"


def register_shaders(app: Application) -> None:
    """Build the step's shaders (WGSL) in the app's renderer."""
    for name in SHADERS:
        app.renderer.shaders.build(name, SHADER_DIR / f"{name}.wgsl")


def create_app(headless: bool | None = None, student: bool = False, width: int = 640, height: int = 480) -> Application:
    app = Application("webgpu", width, height, title="step04 · WebGPU", headless=headless, fixed_dt=1 / 60)
    register_shaders(app)
    app.add_scene(build_scene(load_impl(__package__, student)))
    return app


if __name__ == "__main__":
    raise SystemExit(run_variant(create_app, description=__doc__))
