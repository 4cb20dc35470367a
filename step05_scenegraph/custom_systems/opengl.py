"""Step 05 custom systems, OpenGL variant: ``python -m step05_scenegraph.custom_systems.opengl``.

Same scene in both APIs (``scene.py``); only the shaders differ: the step's GLSL 330 (``shaders/*.vert``/``*.frag``).
"""

from gandalf_core.app.cli import launcher

from .scene import PART

create_app, main = launcher(PART, "opengl", __doc__)


if __name__ == "__main__":
    raise SystemExit(main())
