"""Step 06 environment mapping, OpenGL variant: ``python -m step06_lighting.environment.opengl [--student]``.

Same scene in both APIs (``scene.py``); only the shaders differ: GLSL 330 (``shaders/mirror.frag``, ``glass.frag``),
the cube map a ``samplerCube``.
"""

from gandalf_core.app.cli import launcher

from .scene import PART

create_app, main = launcher(PART, "opengl", __doc__)


if __name__ == "__main__":
    raise SystemExit(main())
