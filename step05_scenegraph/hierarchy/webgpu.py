"""Step 05 the hierarchy, WebGPU variant: ``python -m step05_scenegraph.hierarchy.webgpu`` (M re-parents the moon).

Same scene in both APIs (``scene.py``); only the shaders differ: the step's WGSL (``shaders/*.wgsl``).
"""

from __future__ import annotations

from gandalf_core.app.cli import run_variant, variant

from .. import SHADERS
from . import STEP
from .scene import build_scene

create_app = variant("webgpu", STEP, build_scene, SHADERS)


def main(argv: list[str] | None = None) -> int:
    return run_variant(create_app, argv, description=__doc__)


if __name__ == "__main__":
    raise SystemExit(main())
