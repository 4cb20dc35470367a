"""Step 06, WebGPU variant: ``python -m step06_lighting.webgpu [--student]``.

WGSL: the lights arrive in ``lights`` at @group(0) @binding(1) (``frame.wgsl``), the cube map as a
``texture_cube<f32>`` plus its sampler in @group(1); the shading functions come from ``shading.wgsl`` of
``exercises/`` or ``solutions/``.
"""

from __future__ import annotations

from gandalf_core.app.cli import run_variant, variant

from .scene import build_scene
from .shaders import SHADERS, register_shaders  # noqa: F401 (the studies call register_shaders)

create_app = variant("webgpu", __package__, build_scene, SHADERS, include_impl=True)


if __name__ == "__main__":
    raise SystemExit(run_variant(create_app, description=__doc__))
