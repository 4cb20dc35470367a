"""Step 07 path tracer, WebGPU variant: ``python -m step07_advanced.pathtracer.webgpu [--student]``.

A WGSL compute pipeline (``shaders/pathtrace.wgsl``) on the renderer's own device adds one sample per pixel per
frame to a storage buffer; a full-screen material (``display.wgsl``) shows the mean.
"""

from __future__ import annotations

from types import ModuleType

from gandalf_core import Application, Scene
from gandalf_core.app.cli import Backend, launcher

from .compute_wgpu import WGPUPathTracer
from .scene import ACCUM_BUFFER, PART, build_scene
from .shaders import DISPLAY_MATERIAL, DISPLAY_SHADER, SHADER_DIR


# --8<-- [start:setup]
def create_tracer(app: Application, impl: ModuleType) -> WGPUPathTracer:
    """The display shader, the accumulation buffer (renderer.buffers) and the kernel writing it (with ``impl``'s
    shader functions)."""
    app.renderer.shaders.build(DISPLAY_SHADER, SHADER_DIR / "display.wgsl", material=DISPLAY_MATERIAL)
    width, height = app.renderer.width, app.renderer.height
    accum = app.renderer.buffers.build(ACCUM_BUFFER, width * height * 16)  # vec4 per pixel, zeros
    return WGPUPathTracer(app.renderer.device, impl, accum, width, height)
# --8<-- [end:setup]


class WebGPU(Backend):
    """The scene traced by the WGSL kernel."""

    api = "webgpu"

    def scene(self, app: Application, impl: ModuleType) -> Scene:
        return build_scene(create_tracer(app, impl))


create_app, main = launcher(PART, WebGPU(), __doc__)


if __name__ == "__main__":
    raise SystemExit(main())
