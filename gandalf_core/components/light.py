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

from collections.abc import Sequence

import numpy as np

from ..ecs import Component
from .fields import Color, Number

LIGHT_KINDS = ("point", "directional", "ambient")


class LightComponent(Component):
    """A point, directional or ambient light; every field is checked whenever it is set."""

    color = Color()
    intensity = Number(0.0, low_inclusive=True)
    range = Number(0.0, low_inclusive=True, note="0 = no falloff")
    shadow_extent = Number(0.0, note="half the shadow box's width")
    shadow_depth = Number(0.0, note="the shadow box's length along the light")
    shadow_bias = Number(0.0, low_inclusive=True, note="a scale of the default slope-scaled bias, 1 = default")

    def __init__(self, kind: str = "point", color: Sequence[float] = (1.0, 1.0, 1.0), intensity: float = 1.0,
                 range: float = 0.0, cast_shadows: bool = False, shadow_extent: float = 10.0,
                 shadow_depth: float = 50.0, shadow_bias: float = 1.0) -> None:
        self._cast_shadows = False  # so that the kind check below can consult it
        self._set_fields(kind=kind, color=color, intensity=intensity, range=range, cast_shadows=cast_shadows,
                         shadow_extent=shadow_extent, shadow_depth=shadow_depth, shadow_bias=shadow_bias)

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

    def __repr__(self) -> str:
        bias = f", shadow_bias={self.shadow_bias}" if self.shadow_bias != 1.0 else ""
        shadows = (f", cast_shadows=True, shadow_extent={self.shadow_extent}, shadow_depth={self.shadow_depth}{bias}"
                   if self.cast_shadows else "")
        return (f"LightComponent({self.kind!r}, color={self.color.tolist()}, intensity={self.intensity}, "
                f"range={self.range}{shadows})")
