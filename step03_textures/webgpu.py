"""Step 03, WebGPU variant: ``python -m step03_textures.webgpu``.

WGSL declares a ``texture_2d<f32>`` and a separate ``sampler``: WebGPU splits the image (texture + view) from
how it is read (a sampler object with filter, address and mipmap modes); ``gandalf_core/render/webgpu/libs.py``
creates both and puts them in the material's bind group.
"""

from __future__ import annotations

from gandalf_core.app.cli import run_variant, variant

from .scene import SHADERS, build_scene

create_app = variant("webgpu", __package__, build_scene, SHADERS)


if __name__ == "__main__":
    raise SystemExit(run_variant(create_app, description=__doc__))
