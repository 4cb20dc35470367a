"""The technique's shader files, and the folders their ``#include`` lines are resolved in.

The fragment shaders include the student's (or the reference) ``brdf.*`` and ``normal_map.*`` from the
implementation package, and the showcase's ``pbr_lighting.*`` (direct light) and vertex stage.
"""

from __future__ import annotations

from pathlib import Path
from types import ModuleType

from step07_advanced.showcase.shaders import SHADER_DIR as SHOWCASE_SHADER_DIR
from step07_advanced.showcase.shaders import impl_shader_dir

SHADER_DIR = Path(__file__).resolve().parent / "shaders"
SHADER_NAME = "pbr_model"
GL_VERTEX = SHOWCASE_SHADER_DIR / "surface.vert"
GL_FRAGMENT = SHADER_DIR / "pbr_model.frag"
WGSL = SHADER_DIR / "pbr_model.wgsl"
#: The Material block (one field per value of the material: its colour, then its params), declared once: the
#: engine writes it into both languages (``#include "material.glsl"`` / ``"material.wgsl"``).
MATERIAL = [("color", "vec4"), ("emissive", "vec4"), ("metallic", "float"), ("roughness", "float"),
            ("normal_scale", "float"), ("occlusion_strength", "float"), ("env_strength", "float"),
            ("prefiltered_levels", "float")]


def include_dirs(impl: ModuleType) -> list[Path]:
    """Where ``#include`` looks after a shader's own folder: the implementation, then the showcase's shaders."""
    return [impl_shader_dir(impl), SHOWCASE_SHADER_DIR]
