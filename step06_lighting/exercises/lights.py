"""Exercise: collect the scene's lights into the bytes of the lights uniform block.

The block (``gandalf_core/render/shaders/frame.glsl``, std140, 16 + 16 + 64·16 + 64·16 bytes)::

    ivec4 count;         x = number of point/directional lights packed (at most MAX_LIGHTS);
                         y, z, w = 0
    vec4  ambient;       rgb = the sum of all ambient lights, a = 0
    vec4  position[64];  point: (world position, 1);
                         directional: (unit direction TOWARDS the light, 0)
    vec4  color[64];     rgb = linear colour × intensity, a = range

* Light colours are sRGB (as a colour picker shows them): decode them to linear light with
  ``gandalf_core.resources.srgb_to_linear`` before multiplying by the intensity.
* A directional light shines along its entity's -Z axis (the third column of the world matrix,
  negated); the block stores the opposite direction, normalised (a zero axis gives (0, 1, 0)).
* Unused slots are zero. Ambient lights do not take a slot. After MAX_LIGHTS lights, warn
  (``warnings.warn``) and ignore the rest.
"""

from __future__ import annotations

from gandalf_core.render.frame import LIGHTS_BYTES, MAX_LIGHTS
from gandalf_core.systems.light_system import LightSystem

__all__ = ["LIGHTS_BYTES", "MAX_LIGHTS", "LightCollectionSystem"]


class LightCollectionSystem(LightSystem):
    """Packs (LightComponent, TransformComponent) pairs; the render system uploads :attr:`data`
    each frame."""

    def pack(self, components) -> bytes:
        """The lights block (``LIGHTS_BYTES`` bytes) for the pairs in ``components``."""
        raise NotImplementedError("exercise: LightCollectionSystem.pack")
