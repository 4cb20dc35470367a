"""Step 07 PBR model, WebGPU variant: ``python -m step07_advanced.pbr_model.webgpu [--student]``.

The same scene with one WGSL module (``shaders/pbr_model.wgsl``): the model's five glTF maps and the three
IBL textures are bindings 1-16 of the material's bind group, and the student's ``brdf.wgsl`` functions come
from ``exercises/`` (``--student``) or ``solutions/``.
"""

from __future__ import annotations

from types import ModuleType

from gandalf_core import Application
from gandalf_core.app.cli import load_impl, run_variant

from . import STEP
from .scene import build_scene
from .shaders import MATERIAL, SHADER_NAME, WGSL, include_dirs


# --8<-- [start:register]
def register_shaders(app: Application, impl: ModuleType) -> None:
    """Build the model's WGSL module with ``impl``'s ``brdf.wgsl`` and ``normal_map.wgsl``."""
    app.renderer.shaders.build(SHADER_NAME, WGSL, include_dirs=include_dirs(impl), material=MATERIAL)
# --8<-- [end:register]


def create_app(headless: bool | None = None, student: bool = False, width: int = 640, height: int = 480) -> Application:
    impl = load_impl(STEP, student)
    app = Application("webgpu", width, height, title="step07 PBR model · WebGPU", headless=headless, fixed_dt=1 / 60)
    register_shaders(app, impl)
    app.add_scene(build_scene(impl))
    return app


def main(argv: list[str] | None = None) -> int:
    return run_variant(create_app, argv, description=__doc__)


if __name__ == "__main__":
    raise SystemExit(main())
