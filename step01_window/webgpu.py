"""Step 01, WebGPU variant: ``python -m step01_window.webgpu``.

The WebGPU renderer begins a render pass on an ``rgba8unorm-srgb`` texture with ``load_op="clear"`` and
the scene's clear colour; compare ``gandalf_core/render/webgpu/renderer.py``.
"""

from __future__ import annotations

from gandalf_core import Application
from gandalf_core.app.cli import load_impl, run_variant

from .scene import build_scene


def create_app(headless: bool | None = None, student: bool = False, width: int = 640, height: int = 480) -> Application:
    app = Application("webgpu", width, height, title="step01 · WebGPU", headless=headless, fixed_dt=1 / 60)
    app.add_scene(build_scene(load_impl(__package__, student)))
    return app


if __name__ == "__main__":
    raise SystemExit(run_variant(create_app, description=__doc__))
