"""Step 07 showcase, OpenGL variant: ``python -m step07_advanced.showcase.opengl [--student]``.

The render shaders are GLSL 3.30; the particle kernel is a GLSL 4.30 compute shader run in the same moderngl
context (``compute_gl.py``). The shader functions come from ``exercises/`` or ``solutions/``.
"""

from __future__ import annotations

from types import ModuleType

from gandalf_core import Application
from gandalf_core.app.cli import build_shaders, load_impl, run_variant

from . import STEP
from .compute_gl import GLParticleKernel
from .scene import build_scene, fountain_state
from .shaders import SHADER_DIR, SHADERS, impl_shader_dir

#: glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS): filter across cube faces, as WebGPU always does.
GL_TEXTURE_CUBE_MAP_SEAMLESS = 0x884F


def register_shaders(app: Application, impl: ModuleType) -> None:
    """Build the step's GLSL programs with ``impl``'s ``brdf.glsl`` and ``normal_map.glsl``."""
    build_shaders(app, SHADERS, SHADER_DIR, [impl_shader_dir(impl)])
    # Rough materials read the sky's small mip levels, where unfiltered face edges would show as seams.
    app.renderer.ctx.enable_direct(GL_TEXTURE_CUBE_MAP_SEAMLESS)


def create_app(headless: bool | None = None, student: bool = False, width: int = 640, height: int = 480) -> Application:
    impl = load_impl(STEP, student)
    app = Application("opengl", width, height, title="step07 · OpenGL", headless=headless, fixed_dt=1 / 60)
    register_shaders(app, impl)
    app.add_scene(build_scene(impl, GLParticleKernel(app.renderer.ctx, impl, fountain_state())))
    return app


def main(argv: list[str] | None = None) -> int:
    return run_variant(create_app, argv, description=__doc__)


if __name__ == "__main__":
    raise SystemExit(main())
