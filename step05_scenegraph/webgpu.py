"""Step 05, WebGPU variant: ``python -m step05_scenegraph.webgpu`` (keys 1/2/3 or TAB switch scenes).

The scenes are the same for both APIs; only the shaders differ: WGSL (``shaders/*.wgsl``).
"""

from __future__ import annotations

from pathlib import Path

from gandalf_core import Application
from gandalf_core.app.cli import load_impl, run_variant

from .scene import SHADERS, build_scenes

SHADER_DIR = Path(__file__).resolve().parent / "shaders"


def create_app(headless: bool | None = None, student: bool = False, width: int = 640, height: int = 480) -> Application:
    app = Application("webgpu", width, height, title="step05 · WebGPU", headless=headless, fixed_dt=1 / 60)
    for name in SHADERS:
        app.renderer.shaders.build(name, SHADER_DIR / f"{name}.wgsl")
    for scene in build_scenes(load_impl(__package__, student)):
        app.add_scene(scene)
    return app


if __name__ == "__main__":
    raise SystemExit(run_variant(create_app, description=__doc__))
