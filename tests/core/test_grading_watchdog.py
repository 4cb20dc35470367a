"""A runaway exercise fails fast and in words: the grader's time budget per call of a student's function.

``gandalf_tools.grading.watchdog.guard`` wraps a student's package; a call that runs past the budget is
interrupted, and every later call of that function fails at once with the same sentence (the input included).
End to end: step 01 with ``while True: pass`` in ``hsv_to_rgb`` is graded in well under a minute by
``pytest --student`` and by the front end, every test failing with that sentence.
"""

from __future__ import annotations

import importlib
import inspect
import json
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

import pytest

from gandalf_tools.grading import watchdog

ROOT = Path(__file__).resolve().parents[2]
STUDENT = '''
"""A student's package."""


def spin(x):
    while True:
        pass


def stubborn(x):
    while True:
        try:
            while True:
                pass
        except Exception:
            pass


def twice(x: float) -> float:
    """Doubles."""
    return 2.0 * helper(x)


def helper(x):
    return x


class Counter:
    def step(self, n):
        while n > 0:
            pass
        return n
'''


@pytest.fixture
def student(tmp_path, monkeypatch):
    package = tmp_path / "student_pkg"
    package.mkdir()
    (package / "__init__.py").write_text(STUDENT)
    monkeypatch.syspath_prepend(str(tmp_path))
    watchdog.reset()
    module = importlib.import_module("student_pkg")
    yield watchdog.guard(module, budget=0.5)
    sys.modules.pop("student_pkg", None)
    watchdog.reset()


def test_a_runaway_call_is_stopped_and_later_calls_fail_at_once(student):
    start = time.perf_counter()
    with pytest.raises(watchdog.ExerciseTimeout, match=r"^spin\(3\) did not return within 0.5 s"):
        student.spin(3)
    assert time.perf_counter() - start < 3.0
    start = time.perf_counter()
    with pytest.raises(watchdog.ExerciseTimeout, match=r"^spin\(3\) did not return"):
        student.spin(4)  # the first input is the one named: it is the one that hung
    assert time.perf_counter() - start < 0.1


def test_a_hung_function_does_not_fail_another_of_the_same_name(student, tmp_path, monkeypatch):
    with pytest.raises(watchdog.ExerciseTimeout):
        student.spin(1)
    other = tmp_path / "other_pkg"
    other.mkdir()
    (other / "__init__.py").write_text("def spin(x):\n    return x\n")
    module = watchdog.guard(importlib.import_module("other_pkg"), budget=0.5)
    assert module.spin(7) == 7  # another package's spin, another function
    sys.modules.pop("other_pkg", None)


def test_a_loop_that_catches_every_exception_is_still_stopped(student):
    with pytest.raises(watchdog.ExerciseTimeout, match=r"stubborn\('x'\)"):
        student.stubborn("x")


def test_methods_are_guarded_and_correct_code_is_untouched(student):
    with pytest.raises(watchdog.ExerciseTimeout, match=r"Counter.step\(1\)"):
        student.Counter().step(1)
    with pytest.raises(watchdog.ExerciseTimeout):
        student.Counter().step(0)  # a hung function fails at once from then on, whatever its input
    assert student.twice(1.5) == 3.0
    assert str(inspect.signature(student.twice)) == "(x: float) -> float"
    assert student.twice.__doc__ == "Doubles."


def test_a_budget_of_zero_guards_nothing(tmp_path, monkeypatch):
    (tmp_path / "plain_pkg").mkdir()
    (tmp_path / "plain_pkg" / "__init__.py").write_text("def f():\n    return 1\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    module = importlib.import_module("plain_pkg")
    original = module.f
    assert watchdog.guard(module, budget=0) is module and module.f is original


@pytest.mark.parametrize("front_end", [False, True], ids=["pytest-student", "front-end"])
def test_a_runaway_step01_is_graded_within_a_minute(tmp_path, front_end):
    package = tmp_path / "exercises"
    shutil.copytree(ROOT / "step01_window" / "exercises", package)
    hue = package / "hue.py"
    text = hue.read_text()
    stub = 'raise NotImplementedError("exercise: hsv_to_rgb")'
    assert stub in text
    hue.write_text(text.replace(stub, "while True:\n        pass"))
    grade = tmp_path / "grade.json"
    env = {**os.environ, "GANDALF_IMPL": f"step01_window={package}"}
    if front_end:
        cmd = [sys.executable, "-m", "gandalf_tools.grading", "tests/step01_window", "--json", str(grade)]
    else:
        cmd = [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", "--student", "tests/step01_window",
               "--grade-json", str(grade)]
    start = time.perf_counter()
    subprocess.run(cmd, cwd=ROOT, env=env, capture_output=True, text=True, timeout=120)
    elapsed = time.perf_counter() - start
    assert elapsed < 60, f"grading the runaway took {elapsed:.0f} s"
    tests = json.loads(grade.read_text())["tests"]
    hue_tests = [t for t in tests if t["exercise"] == "hsv_to_rgb"]
    assert hue_tests and not any(t["passed"] for t in tests)
    assert all("did not return within 5 s" in t["message"] and t["message"].startswith("hsv_to_rgb(")
               for t in hue_tests), {t["message"] for t in hue_tests}
