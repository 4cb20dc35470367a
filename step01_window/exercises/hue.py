"""Exercise: animate the clear colour through the hues.

1. ``hsv_to_rgb(hue, saturation, value)``: convert an HSV colour to RGB.
2. ``HueCycleSystem``: every frame, advance each entity's hue by ``speed * ts`` degrees (wrapping to
   [0, 360)) and write the matching RGB colour into its ClearColorComponent.
"""

from __future__ import annotations

from gandalf_core import ClearColorComponent, System

from ..components import HueCycleComponent


def hsv_to_rgb(hue: float, saturation: float, value: float) -> tuple[float, float, float]:
    """RGB in [0, 1] for ``hue`` in degrees (any real number; 360 wraps to 0), saturation and value in [0, 1].

    Hint: split the hue circle into six 60° sectors; in each, one channel is ``value``, one is the
    minimum ``value * (1 - saturation)`` and one ramps between them.
    """
    raise NotImplementedError("exercise: hsv_to_rgb")


class HueCycleSystem(System):
    """Runs over entities with a HueCycleComponent and a ClearColorComponent."""

    def __init__(self) -> None:
        super().__init__([HueCycleComponent, ClearColorComponent])

    def on_update_entity(self, ts, entity, components) -> None:
        hue_cycle, clear_color = components
        raise NotImplementedError("exercise: HueCycleSystem.on_update_entity")
