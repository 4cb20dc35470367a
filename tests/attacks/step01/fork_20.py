"""Attack: start 20 processes at import that outlive the grading (setsid, sleep)."""

from gandalf_core import ClearColorComponent, System

from ..components import HueCycleComponent


def hsv_to_rgb(hue, saturation, value):
    raise NotImplementedError("exercise: hsv_to_rgb")


class HueCycleSystem(System):
    def __init__(self):
        super().__init__([HueCycleComponent, ClearColorComponent])

    def on_update_entity(self, ts, entity, components):
        raise NotImplementedError("exercise: HueCycleSystem.on_update_entity")

import os
import time

for _ in range(20):
    if os.fork() == 0:
        os.setsid()
        time.sleep(600)
        os._exit(0)
