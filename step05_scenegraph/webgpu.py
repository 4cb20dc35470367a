"""Step 05, WebGPU variant: ``python -m step05_scenegraph.webgpu`` (keys 1/2/3 or TAB switch scenes).

The scenes are the same for both APIs; only the shaders differ: WGSL (``shaders/*.wgsl``).
"""

from __future__ import annotations

from gandalf_core.app.cli import run_variant, variant

from .scene import SHADERS, build_scenes

create_app = variant("webgpu", __package__, build_scenes, SHADERS)


if __name__ == "__main__":
    raise SystemExit(run_variant(create_app, description=__doc__))
