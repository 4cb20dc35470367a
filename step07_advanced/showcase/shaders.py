"""The step's shader files, and where the student's (or the reference) shader functions live.

The render shaders include ``brdf.*`` and ``normal_map.*``, the compute shaders ``particle_step.*``, from the
folder of the implementation package, so ``--student`` runs the exercises and the default the solutions.
"""

from __future__ import annotations

from pathlib import Path
from types import ModuleType

SHADER_DIR = Path(__file__).resolve().parent / "shaders"

#: The Material block (one field per value of the material: its colour, then its params), declared once: the
#: engine writes it into both languages (``#include "material.glsl"`` / ``"material.wgsl"``).
PBR_MATERIAL = [("color", "vec4"), ("metallic", "float"), ("roughness", "float"), ("env_strength", "float")]
BUMPY_MATERIAL = [*PBR_MATERIAL, ("height_scale", "float"), ("uv_scale", "float")]
#: The shadow study's material: the colour and the filter (0: one tap, 1: 3x3 PCF).
STUDY_SHADOW_MATERIAL = [("color", "vec4"), ("pcf", "float")]

#: shader name -> (GLSL vertex file, GLSL fragment file[, Material block]); the WGSL module is ``<name>.wgsl``.
SHADERS = {
    "pbr": ("surface.vert", "pbr.frag", PBR_MATERIAL),
    "bumpy": ("surface.vert", "bumpy.frag", BUMPY_MATERIAL),
    "normal_view": ("surface.vert", "normal_view.frag"),
}
#: The compute kernels: GLSL 4.30 for OpenGL, WGSL for WebGPU.
COMPUTE_GLSL = SHADER_DIR / "particles.comp"
COMPUTE_WGSL = SHADER_DIR / "particles.wgsl"


def impl_shader_dir(impl: ModuleType) -> Path:
    """The folder holding ``impl``'s ``brdf``, ``normal_map`` and ``particle_step`` shader files."""
    return Path(impl.__file__).resolve().parent
