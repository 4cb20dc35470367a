"""Step 06 environment mapping, WebGPU variant: ``python -m step06_lighting.environment.webgpu [--student]``.

Same scene in both APIs (``scene.py``); only the shaders differ: WGSL (``shaders/mirror.wgsl``, ``glass.wgsl``),
the cube map a ``texture_cube<f32>`` and its sampler in @group(1).
"""

from gandalf_core.app.cli import launcher

from .scene import PART

create_app, main = launcher(PART, "webgpu", __doc__)


if __name__ == "__main__":
    raise SystemExit(main())
