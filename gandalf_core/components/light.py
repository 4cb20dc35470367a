"""The Light component: a light source placed by its entity's Transform.

``kind`` is "point" (at the entity's world position), "directional" (shining along the entity's -Z
axis, like a camera looks) or "ambient" (adds to the scene's ambient light). ``color`` is sRGB like
every colour a scene sets; ``intensity`` scales it in linear light. A point light with ``range > 0``
fades smoothly to zero at that distance (windowed inverse-square); ``range = 0`` means no falloff.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from ..ecs import Component

LIGHT_KINDS = ("point", "directional", "ambient")


class LightComponent(Component):
    def __init__(self, kind: str = "point", color: Sequence[float] = (1.0, 1.0, 1.0), intensity: float = 1.0,
                 range: float = 0.0) -> None:
        if kind not in LIGHT_KINDS:
            raise ValueError(f"LightComponent.kind must be one of {LIGHT_KINDS}, got {kind!r}")
        rgb = np.asarray(color, dtype=np.float64).ravel()[:3]
        if rgb.shape != (3,) or not np.all(np.isfinite(rgb)) or np.any(rgb < 0):
            raise ValueError(f"LightComponent.color must be 3 non-negative finite floats, got {color!r}")
        if not (math.isfinite(intensity) and intensity >= 0):
            raise ValueError(f"LightComponent.intensity must be a non-negative number, got {intensity!r}")
        if not (math.isfinite(range) and range >= 0):
            raise ValueError(f"LightComponent.range must be a non-negative number (0 = no falloff), got {range!r}")
        self.kind = kind
        self.color = rgb
        self.intensity = float(intensity)
        self.range = float(range)
