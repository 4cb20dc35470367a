"""Step 03, WebGPU variant: ``python -m step03_textures.webgpu``.

WGSL declares a ``texture_2d<f32>`` and a separate ``sampler``: WebGPU splits the image (texture + view) from
how it is read (a sampler object with filter, address and mipmap modes); ``gandalf_core/render/webgpu/libs.py``
creates both and puts them in the material's bind group.
"""

from __future__ import annotations

from pathlib import Path

from gandalf_core import Application
from gandalf_core.app.cli import load_impl, run_variant

from .scene import SHADER, build_scene

SHADERS = Path(__file__).resolve().parent / "shaders"


def create_app(headless: bool | None = None, student: bool = False, width: int = 640, height: int = 480) -> Application:
    app = Application("webgpu", width, height, title="step03 · WebGPU", headless=headless, fixed_dt=1 / 60)
    app.renderer.shaders.build(SHADER, SHADERS / "textured.wgsl")
    app.add_scene(build_scene(load_impl(__package__, student)))
    return app


if __name__ == "__main__":
    raise SystemExit(run_variant(create_app, description=__doc__))
