"""Attack: allocate 4 GiB at import."""

from gandalf_core import ClearColorComponent, System

from ..components import HueCycleComponent


def hsv_to_rgb(hue, saturation, value):
    raise NotImplementedError("exercise: hsv_to_rgb")


class HueCycleSystem(System):
    def __init__(self):
        super().__init__([HueCycleComponent, ClearColorComponent])

    def on_update_entity(self, ts, entity, components):
        raise NotImplementedError("exercise: HueCycleSystem.on_update_entity")

_hog = bytearray(4 * 2**30)
