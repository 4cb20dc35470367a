"""The technique's shader files, and the folder the student's (or the reference) ``explode.*`` is included from."""

from __future__ import annotations

from pathlib import Path
from types import ModuleType

SHADER_DIR = Path(__file__).resolve().parent / "shaders"

#: OpenGL: the exploding program (vertex → geometry → fragment) and the unexploded reference.
GL_EXPLODE = {"vert": SHADER_DIR / "explode.vert", "geom": SHADER_DIR / "explode.geom",
              "frag": SHADER_DIR / "explode.frag"}
GL_LIT = {"vert": SHADER_DIR / "lit.vert", "frag": SHADER_DIR / "explode_lit.frag"}
#: OpenGL vertex pulling (the study's third route): the WebGPU way in GLSL 4.30.
GL_PULLED = {"vert": SHADER_DIR / "explode_pulled.vert", "frag": SHADER_DIR / "explode.frag"}
#: WebGPU: the vertex-pulling module and the unexploded reference.
WGSL_PULLED = SHADER_DIR / "explode_pulled.wgsl"
WGSL_LIT = SHADER_DIR / "explode_lit.wgsl"
#: The Material block (one field per value of the material: its colour, then its params), declared once: the
#: engine writes it into both languages (``#include "material.glsl"`` / ``"material.wgsl"``).
LIT_MATERIAL = [("color", "vec4"), ("specular", "float"), ("shininess", "float")]
EXPLODE_MATERIAL = [("color", "vec4"),
                    ("explode_time", "float"),  # seconds on the explosion clock (set every frame by ExplodeSystem)
                    ("amount", "float"),  # how far a face moves at the peak (world units)
                    ("period", "float"),  # seconds from one whole mesh to the next
                    ("specular", "float"), ("shininess", "float")]


def impl_shader_dir(impl: ModuleType) -> Path:
    """The folder holding ``impl``'s ``explode.glsl`` / ``explode.wgsl``."""
    return Path(impl.__file__).resolve().parent
