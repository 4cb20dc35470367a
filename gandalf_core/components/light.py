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
    """A point, directional or ambient light; every field is checked whenever it is set."""

    def __init__(self, kind: str = "point", color: Sequence[float] = (1.0, 1.0, 1.0), intensity: float = 1.0,
                 range: float = 0.0) -> None:
        self.kind = kind
        self.color = color
        self.intensity = intensity
        self.range = range

    @property
    def kind(self) -> str:
        return self._kind

    @kind.setter
    def kind(self, value: str) -> None:
        if value not in LIGHT_KINDS:
            raise ValueError(f"LightComponent.kind must be one of {LIGHT_KINDS}, got {value!r}")
        self._kind = value

    @property
    def color(self) -> np.ndarray:
        return self._color

    @color.setter
    def color(self, value: Sequence[float]) -> None:
        rgb = np.asarray(value, dtype=np.float64).ravel()
        if rgb.shape != (3,) or not np.all(np.isfinite(rgb)) or np.any(rgb < 0):
            raise ValueError(f"LightComponent.color must be 3 non-negative finite floats, got {value!r}")
        self._color = rgb

    @property
    def intensity(self) -> float:
        return self._intensity

    @intensity.setter
    def intensity(self, value: float) -> None:
        if not (math.isfinite(value) and value >= 0):
            raise ValueError(f"LightComponent.intensity must be a non-negative number, got {value!r}")
        self._intensity = float(value)

    @property
    def range(self) -> float:
        return self._range

    @range.setter
    def range(self, value: float) -> None:
        if not (math.isfinite(value) and value >= 0):
            raise ValueError(f"LightComponent.range must be a non-negative number (0 = no falloff), got {value!r}")
        self._range = float(value)

    def __repr__(self) -> str:
        return (f"LightComponent({self.kind!r}, color={self.color.tolist()}, intensity={self.intensity}, "
                f"range={self.range})")
