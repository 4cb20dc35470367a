"""Step 06, OpenGL variant: ``python -m step06_lighting.opengl [--student]``.

GLSL 330: the lights arrive in the ``Lights`` uniform block (``frame.glsl``), the cube map as a
``samplerCube``; the shading functions come from ``shading.glsl`` of ``exercises/`` or ``solutions/``.
"""

from __future__ import annotations

from gandalf_core.app.cli import run_variant, variant

from .scene import build_scene
from .shaders import SHADERS, register_shaders  # noqa: F401 (the studies call register_shaders)

create_app = variant("opengl", __package__, build_scene, SHADERS, include_impl=True)


if __name__ == "__main__":
    raise SystemExit(run_variant(create_app, description=__doc__))
