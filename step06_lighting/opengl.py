"""Step 06, OpenGL: ``python -m step06_lighting.opengl [--concept NAME] [--student] [--headless] ...``.

Each concept also runs on its own: ``python -m step06_lighting.lights.opengl``. ``create_app`` builds the step's
whole scene (``scene.py``: the three concepts in one), which the tests compare across the APIs.
"""

from gandalf_core.app.cli import launcher

from .scene import PART

create_app, main = launcher(PART, "opengl", __doc__)


if __name__ == "__main__":
    raise SystemExit(main())
