"""Step 07 explode, WebGPU variant: ``python -m step07_advanced.explode.webgpu [--student]``.

WebGPU has no geometry stage: the bunny's corners, normals and indices go to storage buffers, the renderer
draws 3·F attribute-less vertices and the vertex shader pulls each triangle's corners from the buffers
(``shaders/explode_pulled.wgsl``), calling the student's ``explode_offset`` from ``exercises/explode.wgsl``.
"""

from __future__ import annotations

from types import ModuleType

from gandalf_core import Application
from gandalf_core.app.cli import load_impl, run_variant

from . import STEP
from .scene import LIT_SHADER, PullingRoute, build_scene
from .shaders import EXPLODE_MATERIAL, LIT_MATERIAL, WGSL_LIT, WGSL_PULLED, impl_shader_dir


# --8<-- [start:register]
def register_shaders(app: Application, impl: ModuleType, pulling: bool = True) -> None:
    """The vertex-pulling module with ``impl``'s ``explode.wgsl`` (and the unexploded reference ``explode_lit``)."""
    include = [impl_shader_dir(impl)]
    app.renderer.shaders.build("explode_pulled", WGSL_PULLED, include_dirs=include, material=EXPLODE_MATERIAL)
    app.renderer.shaders.build(LIT_SHADER, WGSL_LIT, include_dirs=include, material=LIT_MATERIAL)
# --8<-- [end:register]


def create_app(headless: bool | None = None, student: bool = False, width: int = 640, height: int = 480) -> Application:
    impl = load_impl(STEP, student)
    app = Application("webgpu", width, height, title="step07 explode · WebGPU", headless=headless, fixed_dt=1 / 60)
    register_shaders(app, impl)
    app.add_scene(build_scene(impl, PullingRoute(app.renderer)))
    return app


def main(argv: list[str] | None = None) -> int:
    return run_variant(create_app, argv, description=__doc__)


if __name__ == "__main__":
    raise SystemExit(main())
