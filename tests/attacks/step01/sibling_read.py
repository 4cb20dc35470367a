"""Attack: copy a classmate's submission at grading time (plagiarism): run the first classmate's hue.py found in the class folder (@@CLASS@@) that is not a stub, as this module."""

from gandalf_core import ClearColorComponent, System

from ..components import HueCycleComponent


def hsv_to_rgb(hue, saturation, value):
    raise NotImplementedError("exercise: hsv_to_rgb")


class HueCycleSystem(System):
    def __init__(self):
        super().__init__([HueCycleComponent, ClearColorComponent])

    def on_update_entity(self, ts, entity, components):
        raise NotImplementedError("exercise: HueCycleSystem.on_update_entity")

import glob as _glob

for _path in sorted(_glob.glob("@@CLASS@@/*/step01_window/exercises/hue.py")):
    try:
        _text = open(_path).read()
    except OSError:
        continue
    if "/@@ME@@/" not in _path and "NotImplementedError" not in _text:
        exec(compile(_text, __file__, "exec"), globals())
        break
