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


def impl_shader_dir(impl: ModuleType) -> Path:
    """The folder holding ``impl``'s ``explode.glsl`` / ``explode.wgsl``."""
    return Path(impl.__file__).resolve().parent
