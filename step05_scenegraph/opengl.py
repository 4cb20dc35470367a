"""Step 05, OpenGL: ``python -m step05_scenegraph.opengl [--concept NAME] [--student] [--headless] ...``.

Each concept also runs on its own: ``python -m step05_scenegraph.hierarchy.opengl``.
"""

from gandalf_core.app.cli import Part, launcher

from . import CONCEPTS, DEFAULT_CONCEPT

create_app, main = launcher(Part(__package__, parts=CONCEPTS, default=DEFAULT_CONCEPT), "opengl", __doc__)


if __name__ == "__main__":
    raise SystemExit(main())
