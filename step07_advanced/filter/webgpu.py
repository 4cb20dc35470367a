"""Step 07 image filter, WebGPU variant: ``python -m step07_advanced.filter.webgpu [--student]``.

The filters are WGSL compute pipelines over storage textures run once at start-up on the renderer's own device
(``compute_wgpu.py``); the four panels are drawn by the core's ready unlit material (gandalf.unlit).
"""

from __future__ import annotations

from types import ModuleType

from gandalf_core import Application, Scene
from gandalf_core.app.cli import Backend, launcher

from .compute_wgpu import WGPUImageFilter
from .scene import PART, build_scene, panel_images


class WebGPU(Backend):
    """The panels filtered by WGSL compute pipelines before the first frame."""

    api = "webgpu"

    def scene(self, app: Application, impl: ModuleType) -> Scene:
        image_filter = WGPUImageFilter(app.renderer.device, impl)
        try:
            images = panel_images(image_filter)
        finally:
            image_filter.release()
        return build_scene(images)


create_app, main = launcher(PART, WebGPU(), __doc__)


if __name__ == "__main__":
    raise SystemExit(main())
