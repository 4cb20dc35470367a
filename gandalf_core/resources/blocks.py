"""The sizes of the engine's uniform blocks, which the light system (CPU) and the renderers (GPU) share.

The blocks hold only mat4/vec4 members and vec4 arrays, so their bytes are the same in GLSL's std140 and WGSL's
uniform layout (``render/shaders/frame.glsl`` / ``frame.wgsl`` declare them). They live here, below both the
systems that pack them and the renderers that upload them, so neither layer imports the other.
"""

from __future__ import annotations

#: Lights a scene may have (point and directional; ambient lights add up into one colour).
MAX_LIGHTS = 64
#: count (ivec4), ambient, position[MAX_LIGHTS], color[MAX_LIGHTS]: what LightSystem.pack() returns.
LIGHTS_BYTES = 16 + 16 + 16 * MAX_LIGHTS * 2
#: light_view_projection (mat4), shadow (vec4): the shadow part at the block's end (LightSystem.shadow()).
SHADOW_BYTES = 64 + 16
#: The whole lights uniform block as the shaders declare it.
LIGHTS_BLOCK_BYTES = LIGHTS_BYTES + SHADOW_BYTES
#: Side of the square shadow map in texels.
SHADOW_MAP_SIZE = 2048
