"""Step 06 the lights, OpenGL variant: ``python -m step06_lighting.lights.opengl [--student]``.

Same scene in both APIs (``scene.py``); only the shaders differ: GLSL 330: the lights arrive in the ``Lights``
uniform block (``frame.glsl``); ``phong.frag`` and ``phong_textured.frag`` loop over them in ``lighting.glsl``.
"""

from gandalf_core.app.cli import launcher

from .scene import PART

create_app, main = launcher(PART, "opengl", __doc__)


if __name__ == "__main__":
    raise SystemExit(main())
