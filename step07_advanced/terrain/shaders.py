"""The terrain's shader files, and where the student's (or the reference) ``terrain.glsl`` / ``terrain.wgsl`` live."""

from __future__ import annotations

from pathlib import Path
from types import ModuleType

SHADER_DIR = Path(__file__).resolve().parent / "shaders"
#: OpenGL: the four stages of the terrain program.
GL_STAGES = {"vertex": "terrain.vert", "tess_control": "terrain.tesc", "tess_evaluation": "terrain.tese",
             "fragment": "terrain.frag"}
#: WebGPU: the render module (vertex pulling + shading) and the compute pass that tessellates.
WGSL_RENDER = SHADER_DIR / "terrain_render.wgsl"
WGSL_TESSELLATE = SHADER_DIR / "tessellate.wgsl"
SHADER_NAME = "terrain"
#: The Material block (one field per value of the material: its colour, then its params), declared once: the
#: engine writes it into both languages (``#include "material.glsl"`` / ``"material.wgsl"``).
MATERIAL = [("color", "vec4"),  # the haze (the sky's colour), linear
            ("size", "float"), ("height_scale", "float"),
            ("lod", "vec4")]  # scale, min level, max level (OpenGL's tessellation; WebGPU's compute pass has its own)


def impl_shader_dir(impl: ModuleType) -> Path:
    """The folder holding ``impl``'s ``terrain.glsl`` and ``terrain.wgsl``."""
    return Path(impl.__file__).resolve().parent
