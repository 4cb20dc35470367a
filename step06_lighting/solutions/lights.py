"""Reference solution: the light-collection system that packs the lights uniform block."""

from __future__ import annotations

import warnings

import numpy as np

from gandalf_core.render.frame import LIGHTS_BYTES, MAX_LIGHTS
from gandalf_core.resources import srgb_to_linear
from gandalf_core.systems.light_system import LightSystem


class LightCollectionSystem(LightSystem):
    """Packs (LightComponent, TransformComponent) pairs; the render system uploads :attr:`data` each frame."""

    def pack(self, components) -> bytes:
        """The lights block (``LIGHTS_BYTES`` bytes) for the pairs in ``components``."""
        block = np.zeros(LIGHTS_BYTES // 4, dtype=np.float32)
        ambient = np.zeros(3)
        positions = np.zeros((MAX_LIGHTS, 4))
        colors = np.zeros((MAX_LIGHTS, 4))
        count = 0
        for light, transform in components:
            radiance = srgb_to_linear(np.asarray(light.color, dtype=np.float64)) * light.intensity
            if light.kind == "ambient":
                ambient += radiance
                continue
            if count == MAX_LIGHTS:
                warnings.warn(f"more than {MAX_LIGHTS} lights: the rest are ignored", stacklevel=2)
                break
            world = transform.world
            if light.kind == "point":
                positions[count] = (*world[:3, 3], 1.0)
            else:
                towards = world[:3, 2]  # the light shines along -Z, so +Z points back towards it
                length = np.linalg.norm(towards)
                positions[count, :3] = towards / length if length > 0 else (0.0, 1.0, 0.0)
            colors[count] = (*radiance, light.range)
            count += 1
        block[0:4].view(np.int32)[0] = count
        block[4:7] = ambient
        block[8 : 8 + 4 * MAX_LIGHTS] = positions.ravel()
        block[8 + 4 * MAX_LIGHTS :] = colors.ravel()
        return block.tobytes()
