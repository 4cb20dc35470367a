"""The step's shader files, and where the student's (or the reference) shader functions live.

The render shaders include ``brdf.*`` and ``normal_map.*``, the compute shaders ``particle_step.*``, from the
folder of the implementation package, so ``--student`` runs the exercises and the default the solutions.
"""

from __future__ import annotations

from pathlib import Path
from types import ModuleType

SHADER_DIR = Path(__file__).resolve().parent / "shaders"

#: shader name -> (GLSL vertex file, GLSL fragment file); the WGSL module is ``<name>.wgsl``.
SHADERS = {
    "pbr": ("surface.vert", "pbr.frag"),
    "bumpy": ("surface.vert", "bumpy.frag"),
    "normal_view": ("surface.vert", "normal_view.frag"),
}
#: The compute kernels: GLSL 4.30 for OpenGL, WGSL for WebGPU.
COMPUTE_GLSL = SHADER_DIR / "particles.comp"
COMPUTE_WGSL = SHADER_DIR / "particles.wgsl"


def impl_shader_dir(impl: ModuleType) -> Path:
    """The folder holding ``impl``'s ``brdf``, ``normal_map`` and ``particle_step`` shader files."""
    return Path(impl.__file__).resolve().parent
