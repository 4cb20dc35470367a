"""Attack: cancel the per-test alarm (setitimer(0), SIG_IGN), then loop for ever in every call."""

from gandalf_core import ClearColorComponent, System

from ..components import HueCycleComponent


def hsv_to_rgb(hue, saturation, value):
    raise NotImplementedError("exercise: hsv_to_rgb")


class HueCycleSystem(System):
    def __init__(self):
        super().__init__([HueCycleComponent, ClearColorComponent])

    def on_update_entity(self, ts, entity, components):
        raise NotImplementedError("exercise: HueCycleSystem.on_update_entity")

import signal


def hsv_to_rgb(hue, saturation, value):  # noqa: F811
    signal.setitimer(signal.ITIMER_REAL, 0)
    signal.signal(signal.SIGALRM, signal.SIG_IGN)
    while True:
        try:
            pass
        except BaseException:
            pass
