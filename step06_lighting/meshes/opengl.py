"""Step 06 the meshes, OpenGL variant: ``python -m step06_lighting.meshes.opengl [--student]``.

Same scene in both APIs (``scene.py``); only the shaders differ: GLSL 330 (``shaders/lit.vert`` + ``phong.frag``).
"""

from gandalf_core.app.cli import launcher

from .scene import PART

create_app, main = launcher(PART, "opengl", __doc__)


if __name__ == "__main__":
    raise SystemExit(main())
