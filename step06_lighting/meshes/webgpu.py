"""Step 06 the meshes, WebGPU variant: ``python -m step06_lighting.meshes.webgpu [--student]``.

Same scene in both APIs (``scene.py``); only the shaders differ: WGSL (``shaders/phong.wgsl``).
"""

from gandalf_core.app.cli import launcher

from .scene import PART

create_app, main = launcher(PART, "webgpu", __doc__)


if __name__ == "__main__":
    raise SystemExit(main())
