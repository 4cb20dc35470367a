"""Step 06 the lights, OpenGL variant: ``python -m step06_lighting.lights.opengl [--student]``.

Same scene in both APIs (``scene.py``); only the shaders differ: GLSL 330: the lights arrive in the ``Lights``
uniform block (``frame.glsl``); ``phong.frag`` and ``phong_textured.frag`` loop over them in ``lighting.glsl``.
"""

from __future__ import annotations

from gandalf_core.app.cli import run_variant, variant

from ..shaders import shader_table
from . import SHADERS, STEP
from .scene import build_scene

# --8<-- [start:variant]
create_app = variant("opengl", STEP, build_scene, shader_table(SHADERS), include_impl=True)
# --8<-- [end:variant]


def main(argv: list[str] | None = None) -> int:
    return run_variant(create_app, argv, description=__doc__)


if __name__ == "__main__":
    raise SystemExit(main())
