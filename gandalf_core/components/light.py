"""The Light component: a light source placed by its entity's Transform.

``kind`` is "point" (at the entity's world position), "directional" (shining along the entity's -Z
axis, like a camera looks) or "ambient" (adds to the scene's ambient light). ``color`` is sRGB like
every colour a scene sets; ``intensity`` scales it in linear light. A point light with ``range > 0``
fades smoothly to zero at that distance (windowed inverse-square); ``range = 0`` means no falloff.

A directional light may cast shadows (``cast_shadows=True``): the renderer then draws the scene's depth
from the light into a shadow map, over an orthographic box centred on the light's world position,
``2 · shadow_extent`` wide and high across the light's direction and ``shadow_depth`` long along it.
Put the light above the middle of what it should shadow; the box only needs to enclose it.

``shadow_bias`` is a quality knob of the shadow lookup (step 07's shadow study measures it): it scales the
slope-scaled depth bias (1 = the engine's default of 1.5 + 2·tan θ shadow-map texels; less brings shadow acne,
more detaches shadows from their casters, "peter-panning").
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
                 range: float = 0.0, cast_shadows: bool = False, shadow_extent: float = 10.0,
                 shadow_depth: float = 50.0, shadow_bias: float = 1.0) -> None:
        self._cast_shadows = False  # so that the kind check below can consult it
        self.kind = kind
        self.color = color
        self.intensity = intensity
        self.range = range
        self.cast_shadows = cast_shadows
        self.shadow_extent = shadow_extent
        self.shadow_depth = shadow_depth
        self.shadow_bias = shadow_bias

    @property
    def kind(self) -> str:
        return self._kind

    @kind.setter
    def kind(self, value: str) -> None:
        if value not in LIGHT_KINDS:
            raise ValueError(f"LightComponent.kind must be one of {LIGHT_KINDS}, got {value!r}")
        if self._cast_shadows and value != "directional":
            raise ValueError(f"LightComponent.kind: a {value!r} light cannot cast shadows (cast_shadows=True); "
                             "only a directional light can")
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

    @property
    def cast_shadows(self) -> bool:
        return self._cast_shadows

    @cast_shadows.setter
    def cast_shadows(self, value: bool) -> None:
        if not isinstance(value, (bool, np.bool_)):
            raise TypeError(f"LightComponent.cast_shadows must be True or False, got {value!r}")
        if value and self.kind != "directional":
            raise ValueError(f"LightComponent.cast_shadows: only a directional light can cast shadows, "
                             f"this one is {self.kind!r}")
        self._cast_shadows = bool(value)

    @property
    def shadow_extent(self) -> float:
        return self._shadow_extent

    @shadow_extent.setter
    def shadow_extent(self, value: float) -> None:
        if not (math.isfinite(value) and value > 0):
            raise ValueError(f"LightComponent.shadow_extent must be a positive number (half the shadow box's "
                             f"width), got {value!r}")
        self._shadow_extent = float(value)

    @property
    def shadow_depth(self) -> float:
        return self._shadow_depth

    @shadow_depth.setter
    def shadow_depth(self, value: float) -> None:
        if not (math.isfinite(value) and value > 0):
            raise ValueError(f"LightComponent.shadow_depth must be a positive number (the shadow box's length "
                             f"along the light), got {value!r}")
        self._shadow_depth = float(value)

    @property
    def shadow_bias(self) -> float:
        return self._shadow_bias

    @shadow_bias.setter
    def shadow_bias(self, value: float) -> None:
        if isinstance(value, bool) or not (isinstance(value, (int, float, np.floating, np.integer))
                                           and math.isfinite(value) and value >= 0):
            raise ValueError(f"LightComponent.shadow_bias must be a finite number >= 0 (a scale of the default "
                             f"slope-scaled bias, 1 = default), got {value!r}")
        self._shadow_bias = float(value)

    def __repr__(self) -> str:
        bias = f", shadow_bias={self.shadow_bias}" if self.shadow_bias != 1.0 else ""
        shadows = (f", cast_shadows=True, shadow_extent={self.shadow_extent}, shadow_depth={self.shadow_depth}{bias}"
                   if self.cast_shadows else "")
        return (f"LightComponent({self.kind!r}, color={self.color.tolist()}, intensity={self.intensity}, "
                f"range={self.range}{shadows})")
