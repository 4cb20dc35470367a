"""Step 07 explode, OpenGL variant: ``python -m step07_advanced.explode.opengl [--student]``.

A geometry shader moves every triangle of the bunny along its face normal (``shaders/explode.geom``), calling
the student's ``explode_offset`` from ``exercises/explode.glsl`` (``--student``) or ``solutions/``.
"""

from __future__ import annotations

from types import ModuleType

from gandalf_core import Application, Scene
from gandalf_core.app.cli import Backend, launcher
from gandalf_core.render.capabilities import require_opengl

from .scene import LIT_SHADER, PART, GeometryShaderRoute, build_scene
from .shaders import EXPLODE_MATERIAL, GL_EXPLODE, GL_LIT, GL_PULLED, LIT_MATERIAL, impl_shader_dir


# --8<-- [start:register]
def register_shaders(app: Application, impl: ModuleType, pulling: bool = False) -> None:
    """The exploding program with ``impl``'s ``explode.glsl`` (and the unexploded reference ``explode_lit``);
    ``pulling`` also builds the GLSL 4.30 vertex-pulling program (the study compares the two routes)."""
    include = [impl_shader_dir(impl)]
    shaders = app.renderer.shaders
    shaders.build("explode", GL_EXPLODE["vert"], GL_EXPLODE["frag"], geometry=GL_EXPLODE["geom"], include_dirs=include,
                  material=EXPLODE_MATERIAL)
    shaders.build(LIT_SHADER, GL_LIT["vert"], GL_LIT["frag"], include_dirs=include, material=LIT_MATERIAL)
    if pulling:  # storage buffers in a vertex shader: OpenGL 4.3
        require_opengl(app.renderer.ctx, 430, "storage buffers", "the vertex-pulling route")
        shaders.build("explode_pulled", GL_PULLED["vert"], GL_PULLED["frag"], include_dirs=include,
                      material=EXPLODE_MATERIAL)
# --8<-- [end:register]


class OpenGL(Backend):
    """The bunny drawn through the geometry shader."""

    api = "opengl"

    def scene(self, app: Application, impl: ModuleType) -> Scene:
        register_shaders(app, impl)
        return build_scene(impl, GeometryShaderRoute())


create_app, main = launcher(PART, OpenGL(), __doc__)


if __name__ == "__main__":
    raise SystemExit(main())
