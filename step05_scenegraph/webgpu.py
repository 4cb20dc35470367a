"""Step 05, WebGPU: ``python -m step05_scenegraph.webgpu [--concept NAME] [--student] [--headless] ...``.

Each concept also runs on its own: ``python -m step05_scenegraph.hierarchy.webgpu``.
"""

from gandalf_core.app.cli import Part, launcher

from . import CONCEPTS, DEFAULT_CONCEPT

create_app, main = launcher(Part(__package__, parts=CONCEPTS, default=DEFAULT_CONCEPT), "webgpu", __doc__)


if __name__ == "__main__":
    raise SystemExit(main())
