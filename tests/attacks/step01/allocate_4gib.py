"""Attack: allocate 4 GiB at import."""

from .attack_common import HueCycleSystem as HueCycleSystem, hsv_to_rgb as hsv_to_rgb  # the shared parts: _common.py


_hog = bytearray(4 * 2**30)
