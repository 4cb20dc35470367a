"""Where the path tracer's shader files live, and where the student's (or the reference) shader functions are.

The kernels include ``ray_sphere.*`` (exercise ``hit_sphere``) and ``dielectric.*`` (exercise
``scatter_dielectric``) from the implementation package's folder, so ``--student`` runs the exercises and the
default the solutions. Their own pieces (``rng``, ``sky``, ``trace``) sit next to them in ``shaders/``.
"""

from __future__ import annotations

import re
from pathlib import Path
from types import ModuleType

from gandalf_core.render.shader_files import load_shader
from gandalf_core.resources import ShaderSource
from gandalf_core.resources.layout import BlockLayout

SHADER_DIR = Path(__file__).resolve().parent / "shaders"
#: The full-screen material that shows the accumulation (``display.vert`` + ``display.frag`` / ``display.wgsl``).
DISPLAY_SHADER = "pathtracer_display"
#: The Material block (one field per value of the material: its colour, then its params), declared once: the
#: engine writes it into both languages (``#include "material.glsl"`` / ``"material.wgsl"``).
DISPLAY_MATERIAL = [("color", "vec4"), ("exposure", "float"), ("trace_width", "float"), ("trace_height", "float")]
KERNEL_GLSL = SHADER_DIR / "pathtrace.comp"
KERNEL_WGSL = SHADER_DIR / "pathtrace.wgsl"

# --8<-- [start:params]
#: The kernels' per-dispatch values, declared once: :meth:`.scene.PackedScene.params` packs them, and the kernels
#: ``#include "pathtrace_params.glsl"`` / ``"pathtrace_params.wgsl"``, written from this layout.
PARAMS_LAYOUT = BlockLayout("Params", [
    ("origin", "vec4"),  # xyz: the camera position
    ("right", "vec4"),  # xyz: camera right * tan(fov / 2) * aspect
    ("up", "vec4"),  # xyz: camera up * tan(fov / 2)
    ("forward", "vec4"),  # xyz: the unit view direction
    ("background", "vec4"),  # rgb: the background without a sky; w: the sky's face size (0: no sky)
    ("size", "uvec4"),  # width, height, sample index (the frame of the accumulation), seed
    ("counts", "uvec4"),  # spheres, triangles, BVH nodes, maximum bounces
])
#: GL binding point of the block (0 and 1 are the engine's Frame and Lights); WGSL: @group(0) @binding(0).
PARAMS_BINDING = 4
PARAMS_INCLUDES = {
    "pathtrace_params.glsl": PARAMS_LAYOUT.glsl(None, {name: f"u_{name}" for name in PARAMS_LAYOUT.names()},
                                                binding=PARAMS_BINDING),
    "pathtrace_params.wgsl": PARAMS_LAYOUT.wgsl("params", 0, 0),
}
# --8<-- [end:params]

#: Line numbers in compiler logs: GLSL drivers ("0:12(5): error ..."), naga ("wgsl:12:5").
_LINE = {
    "glsl": re.compile(r"^\s*(?:ERROR:\s*)?\d+[:(](\d+)\)?"),
    "wgsl": re.compile(r"(?:wgsl|<[^>]*>|\S+\.wgsl):(\d+):\d+"),
}


def impl_shader_dir(impl: ModuleType) -> Path:
    """The folder holding ``impl``'s ``ray_sphere`` and ``dielectric`` shader files."""
    return Path(impl.__file__).resolve().parent


def kernel_source(backend: str, impl: ModuleType) -> ShaderSource:
    """The path tracing kernel's expanded source for ``backend`` with ``impl``'s exercise files included."""
    if backend == "opengl":
        return load_shader(KERNEL_GLSL, "compute", "glsl", [impl_shader_dir(impl)], PARAMS_INCLUDES)
    return load_shader(KERNEL_WGSL, None, "wgsl", [impl_shader_dir(impl)], PARAMS_INCLUDES)


def explain_error(src: ShaderSource, message: str) -> str:
    """A compiler log as ``file:line: message`` lines of the original files (the includes resolved)."""
    pattern = _LINE[src.lang]
    out = [src.format_error(int(m.group(1)), text.strip()) for text in message.splitlines()
           if (m := pattern.search(text))]
    return "\n".join(out) if out else f"{src.filename}: {message.strip()}"
