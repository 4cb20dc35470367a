"""Step 02, OpenGL variant: ``python -m step02_triangle.opengl``.

The renderer compiles the GLSL vertex and fragment shaders into one program, asks it which vertex inputs
it reads (locations 0 and 4), and binds the mesh's interleaved buffer to them with a vertex array object.
"""

from __future__ import annotations

from gandalf_core.app.cli import run_variant, variant

from .scene import SHADERS, build_scene, register_shaders  # noqa: F401 (tests and the preview call it)

create_app = variant("opengl", __package__, build_scene, SHADERS)


if __name__ == "__main__":
    raise SystemExit(run_variant(create_app, description=__doc__))
