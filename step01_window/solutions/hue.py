"""Reference solution: HSV to RGB and the hue-cycling system."""

from __future__ import annotations

import math

from gandalf_core import ClearColorComponent, System

from ..components import HueCycleComponent


def hsv_to_rgb(hue: float, saturation: float, value: float) -> tuple[float, float, float]:
    """RGB in [0, 1] for ``hue`` in degrees (any real number), saturation and value in [0, 1]."""
    h = math.fmod(hue, 360.0)
    if h < 0:
        h += 360.0
    sector = h / 60.0
    chroma = value * saturation
    x = chroma * (1.0 - abs(math.fmod(sector, 2.0) - 1.0))
    r, g, b = [
        (chroma, x, 0.0), (x, chroma, 0.0), (0.0, chroma, x),
        (0.0, x, chroma), (x, 0.0, chroma), (chroma, 0.0, x),
    ][min(int(sector), 5)]
    m = value - chroma
    return (r + m, g + m, b + m)


class HueCycleSystem(System):
    """Advances the hue by ``speed * ts`` and writes the colour into the ClearColorComponent."""

    def __init__(self) -> None:
        super().__init__([HueCycleComponent, ClearColorComponent])

    def on_update_entity(self, ts, entity, components) -> None:
        hue_cycle, clear_color = components
        hue_cycle.hue = math.fmod(hue_cycle.hue + hue_cycle.speed * ts, 360.0)
        if hue_cycle.hue < 0:
            hue_cycle.hue += 360.0
        clear_color.color = hsv_to_rgb(hue_cycle.hue, hue_cycle.saturation, hue_cycle.value)
