"""Step 05 the house, WebGPU variant: ``python -m step05_scenegraph.house.webgpu`` (P pauses; ``--student``: yours).

Same scene in both APIs (``scene.py``); only the shaders differ: the step's WGSL (``shaders/*.wgsl``).
"""

from gandalf_core.app.cli import launcher

from .scene import PART

create_app, main = launcher(PART, "webgpu", __doc__)


if __name__ == "__main__":
    raise SystemExit(main())
