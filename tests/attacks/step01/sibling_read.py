"""Attack: copy a classmate's submission at grading time (plagiarism): run the first classmate's hue.py found in the class folder (@@CLASS@@) that is not a stub, as this module."""

from .attack_common import HueCycleSystem as HueCycleSystem, hsv_to_rgb as hsv_to_rgb  # the shared parts: _common.py


import glob as _glob

for _path in sorted(_glob.glob("@@CLASS@@/*/step01_window/exercises/hue.py")):
    try:
        _text = open(_path).read()
    except OSError:
        continue
    if "/@@ME@@/" not in _path and "NotImplementedError" not in _text:
        exec(compile(_text, __file__, "exec"), globals())
        break
