"""Step 07 PBR model, OpenGL variant: ``python -m step07_advanced.pbr_model.opengl [--student]``.

The fragment shader (``shaders/pbr_model.frag``, GLSL 3.30) samples the model's five glTF maps and the three
IBL textures, calling the student's ``brdf.glsl`` functions from ``exercises/`` (``--student``) or
``solutions/``. The prefiltered environment's mip levels are written one by one (glTexSubImage2D).
"""

from __future__ import annotations

from types import ModuleType

from gandalf_core import Application
from gandalf_core.app.cli import launcher

from .scene import PART
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


create_app, main = launcher(PART, "opengl", __doc__, shaders=register_shaders)


if __name__ == "__main__":
    raise SystemExit(main())
