"""Step 07, OpenGL: ``python -m step07_advanced.opengl --technique NAME [--student] [--headless] ...``.

Each technique also runs on its own: ``python -m step07_advanced.terrain.opengl``.
"""

from gandalf_core.app.cli import launcher

from .techniques import PART

create_app, main = launcher(PART, "opengl", __doc__)


if __name__ == "__main__":
    raise SystemExit(main())
