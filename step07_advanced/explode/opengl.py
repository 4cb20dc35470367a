"""Step 07 explode, OpenGL variant: ``python -m step07_advanced.explode.opengl [--student]``.

A geometry shader moves every triangle of the bunny along its face normal (``shaders/explode.geom``), calling
the student's ``explode_offset`` from ``exercises/explode.glsl`` (``--student``) or ``solutions/``.
"""

from __future__ import annotations

from types import ModuleType

from gandalf_core import Application
from gandalf_core.app.cli import load_impl, run_variant

from . import STEP
from .scene import LIT_SHADER, GeometryShaderRoute, build_scene
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
    if pulling:
        shaders.build("explode_pulled", GL_PULLED["vert"], GL_PULLED["frag"], include_dirs=include,
                      material=EXPLODE_MATERIAL)
# --8<-- [end:register]


def create_app(headless: bool | None = None, student: bool = False, width: int = 640, height: int = 480) -> Application:
    impl = load_impl(STEP, student)
    app = Application("opengl", width, height, title="step07 explode · OpenGL", headless=headless, fixed_dt=1 / 60)
    register_shaders(app, impl)
    app.add_scene(build_scene(impl, GeometryShaderRoute()))
    return app


def main(argv: list[str] | None = None) -> int:
    return run_variant(create_app, argv, description=__doc__)


if __name__ == "__main__":
    raise SystemExit(main())
