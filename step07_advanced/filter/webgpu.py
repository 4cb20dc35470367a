"""Step 07 image filter, WebGPU variant: ``python -m step07_advanced.filter.webgpu [--student]``.

The filters are WGSL compute pipelines over storage textures run once at start-up on the renderer's own device
(``compute_wgpu.py``); the four panels are drawn by the core's ready unlit material (gandalf.unlit).
"""

from __future__ import annotations

from gandalf_core import Application
from gandalf_core.app.cli import load_impl, run_variant

from . import STEP
from .compute_wgpu import WGPUImageFilter
from .scene import build_scene, panel_images


def create_app(headless: bool | None = None, student: bool = False, width: int = 640, height: int = 480) -> Application:
    impl = load_impl(STEP, student)
    app = Application("webgpu", width, height, title="step07 filter · WebGPU", headless=headless, fixed_dt=1 / 60)
    image_filter = WGPUImageFilter(app.renderer.device, impl)
    try:
        images = panel_images(image_filter)
    finally:
        image_filter.release()
    app.add_scene(build_scene(images))
    return app


def main(argv: list[str] | None = None) -> int:
    return run_variant(create_app, argv, description=__doc__)


if __name__ == "__main__":
    raise SystemExit(main())
