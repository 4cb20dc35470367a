"""Step 01, WebGPU variant: ``python -m step01_window.webgpu``.

The WebGPU renderer begins a render pass on an ``rgba8unorm-srgb`` texture with ``load_op="clear"`` and
the scene's clear colour; compare ``gandalf_core/render/webgpu/renderer.py``.
"""

from __future__ import annotations

from gandalf_core.app.cli import run_variant, variant

from .scene import build_scene

create_app = variant("webgpu", __package__, build_scene)


if __name__ == "__main__":
    raise SystemExit(run_variant(create_app, description=__doc__))
