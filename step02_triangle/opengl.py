"""Step 02, OpenGL variant: ``python -m step02_triangle.opengl``.

The renderer compiles the GLSL vertex and fragment shaders into one program, asks it which vertex inputs
it reads (locations 0 and 4), and binds the mesh's interleaved buffer to them with a vertex array object.
"""

from gandalf_core.app.cli import launcher

from .scene import PART

create_app, main = launcher(PART, "opengl", __doc__)


if __name__ == "__main__":
    raise SystemExit(main())
