"""Step 06 the meshes, WebGPU variant: ``python -m step06_lighting.meshes.webgpu [--student]``.

Same scene in both APIs (``scene.py``); only the shaders differ: WGSL (``shaders/phong.wgsl``).
"""

from __future__ import annotations

from gandalf_core.app.cli import run_variant, variant

from ..shaders import shader_table
from . import SHADERS, STEP
from .scene import build_scene

create_app = variant("webgpu", STEP, build_scene, shader_table(SHADERS), include_impl=True)


def main(argv: list[str] | None = None) -> int:
    return run_variant(create_app, argv, description=__doc__)


if __name__ == "__main__":
    raise SystemExit(main())
