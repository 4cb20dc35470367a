"""Step 07 parallax, WebGPU variant: ``python -m step07_advanced.parallax.webgpu [--student]``.

The same four tiles and the same fragment-stage technique as OpenGL (parallax mapping needs no stage WebGPU
lacks), calling the student's functions from ``exercises/parallax.wgsl`` (``--student``) or ``solutions/``.
"""

from __future__ import annotations

from types import ModuleType

from gandalf_core import Application
from gandalf_core.app.cli import launcher

from .scene import PART
from .shaders import MATERIAL, SHADER, WGSL, include_dirs


# --8<-- [start:register]
def register_shaders(app: Application, impl: ModuleType) -> None:
    """The parallax module (the showcase's vertex stage, this technique's fragment stage) with ``impl``'s
    ``parallax.wgsl``."""
    app.renderer.shaders.build(SHADER, WGSL, include_dirs=include_dirs(impl), material=MATERIAL)
# --8<-- [end:register]


create_app, main = launcher(PART, "webgpu", __doc__, shaders=register_shaders)


if __name__ == "__main__":
    raise SystemExit(main())
