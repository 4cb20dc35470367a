"""Step 02, WebGPU variant: ``python -m step02_triangle.webgpu``.

The renderer compiles one WGSL module holding both entry points, reflects which vertex inputs it reads
(locations 0 and 4), and describes the mesh's interleaved buffer to a render pipeline (stride, formats,
offsets, shader locations).
"""

from gandalf_core.app.cli import launcher

from .scene import PART

create_app, main = launcher(PART, "webgpu", __doc__)


if __name__ == "__main__":
    raise SystemExit(main())
