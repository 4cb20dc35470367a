"""The technique's shader files, and the folder the student's (or the reference) ``parallax.*`` is included from.

The vertex stage is the showcase's (``surface.vert`` / ``surface_vertex.wgsl``: world position, normal, uv and
tangent); the fragment stage (``parallax_surface``) is this technique's own.
"""

from __future__ import annotations

from pathlib import Path
from types import ModuleType

from ..showcase.shaders import SHADER_DIR as SHOWCASE_SHADER_DIR

SHADER_DIR = Path(__file__).resolve().parent / "shaders"
#: The one material shader: method 0-3 picks normal mapping, parallax offset, steep or occlusion.
SHADER = "parallax_surface"
GL_VERT = SHOWCASE_SHADER_DIR / "surface.vert"
GL_FRAG = SHADER_DIR / "parallax_surface.frag"
WGSL = SHADER_DIR / "parallax_surface.wgsl"
#: The Material block (one field per value of the material: its colour, then its params), declared once: the
#: engine writes it into both languages (``#include "material.glsl"`` / ``"material.wgsl"``).
MATERIAL = [("color", "vec4"), ("uv_scale", "vec2"), ("method", "float"), ("height_scale", "float"),
            ("layers", "float"), ("specular", "float"), ("shininess", "float")]


def impl_shader_dir(impl: ModuleType) -> Path:
    """The folder holding ``impl``'s ``parallax.glsl`` / ``parallax.wgsl``."""
    return Path(impl.__file__).resolve().parent


def include_dirs(impl: ModuleType) -> list[Path]:
    """Where the shaders' includes are found: ``impl``'s folder first (it holds ``parallax.*``, and the showcase
    has a ``parallax.*`` of its own), then the showcase's shaders (``surface_vertex.wgsl``)."""
    return [impl_shader_dir(impl), SHOWCASE_SHADER_DIR]
