"""Step 07 parallax, WebGPU variant: ``python -m step07_advanced.parallax.webgpu [--student]``.

The same four tiles and the same fragment-stage technique as OpenGL (parallax mapping needs no stage WebGPU
lacks), calling the student's functions from ``exercises/parallax.wgsl`` (``--student``) or ``solutions/``.
"""

from __future__ import annotations

from types import ModuleType

from gandalf_core import Application
from gandalf_core.app.cli import load_impl, run_variant

from . import STEP
from .scene import build_scene
from .shaders import MATERIAL, SHADER, WGSL, include_dirs


# --8<-- [start:register]
def register_shaders(app: Application, impl: ModuleType) -> None:
    """The parallax module (the showcase's vertex stage, this technique's fragment stage) with ``impl``'s
    ``parallax.wgsl``."""
    app.renderer.shaders.build(SHADER, WGSL, include_dirs=include_dirs(impl), material=MATERIAL)
# --8<-- [end:register]


def create_app(headless: bool | None = None, student: bool = False, width: int = 640, height: int = 480) -> Application:
    impl = load_impl(STEP, student)
    app = Application("webgpu", width, height, title="step07 parallax · WebGPU", headless=headless, fixed_dt=1 / 60)
    register_shaders(app, impl)
    app.add_scene(build_scene(impl))
    return app


def main(argv: list[str] | None = None) -> int:
    return run_variant(create_app, argv, description=__doc__)


if __name__ == "__main__":
    raise SystemExit(main())
