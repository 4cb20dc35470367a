"""Step 07 GPU-driven motion, WebGPU variant: ``python -m step07_advanced.gpu_motion.webgpu``.

The technique's compute pass (WGSL, ``shaders/motion_spin.wgsl``, :mod:`.motion_wgpu`) is recorded in the frame's
command encoder before the render passes and writes a buffer that the draws then read their instance rows from.
"""

from __future__ import annotations

from gandalf_core.app.cli import launcher

from .scene import PART

create_app, main = launcher(PART, "webgpu", __doc__)


if __name__ == "__main__":
    raise SystemExit(main())
