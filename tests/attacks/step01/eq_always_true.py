"""Attack: return objects whose __eq__ is always true (for the colour, and for the hue the system writes)."""

from gandalf_core import ClearColorComponent, System

from ..components import HueCycleComponent


class _Anything(float):
    def __eq__(self, other):
        return True

    __hash__ = float.__hash__


class _Colour(tuple):
    def __eq__(self, other):
        return True

    __hash__ = tuple.__hash__


def hsv_to_rgb(hue, saturation, value):
    return _Colour((0.25, 0.25, 0.25))  # correct for no tested input


class HueCycleSystem(System):
    def __init__(self):
        super().__init__([HueCycleComponent, ClearColorComponent])

    def on_update_entity(self, ts, entity, components):
        components[0].hue = _Anything(0.0)
