"""Step 07 showcase, WebGPU variant: ``python -m step07_advanced.showcase.webgpu [--student]``.

The render shaders and the particle kernel are WGSL; the kernel runs as a compute pipeline on the renderer's
device (``compute_wgpu.py``). The shader functions come from ``exercises/`` or ``solutions/``.
"""

from __future__ import annotations

from types import ModuleType

from gandalf_core import Application
from gandalf_core.app.cli import build_shaders, load_impl, run_variant

from . import STEP
from .compute_wgpu import WGPUParticleKernel
from .scene import build_scene, fountain_state
from .shaders import SHADER_DIR, SHADERS, impl_shader_dir


def register_shaders(app: Application, impl: ModuleType) -> None:
    """Build the step's WGSL modules with ``impl``'s ``brdf.wgsl`` and ``normal_map.wgsl``."""
    build_shaders(app, SHADERS, SHADER_DIR, [impl_shader_dir(impl)])


def create_app(headless: bool | None = None, student: bool = False, width: int = 640, height: int = 480) -> Application:
    impl = load_impl(STEP, student)
    app = Application("webgpu", width, height, title="step07 · WebGPU", headless=headless, fixed_dt=1 / 60)
    register_shaders(app, impl)
    app.add_scene(build_scene(impl, WGPUParticleKernel(app.renderer.device, impl, fountain_state())))
    return app


def main(argv: list[str] | None = None) -> int:
    return run_variant(create_app, argv, description=__doc__)


if __name__ == "__main__":
    raise SystemExit(main())
