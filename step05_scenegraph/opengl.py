"""Step 05, OpenGL: ``python -m step05_scenegraph.opengl [--concept NAME] [--student] [--headless] ...``.

Each concept also runs on its own: ``python -m step05_scenegraph.hierarchy.opengl``.
"""

from gandalf_core.app.cli import launch_part

from . import CONCEPTS, DEFAULT_CONCEPT


def main(argv: list[str] | None = None) -> int:
    """Run ``--concept``'s OpenGL variant (default: every scene in one app) with the other options."""
    return launch_part(__package__, "opengl", CONCEPTS, "concept", argv, default=DEFAULT_CONCEPT)


if __name__ == "__main__":
    raise SystemExit(main())
