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


def impl_shader_dir(impl: ModuleType) -> Path:
    """The folder holding ``impl``'s ``terrain.glsl`` and ``terrain.wgsl``."""
    return Path(impl.__file__).resolve().parent
