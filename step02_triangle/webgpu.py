"""Step 02, WebGPU variant: ``python -m step02_triangle.webgpu``.

The renderer compiles one WGSL module holding both entry points, reflects which vertex inputs it reads
(locations 0 and 4), and describes the mesh's interleaved buffer to a render pipeline (stride, formats,
offsets, shader locations).
"""

from __future__ import annotations

from gandalf_core.app.cli import run_variant, variant

from .scene import SHADERS, build_scene, register_shaders  # noqa: F401 (tests and the preview call it)

create_app = variant("webgpu", __package__, build_scene, SHADERS)


if __name__ == "__main__":
    raise SystemExit(run_variant(create_app, description=__doc__))
