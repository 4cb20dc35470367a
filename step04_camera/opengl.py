"""Step 04, OpenGL variant: ``python -m step04_camera.opengl`` (drag to orbit, scroll to zoom, C to switch).

The projection is built with OpenGL's depth range: z_ndc in [-1, 1] (see ``gandalf_core.math.perspective``).
"""

from __future__ import annotations

from gandalf_core.app.cli import run_variant, variant

from .scene import SHADERS, build_scene, register_shaders  # noqa: F401 (tests and the preview call it)

create_app = variant("opengl", __package__, build_scene, SHADERS)


if __name__ == "__main__":
    raise SystemExit(run_variant(create_app, description=__doc__))
