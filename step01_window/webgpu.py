"""Step 01, WebGPU variant: ``python -m step01_window.webgpu``.

The WebGPU renderer begins a render pass on an ``rgba8unorm-srgb`` texture with ``load_op="clear"`` and
the scene's clear colour; compare ``gandalf_core/render/webgpu/renderer.py``.
"""

from gandalf_core.app.cli import launcher

from .scene import PART

create_app, main = launcher(PART, "webgpu", __doc__)


if __name__ == "__main__":
    raise SystemExit(main())
