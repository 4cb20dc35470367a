"""Step 07 showcase, WebGPU variant: ``python -m step07_advanced.showcase.webgpu [--student]``.

The render shaders and the particle kernel are WGSL; the kernel runs as a compute pipeline on the renderer's
device (``compute_wgpu.py``). The shader functions come from ``exercises/`` or ``solutions/``.
"""

from __future__ import annotations

from types import ModuleType

from gandalf_core import Application, Scene
from gandalf_core.app.cli import Backend, build_shaders, launcher

from .compute_wgpu import WGPUParticleKernel
from .scene import PART, build_scene, fountain_state
from .shaders import SHADER_DIR, SHADERS, impl_shader_dir


def register_shaders(app: Application, impl: ModuleType) -> None:
    """Build the step's WGSL modules with ``impl``'s ``brdf.wgsl`` and ``normal_map.wgsl``."""
    build_shaders(app, SHADERS, SHADER_DIR, [impl_shader_dir(impl)])


class WebGPU(Backend):
    """The WGSL modules, and the fountain's kernel on the renderer's device."""

    api = "webgpu"

    def scene(self, app: Application, impl: ModuleType) -> Scene:
        register_shaders(app, impl)
        return build_scene(impl, WGPUParticleKernel(app.renderer.device, impl, fountain_state()))


create_app, main = launcher(PART, WebGPU(), __doc__)


if __name__ == "__main__":
    raise SystemExit(main())
