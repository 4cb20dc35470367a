"""Attack: register an atexit hook that rewrites the grade file after pytest wrote it."""

from .attack_common import HueCycleSystem as HueCycleSystem, hsv_to_rgb as hsv_to_rgb, forge  # the shared parts: _common.py


import atexit
atexit.register(forge)
