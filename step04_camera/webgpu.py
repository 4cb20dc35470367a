"""Step 04, WebGPU variant: ``python -m step04_camera.webgpu`` (drag to orbit, scroll to zoom, C to switch).

The projection is built with WebGPU's depth range: z_ndc in [0, 1] (see ``gandalf_core.math.perspective``).
"""

from gandalf_core.app.cli import launcher

from .scene import PART

create_app, main = launcher(PART, "webgpu", __doc__)


if __name__ == "__main__":
    raise SystemExit(main())
