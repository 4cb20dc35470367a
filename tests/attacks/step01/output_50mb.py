"""Attack: write 50 MB to stdout and stderr at import."""

from .attack_common import HueCycleSystem as HueCycleSystem, hsv_to_rgb as hsv_to_rgb  # the shared parts: _common.py


import sys

for _ in range(50):
    sys.stdout.write('x' * 2**20)
    sys.stderr.write('y' * 2**20)
