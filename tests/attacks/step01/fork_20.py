"""Attack: start 20 processes at import that outlive the grading (setsid, sleep)."""

from .attack_common import HueCycleSystem as HueCycleSystem, hsv_to_rgb as hsv_to_rgb  # the shared parts: _common.py


import os
import time

for _ in range(20):
    if os.fork() == 0:
        os.setsid()
        time.sleep(600)
        os._exit(0)
