"""Step 04, OpenGL variant: ``python -m step04_camera.opengl`` (drag to orbit, scroll to zoom, C to switch).

The projection is built with OpenGL's depth range: z_ndc in [-1, 1] (see ``gandalf_core.math.perspective``).
"""

from gandalf_core.app.cli import launcher

from .scene import PART

create_app, main = launcher(PART, "opengl", __doc__)


if __name__ == "__main__":
    raise SystemExit(main())
