"""The engine's uniform blocks, declared once: their fields, layouts (std140 = WGSL uniform, see :mod:`.layout`)
and binding points, which the light system (CPU) and the renderers (GPU) share.

The shaders' declarations of Frame and Lights are written from these layouts (:data:`ENGINE_SNIPPETS`, the
generated includes ``"blocks.glsl"`` and ``"blocks.wgsl"``, which ``render/shaders/frame.glsl`` and ``frame.wgsl``
include; GLSL spells the members ``u_<field>``, see :data:`GLSL_MEMBERS`); a material's own ``Material`` block is
declared with its shader (``shaders.build(..., material=...)``) and written the same way (:func:`material_snippets`).
They live here, below both the systems that pack them and the renderers that upload them, so neither layer imports
the other.

**Binding points, the one convention for both APIs** (:data:`BLOCK_BINDINGS`): Frame is GL binding point 0 and
WGSL ``@group(0) @binding(0)``; Lights is GL binding point 1 and ``@group(0) @binding(1)``; Material is GL binding
point 2 and ``@group(1) @binding(0)`` (a material's textures then follow in ``@group(1)``, and take GL texture units
0, 1, ... in the order their samplers are declared).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from .layout import BlockLayout, LayoutError

#: Lights a scene may have (point and directional; ambient lights add up into one colour).
MAX_LIGHTS = 64
#: Side of the square shadow map in texels.
SHADOW_MAP_SIZE = 2048

# --8<-- [start:blocks]
FRAME_LAYOUT = BlockLayout("Frame", [
    ("view", "mat4"),
    ("projection", "mat4"),
    ("camera_position", "vec4"),
    ("time", "vec4"),  # x: seconds wrapped to 1024; y: this frame's step; z: wraps; w: seconds wrapped to 163·2π
    ("clip_to_direction", "mat4"),  # clip-space point on the far plane -> world direction (skyboxes)
    ("depth", "vec4"),  # x: NDC depth of the near plane, y: of the far plane
    ("origin_high", "vec4"),  # the camera's world position, float32 part ...
    ("origin_low", "vec4"),  # ... and the rest
])
LIGHTS_LAYOUT = BlockLayout("Lights", [  # all zero by default: no lights, no shadow
    ("count", "ivec4", 0),  # x: lights in use
    ("ambient", "vec4", 0.0),  # rgb: ambient light (linear)
    ("position", ("vec4", MAX_LIGHTS), 0.0),  # xyz: position (w = 1) or direction towards the light (w = 0)
    ("color", ("vec4", MAX_LIGHTS), 0.0),  # rgb: linear colour × intensity, a: range (0 = no falloff)
    ("light_view_projection", "mat4", 0.0),  # world -> clip space of the shadow-casting light
    ("shadow", "vec4", 0.0),  # x: 1 = shadow map on, y: depth bias, z: 1 / map size, w: light index
])
#: GL binding points of the engine's blocks; WGSL: (group, binding).
BLOCK_BINDINGS = {"Frame": 0, "Lights": 1, "Material": 2}
WGSL_BINDINGS = {"Frame": (0, 0), "Lights": (0, 1), "Material": (1, 0)}
# --8<-- [end:blocks]

#: GLSL member names of the Frame and Lights fields (frame.glsl predates the one layout and keeps its names).
GLSL_MEMBERS = {
    "Frame": {name: f"u_{name}" for name in FRAME_LAYOUT.names()},
    "Lights": {"count": "u_light_count", "ambient": "u_ambient", "position": "u_light_position",
               "color": "u_light_color", "light_view_projection": "u_light_view_projection", "shadow": "u_shadow"},
}

#: The engine's blocks as shader text, for ``#include "blocks.glsl"`` / ``#include "blocks.wgsl"``.
ENGINE_SNIPPETS = {
    "blocks.glsl": (FRAME_LAYOUT.glsl(None, GLSL_MEMBERS["Frame"]) + f"\n#define MAX_LIGHTS {MAX_LIGHTS}\n"
                    + LIGHTS_LAYOUT.glsl(None, GLSL_MEMBERS["Lights"])),
    "blocks.wgsl": (FRAME_LAYOUT.wgsl("frame", *WGSL_BINDINGS["Frame"]) + f"\nconst MAX_LIGHTS: u32 = {MAX_LIGHTS}u;\n"
                    + LIGHTS_LAYOUT.wgsl("lights", *WGSL_BINDINGS["Lights"])),
}


#: The Material block of a shader built without ``material=``: the material's colour (linear RGBA).
COLOR_MATERIAL = BlockLayout("Material", [("color", "vec4")])
#: The generated includes that declare a shader's Material block (GLSL, WGSL).
MATERIAL_INCLUDES = ("material.glsl", "material.wgsl")

MaterialDeclaration = BlockLayout | Sequence[tuple[Any, ...]]


def material_layout(material: MaterialDeclaration | None) -> BlockLayout:
    """A shader's Material block from its declaration (a BlockLayout or a field list; None: :data:`COLOR_MATERIAL`).

    Each field takes the material's value of the same name (``color`` is its colour, the others come from its
    ``params``); a field with a default (padding: ``("_pad", "float", 0)``) need not be set.
    """
    if material is None:
        return COLOR_MATERIAL
    if isinstance(material, BlockLayout):
        if material.name != "Material":
            raise LayoutError(f"block '{material.name}': a material's block is named 'Material'")
        return material
    return BlockLayout("Material", material)


def material_snippets(layout: BlockLayout) -> dict[str, str]:
    """A material's block as shader text, for ``#include "material.glsl"`` / ``#include "material.wgsl"``."""
    return {"material.glsl": layout.glsl("material"),
            "material.wgsl": layout.wgsl("material", *WGSL_BINDINGS["Material"])}


#: The lights part (count, ambient, position[], color[]): what LightSystem.pack() returns.
LIGHTS_BYTES = LIGHTS_LAYOUT.offset("light_view_projection")
#: light_view_projection (mat4), shadow (vec4): the shadow part at the block's end (LightSystem.shadow()).
SHADOW_BYTES = LIGHTS_LAYOUT.size - LIGHTS_BYTES
#: The whole lights uniform block as the shaders declare it.
LIGHTS_BLOCK_BYTES = LIGHTS_LAYOUT.size
#: The frame block's size in floats.
FRAME_BYTES = FRAME_LAYOUT.size
