"""Step 07 showcase, OpenGL variant: ``python -m step07_advanced.showcase.opengl [--student]``.

The render shaders are GLSL 3.30; the particle kernel is a GLSL 4.30 compute shader run in the same moderngl
context (``compute_gl.py``). The shader functions come from ``exercises/`` or ``solutions/``.
"""

from __future__ import annotations

from types import ModuleType

from gandalf_core import Application, Scene
from gandalf_core.app.cli import Backend, build_shaders, launcher

from .compute_gl import GLParticleKernel
from .scene import PART, build_scene, fountain_state
from .shaders import SHADER_DIR, SHADERS, impl_shader_dir

#: glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS): filter across cube faces, as WebGPU always does.
GL_TEXTURE_CUBE_MAP_SEAMLESS = 0x884F


def register_shaders(app: Application, impl: ModuleType) -> None:
    """Build the step's GLSL programs with ``impl``'s ``brdf.glsl`` and ``normal_map.glsl``."""
    build_shaders(app, SHADERS, SHADER_DIR, [impl_shader_dir(impl)])
    # Rough materials read the sky's small mip levels, where unfiltered face edges would show as seams.
    app.renderer.ctx.enable_direct(GL_TEXTURE_CUBE_MAP_SEAMLESS)


class OpenGL(Backend):
    """The GLSL programs, and the fountain's kernel in the renderer's moderngl context."""

    api = "opengl"

    def scene(self, app: Application, impl: ModuleType) -> Scene:
        register_shaders(app, impl)
        return build_scene(impl, GLParticleKernel(app.renderer.ctx, impl, fountain_state()))


create_app, main = launcher(PART, OpenGL(), __doc__)


if __name__ == "__main__":
    raise SystemExit(main())
