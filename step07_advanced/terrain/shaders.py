"""The terrain's shader files, and where the student's (or the reference) ``terrain.glsl`` / ``terrain.wgsl`` live."""

from __future__ import annotations

from pathlib import Path
from types import ModuleType

from gandalf_core.resources.layout import BlockLayout

SHADER_DIR = Path(__file__).resolve().parent / "shaders"
#: OpenGL: the four stages of the terrain program.
GL_STAGES = {"vertex": "terrain.vert", "tess_control": "terrain.tesc", "tess_evaluation": "terrain.tese",
             "fragment": "terrain.frag"}
#: WebGPU: the render module (vertex pulling + shading) and the compute pass that tessellates.
WGSL_RENDER = SHADER_DIR / "terrain_render.wgsl"
WGSL_TESSELLATE = SHADER_DIR / "tessellate.wgsl"
SHADER_NAME = "terrain"
# --8<-- [start:params]
#: The compute pass's values, declared once: the tessellator packs them, ``tessellate.wgsl`` includes the struct
#: written from this layout (``#include "tessellate_params.wgsl"``, ``@group(0) @binding(0)``).
TESSELLATE_PARAMS = BlockLayout("Params", [
    ("eye", "vec4"),  # the camera's world position
    ("lod", "vec4"),  # scale, min level, max level
    ("grid", "vec4"),  # terrain size, height scale, patches per side, budget L
])
TESSELLATE_INCLUDES = {"tessellate_params.wgsl": TESSELLATE_PARAMS.wgsl("params", 0, 0)}
# --8<-- [end:params]
#: The Material block (one field per value of the material: its colour, then its params), declared once: the
#: engine writes it into both languages (``#include "material.glsl"`` / ``"material.wgsl"``).
MATERIAL = [("color", "vec4"),  # the haze (the sky's colour), linear
            ("size", "float"), ("height_scale", "float"),
            ("lod", "vec4")]  # scale, min level, max level (OpenGL's tessellation; WebGPU's compute pass has its own)


def impl_shader_dir(impl: ModuleType) -> Path:
    """The folder holding ``impl``'s ``terrain.glsl`` and ``terrain.wgsl``."""
    return Path(impl.__file__).resolve().parent
