"""Step 03, WebGPU variant: ``python -m step03_textures.webgpu``.

WGSL declares a ``texture_2d<f32>`` and a separate ``sampler``: WebGPU splits the image (texture + view) from
how it is read (a sampler object with filter, address and mipmap modes); ``gandalf_core/render/webgpu/libs.py``
creates both and puts them in the material's bind group.
"""

from gandalf_core.app.cli import launcher

from .scene import PART

create_app, main = launcher(PART, "webgpu", __doc__)


if __name__ == "__main__":
    raise SystemExit(main())
