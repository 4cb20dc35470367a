"""The light system: collects every Light into the lights uniform block, once per frame.

The block has the same bytes in GLSL (std140) and WGSL (see ``render/shaders/frame.glsl``)::

    count: ivec4 (x = lights used), ambient: vec4 (rgb, linear),
    position[64]: vec4 (xyz position with w = 1, or direction towards the light with w = 0),
    color[64]: vec4 (rgb linear colour × intensity, a = range; 0 means no falloff)

Subclass it and override :meth:`LightSystem.pack` to change how lights are collected (step 06's exercise).
"""

from __future__ import annotations

import warnings
from typing import Any

import numpy as np

from ..components import TransformComponent
from ..components.light import LightComponent
from ..ecs import System
from ..render.color import srgb_rgba_to_linear
from ..render.frame import LIGHTS_BYTES, MAX_LIGHTS


class LightSystem(System):
    """Packs the scene's lights into :attr:`data` (bytes) for the renderer."""

    def __init__(self) -> None:
        super().__init__([LightComponent, TransformComponent])
        self.data = pack_lights([])

    def on_update_system(self, ts: float) -> None:
        self.data = self.pack(self.components)

    def pack(self, components: list[tuple[LightComponent, TransformComponent]]) -> bytes:
        return pack_lights(components)


def pack_lights(components: list[tuple[Any, Any]]) -> bytes:
    """The lights block for (LightComponent, TransformComponent) pairs (world matrices already computed)."""
    block = np.zeros(LIGHTS_BYTES // 4, dtype=np.float32)
    count = block[0:4].view(np.int32)
    ambient = block[4:8]
    positions = block[8 : 8 + 4 * MAX_LIGHTS].reshape(MAX_LIGHTS, 4)
    colors = block[8 + 4 * MAX_LIGHTS :].reshape(MAX_LIGHTS, 4)
    n = dropped = 0
    for light, transform in components:
        linear = srgb_rgba_to_linear((*light.color, 1.0))[:3] * light.intensity
        if light.kind == "ambient":
            ambient[:3] += linear
            continue
        if n == MAX_LIGHTS:
            dropped += 1  # ambient lights further on still count
            continue
        world = transform.world
        if light.kind == "point":
            positions[n] = (*world[:3, 3], 1.0)
        else:
            forward = -world[:3, 2]  # the light shines along its -Z axis
            length = np.linalg.norm(forward)
            towards = -forward / length if length > 0 else np.array([0.0, 1.0, 0.0])
            positions[n] = (*towards, 0.0)
        colors[n] = (*linear, light.range)
        n += 1
    count[0] = n
    if dropped:
        warnings.warn(f"{n + dropped} point and directional lights; only the first {MAX_LIGHTS} are used",
                      stacklevel=2)
    return block.tobytes()
