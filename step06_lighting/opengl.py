"""Step 06, OpenGL: ``python -m step06_lighting.opengl [--concept NAME] [--student] [--headless] ...``.

Each concept also runs on its own: ``python -m step06_lighting.lights.opengl``. ``create_app`` builds the step's
whole scene (``scene.py``: the three concepts in one), which the tests compare across the APIs.
"""

from __future__ import annotations

from gandalf_core.app.cli import launch_part, variant

from . import CONCEPTS, DEFAULT_CONCEPT
from .scene import build_scene
from .shaders import SHADERS

create_app = variant("opengl", __package__, build_scene, SHADERS, include_impl=True)


def main(argv: list[str] | None = None) -> int:
    """Run ``--concept``'s OpenGL variant (default: the lights) with the other options."""
    return launch_part(__package__, "opengl", CONCEPTS, "concept", argv, default=DEFAULT_CONCEPT)


if __name__ == "__main__":
    raise SystemExit(main())
