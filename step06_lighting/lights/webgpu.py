"""Step 06 the lights, WebGPU variant: ``python -m step06_lighting.lights.webgpu [--student]``.

Same scene in both APIs (``scene.py``); only the shaders differ: WGSL: the lights arrive in ``lights`` at
@group(0) @binding(1) (``frame.wgsl``); ``phong.wgsl`` and ``phong_textured.wgsl`` loop over them in
``lighting.wgsl``.
"""

from gandalf_core.app.cli import launcher

from .scene import PART

create_app, main = launcher(PART, "webgpu", __doc__)


if __name__ == "__main__":
    raise SystemExit(main())
