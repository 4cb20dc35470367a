"""The component of step 01: data for a clear colour that cycles through the hues."""

from __future__ import annotations

from gandalf_core import Component


class HueCycleComponent(Component):
    """Hue (degrees) advancing at ``speed`` degrees per second, at fixed saturation and value (HSV)."""

    def __init__(self, hue: float = 0.0, speed: float = 60.0, saturation: float = 0.7, value: float = 0.9) -> None:
        self.hue = hue
        self.speed = speed
        self.saturation = saturation
        self.value = value


