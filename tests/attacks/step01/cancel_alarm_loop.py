"""Attack: cancel the per-test alarm (setitimer(0), SIG_IGN), then loop for ever in every call."""

from .attack_common import HueCycleSystem as HueCycleSystem, hsv_to_rgb as hsv_to_rgb  # the shared parts: _common.py


import signal


def hsv_to_rgb(hue, saturation, value):  # noqa: F811
    signal.setitimer(signal.ITIMER_REAL, 0)
    signal.signal(signal.SIGALRM, signal.SIG_IGN)
    while True:
        try:
            pass
        except BaseException:
            pass
