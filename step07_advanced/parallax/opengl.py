"""Step 07 parallax, OpenGL variant: ``python -m step07_advanced.parallax.opengl [--student]``.

Four tiles of one brick wall: normal mapping, parallax offset, steep parallax and parallax occlusion mapping, the
last three calling the student's ``parallax_offset`` / ``parallax_steep`` / ``parallax_occlusion`` from
``exercises/parallax.glsl`` (``--student``) or ``solutions/``.
"""

from __future__ import annotations

from types import ModuleType

from gandalf_core import Application
from gandalf_core.app.cli import launcher

from .scene import PART
from .shaders import GL_FRAG, GL_VERT, MATERIAL, SHADER, include_dirs


# --8<-- [start:register]
def register_shaders(app: Application, impl: ModuleType) -> None:
    """The parallax program: the showcase's vertex stage, this technique's fragment stage with ``impl``'s
    ``parallax.glsl``."""
    app.renderer.shaders.build(SHADER, GL_VERT, GL_FRAG, include_dirs=include_dirs(impl), material=MATERIAL)
# --8<-- [end:register]


create_app, main = launcher(PART, "opengl", __doc__, shaders=register_shaders)


if __name__ == "__main__":
    raise SystemExit(main())
