"""Step 07 PBR model, OpenGL variant: ``python -m step07_advanced.pbr_model.opengl [--student]``.

The fragment shader (``shaders/pbr_model.frag``, GLSL 3.30) samples the model's five glTF maps and the three
IBL textures, calling the student's ``brdf.glsl`` functions from ``exercises/`` (``--student``) or
``solutions/``. The prefiltered environment's mip levels are written one by one (glTexSubImage2D).
"""

from __future__ import annotations

from types import ModuleType

from gandalf_core import Application
from gandalf_core.app.cli import load_impl, run_variant

from . import STEP
from .scene import build_scene
from .shaders import GL_FRAGMENT, GL_VERTEX, MATERIAL, SHADER_NAME, include_dirs

#: glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS): filter across cube faces, as WebGPU always does.
GL_TEXTURE_CUBE_MAP_SEAMLESS = 0x884F


# --8<-- [start:register]
def register_shaders(app: Application, impl: ModuleType) -> None:
    """Build the model's GLSL program with ``impl``'s ``brdf.glsl`` and ``normal_map.glsl``."""
    app.renderer.shaders.build(SHADER_NAME, GL_VERTEX, GL_FRAGMENT, include_dirs=include_dirs(impl),
                               material=MATERIAL)
    # The small prefiltered levels would show their face edges without seamless filtering.
    app.renderer.ctx.enable_direct(GL_TEXTURE_CUBE_MAP_SEAMLESS)
# --8<-- [end:register]


def create_app(headless: bool | None = None, student: bool = False, width: int = 640, height: int = 480) -> Application:
    impl = load_impl(STEP, student)
    app = Application("opengl", width, height, title="step07 PBR model · OpenGL", headless=headless, fixed_dt=1 / 60)
    register_shaders(app, impl)
    app.add_scene(build_scene(impl))
    return app


def main(argv: list[str] | None = None) -> int:
    return run_variant(create_app, argv, description=__doc__)


if __name__ == "__main__":
    raise SystemExit(main())
