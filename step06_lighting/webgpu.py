"""Step 06, WebGPU variant: ``python -m step06_lighting.webgpu [--student]``.

WGSL: the lights arrive in ``lights`` at @group(0) @binding(1) (``frame.wgsl``), the cube map as a
``texture_cube<f32>`` plus its sampler in @group(1); the shading functions come from ``shading.wgsl`` of
``exercises/`` or ``solutions/``.
"""

from __future__ import annotations

from types import ModuleType

from gandalf_core import Application
from gandalf_core.app.cli import load_impl, run_variant

from .scene import build_scene
from .shaders import SHADER_DIR, SHADERS, impl_shader_dir


def register_shaders(app: Application, impl: ModuleType) -> None:
    """Build the step's WGSL modules, including ``impl``'s ``shading.wgsl``."""
    for name in SHADERS:
        app.renderer.shaders.build(name, SHADER_DIR / f"{name}.wgsl", include_dirs=[impl_shader_dir(impl)])


def create_app(headless: bool | None = None, student: bool = False, width: int = 640, height: int = 480) -> Application:
    impl = load_impl(__package__, student)
    app = Application("webgpu", width, height, title="step06 · WebGPU", headless=headless, fixed_dt=1 / 60)
    register_shaders(app, impl)
    app.add_scene(build_scene(impl))
    return app


if __name__ == "__main__":
    raise SystemExit(run_variant(create_app, description=__doc__))
