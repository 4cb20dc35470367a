"""The step's shader files, and where the student's (or the reference) ``shading`` include lives.

Every lit shader includes ``shading.glsl``/``shading.wgsl`` (Blinn-Phong, reflect, refract) from the folder of
the implementation package, so ``--student`` renders with the exercises and the default with the solutions.
Each concept builds the shaders its scene uses (:func:`shader_table`); the tests and studies build them all
(:func:`register_shaders`).
"""

from __future__ import annotations

from pathlib import Path
from types import ModuleType
from typing import Any

from gandalf_core.app.cli import build_shaders

SHADER_DIR = Path(__file__).resolve().parent / "shaders"

#: The Material blocks (each field is one value of the material: its colour, then its params), declared once:
#: the engine writes them into both languages (``#include "material.glsl"`` / ``"material.wgsl"``).
PHONG_MATERIAL = [("color", "vec4"), ("specular", "float"), ("shininess", "float")]
GLASS_MATERIAL = [("color", "vec4"), ("ior", "float")]

#: shader name -> (GLSL vertex file, GLSL fragment file[, Material block]); the WGSL module is ``<name>.wgsl``.
SHADERS = {
    "phong": ("lit.vert", "phong.frag", PHONG_MATERIAL),
    "phong_textured": ("phong_textured.vert", "phong_textured.frag", PHONG_MATERIAL),
    "mirror": ("lit.vert", "mirror.frag"),
    "glass": ("lit.vert", "glass.frag", GLASS_MATERIAL),
    "emissive": ("lit.vert", "emissive.frag"),
}


def shader_table(names: tuple[str, ...]) -> dict[str, tuple[Any, ...]]:
    """The part of :data:`SHADERS` a concept's scene uses (``names``: its materials' shaders)."""
    unknown = [name for name in names if name not in SHADERS]
    if unknown:
        raise ValueError(f"step06_lighting has no shader {unknown[0]!r} (known: {', '.join(SHADERS)})")
    return {name: SHADERS[name] for name in names}


def impl_shader_dir(impl: ModuleType) -> Path:
    """The folder holding ``impl``'s ``shading.glsl`` and ``shading.wgsl``."""
    return Path(impl.__file__).resolve().parent


def register_shaders(app: Any, impl: ModuleType) -> None:
    """Build every shader of the step in ``app``'s API (GLSL programs or WGSL modules), including ``impl``'s
    ``shading``."""
    build_shaders(app, SHADERS, SHADER_DIR, [impl_shader_dir(impl)])
