"""The step's shader files, and where the student's (or the reference) shader functions live.

The render shaders include ``brdf.*`` and ``normal_map.*``, the compute shaders ``particle_step.*``, from the
folder of the implementation package, so ``--student`` runs the exercises and the default the solutions.
"""

from __future__ import annotations

from pathlib import Path
from types import ModuleType

from gandalf_core.resources.layout import BlockLayout

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
# --8<-- [start:sim]
#: The kernels' parameters, declared once: :meth:`.particles.SimParams.pack` packs them, and the kernels
#: ``#include "sim_params.glsl"`` / ``"sim_params.wgsl"``, written from this layout. The GLSL block holds one
#: ``SimParams`` struct (``u_sim``), as WGSL's ``sim`` is one: the kernel passes it whole to ``particle_step``.
SIM_LAYOUT = BlockLayout("SimParams", [
    ("gravity", "vec4"),  # xyz: acceleration (m/s²)
    ("emitter", "vec4"),  # xyz: where particles are born, w: longest life (s)
    ("dt", "float"),
    ("restitution", "float"),
    ("floor_y", "float"),
    ("seed", "uint"),  # changes every step: new random launch velocities
])
#: GL binding point of the block (0 and 1 are the engine's Frame and Lights); WGSL: @group(0) @binding(0).
SIM_BINDING = 4
SIM_INCLUDES = {"sim_params.glsl": SIM_LAYOUT.glsl("u_sim", binding=SIM_BINDING, struct=True),
                "sim_params.wgsl": SIM_LAYOUT.wgsl("sim", 0, 0)}
# --8<-- [end:sim]


def impl_shader_dir(impl: ModuleType) -> Path:
    """The folder holding ``impl``'s ``brdf``, ``normal_map`` and ``particle_step`` shader files."""
    return Path(impl.__file__).resolve().parent
