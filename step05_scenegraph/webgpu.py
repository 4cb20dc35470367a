"""Step 05, WebGPU: ``python -m step05_scenegraph.webgpu [--concept NAME] [--student] [--headless] ...``.

Each concept also runs on its own: ``python -m step05_scenegraph.hierarchy.webgpu``.
"""

from gandalf_core.app.cli import launch_part

from . import CONCEPTS, DEFAULT_CONCEPT


def main(argv: list[str] | None = None) -> int:
    """Run ``--concept``'s WebGPU variant (default: every scene in one app) with the other options."""
    return launch_part(__package__, "webgpu", CONCEPTS, "concept", argv, default=DEFAULT_CONCEPT)


if __name__ == "__main__":
    raise SystemExit(main())
