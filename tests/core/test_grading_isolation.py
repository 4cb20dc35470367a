"""The grader survives runaway and crashing student code, and writes Gradescope's format.

Most tests write a tiny fake step (``fakestep``: an ``exercises`` package with an infinite loop, an
``os._exit(3)`` and a hang that no signal reaches, and ``solutions``) plus its graded tests into
``tmp_path`` and runs ``python -m gandalf_tools.grading`` on it in a subprocess: the runaway tests fail
with their own message and every other test is still graded. The last one makes step 01's reference
system loop forever in the first frame of an OpenGL app: pytest-timeout's signal method fails that test and
the same worker renders the next ones correctly.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from gandalf_tools.grading import sandbox

ROOT = Path(__file__).resolve().parents[2]

EXERCISES = """
import os
import signal
import time


def add(a, b):
    return a + b


def spin():
    while True:  # a runaway loop: pytest-timeout's signal fails the test in place
        pass


def die():
    os._exit(3)  # takes its process down: only the worker dies


def hang():
    # Stands for a hang inside native code (a driver call): the alarm signal never reaches Python.
    signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGALRM})
    time.sleep(120)
"""

SOLUTIONS = """
def add(a, b):
    return a + b


def spin():
    return 1


def die():
    return 1


def hang():
    return 1
"""

TESTS = """
import pytest


@pytest.mark.exercise("add")
def test_add(impl):
    assert impl.add(1, 2) == 3


@pytest.mark.exercise("add")
def test_add_negative(impl):
    assert impl.add(-1, -2) == -3


@pytest.mark.exercise("spin")
def test_spin(impl):
    assert impl.spin() == 1


@pytest.mark.exercise("die")
def test_die(impl):
    assert impl.die() == 1


@pytest.mark.exercise("hang")
def test_hang(impl):
    assert impl.hang() == 1


@pytest.mark.exercise("after", points=2)
def test_after_the_crashes(impl):
    assert impl.add(2, 2) == 4, "add(2, 2): expected 4"
"""


def _fake_step(tmp_path: Path) -> Path:
    for name, text in {
        "fakestep/__init__.py": "",
        "fakestep/exercises/__init__.py": EXERCISES,
        "fakestep/solutions/__init__.py": SOLUTIONS,
        "grading_tests/fakestep/conftest.py": (
            "from gandalf_tools.grading.plugin import impl_fixture\n\nimpl = impl_fixture('fakestep')\n"
        ),
        "grading_tests/fakestep/test_fake.py": TESTS,
    }.items():
        path = tmp_path / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(textwrap.dedent(text))
    return tmp_path / "grading_tests" / "fakestep"


def _grade(tmp_path: Path, *args: str, timeout: float = 120) -> tuple[subprocess.CompletedProcess, dict]:
    tests = _fake_step(tmp_path)
    out = tmp_path / "grade.json"
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(tmp_path), str(ROOT)])}
    env.pop("GANDALF_IMPL", None)
    proc = subprocess.run(
        [sys.executable, "-m", "gandalf_tools.grading", str(tests), "--json", str(out), *args],
        cwd=tmp_path,
        env=env,
        capture_output=True,
        text=True,
        timeout=timeout,
    )
    assert out.exists(), f"no grade written (exit {proc.returncode}):\n{proc.stdout[-3000:]}\n{proc.stderr[-3000:]}"
    return proc, json.loads(out.read_text())


def _by_test(result: dict) -> dict[str, dict]:
    return {t["test"].split("::")[-1]: t for t in result["tests"]}


def test_timeout_and_crash_fail_their_own_tests_in_workers(tmp_path):
    gradescope = tmp_path / "results" / "results.json"
    proc, result = _grade(
        tmp_path, "--jobs", "1", "--timeout", "2", "--hard-timeout", "5", "--gradescope", str(gradescope)
    )
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    tests = _by_test(result)
    names = {"test_add", "test_add_negative", "test_spin", "test_die", "test_hang", "test_after_the_crashes"}
    assert set(tests) == names
    assert tests["test_add"]["passed"] and tests["test_add_negative"]["passed"]
    assert tests["test_after_the_crashes"]["passed"], tests["test_after_the_crashes"]
    assert not tests["test_spin"]["passed"] and "Timeout" in tests["test_spin"]["message"]
    # The student's code runs in a sandboxed process: os._exit ends that process only, and a hang that blocks the
    # alarm signal there cannot block it here (the test's time limit fails it; the next call gets a fresh process).
    assert not tests["test_die"]["passed"] and "die() ended its process" in tests["test_die"]["message"]
    assert not tests["test_hang"]["passed"] and "Timeout" in tests["test_hang"]["message"]
    assert result["earned"] == pytest.approx(3.0) and result["possible"] == pytest.approx(6.0)

    # Gradescope: a test per graded test, each exercise's points spread over its tests.
    gs = json.loads(gradescope.read_text())
    assert gs["score"] == pytest.approx(3.0)
    assert {"score", "tests", "execution_time", "stdout_visibility", "visibility"} <= set(gs)
    assert sum(t["max_score"] for t in gs["tests"]) == pytest.approx(6.0)
    assert sum(t["score"] for t in gs["tests"]) == pytest.approx(gs["score"])
    for t in gs["tests"]:
        assert {"name", "score", "max_score", "output", "visibility", "status"} <= set(t)
        assert (t["status"] == "failed") == bool(t["output"]), t
    add = [t for t in gs["tests"] if "add" in t["tags"]]
    assert [t["max_score"] for t in add] == [pytest.approx(0.5)] * 2


def test_timeout_in_process_without_workers(tmp_path):
    # --jobs 0: no worker to lose, so only the signal timeout (the os._exit test is left out here).
    proc, result = _grade(tmp_path, "--jobs", "0", "--timeout", "2", "-k", "not die and not hang")
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    tests = _by_test(result)
    assert not tests["test_spin"]["passed"] and "Timeout" in tests["test_spin"]["message"]
    assert tests["test_after_the_crashes"]["passed"] and tests["test_add"]["passed"]
    assert result["earned"] == pytest.approx(3.0) and result["possible"] == pytest.approx(4.0)


def test_fail_under_turns_the_score_into_an_exit_status(tmp_path):
    proc, _ = _grade(tmp_path, "--jobs", "0", "-k", "add or after", "--fail-under", "100")
    assert proc.returncode == 0, proc.stdout[-2000:]
    proc, _ = _grade(tmp_path, "--jobs", "0", "--timeout", "2", "-k", "add or spin", "--fail-under", "100")
    assert proc.returncode == 1 and "below 100%" in proc.stdout, proc.stdout[-2000:]


SPIN_ONCE = """

_spun = []
_original_update = HueCycleSystem.on_update_entity


def _update_that_spins_once(self, ts, entity, components):
    if not _spun:  # the first update of the run never returns: a runaway loop inside a rendering app's frame
        _spun.append(1)
        while True:
            pass
    return _original_update(self, ts, entity, components)


HueCycleSystem.on_update_entity = _update_that_spins_once
"""


def test_a_timeout_inside_a_rendering_frame_leaves_the_gpu_usable(tmp_path):
    # The signal method interrupts the loop inside an OpenGL app's frame; the same worker then renders the
    # next tests correctly (the thread method would have ended the worker instead). The loop runs in this process
    # (--grade-in-process): a sandboxed student's process would start afresh, and spin again, after it.
    package = tmp_path / "spin"
    shutil.copytree(ROOT / "step01_window" / "solutions", package, ignore=shutil.ignore_patterns("__pycache__"))
    (package / "__init__.py").write_text((package / "__init__.py").read_text() + SPIN_ONCE)
    out = tmp_path / "grade.json"
    env = {k: v for k, v in os.environ.items() if k != "GANDALF_IMPL"}
    proc = subprocess.run(
        [sys.executable, "-m", "gandalf_tools.grading", "tests/step01_window", "--impl", f"step01_window={package}"]
        + ["--timeout", "5", "--json", str(out), "--grade-only", "HueCycleSystem", "-k", "opengl or each_entity"]
        + ["--grade-in-process"],
        cwd=ROOT,
        env=env,
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert proc.returncode == 0 and out.exists(), proc.stdout[-3000:] + proc.stderr[-3000:]
    tests = _by_test(json.loads(out.read_text()))
    first = tests["test_clear_colour_follows_the_hue_in_pixels[opengl-1]"]
    assert not first["passed"] and "Timeout" in first["message"], first
    others = {name: t for name, t in tests.items() if name != "test_clear_colour_follows_the_hue_in_pixels[opengl-1]"}
    assert len(others) == 3 and all(t["passed"] for t in others.values()), others


def test_a_grade_made_without_namespaces_says_so_loudly(tmp_path, monkeypatch):
    # Where the machine allows no namespaces the student's process could forge the grade: the grade files, Gradescope's
    # results (its output and extra_data) and the console say so; where it allows them, none of them warns.
    monkeypatch.setenv(sandbox.ISOLATION_ENV, "process")
    gradescope = tmp_path / "results" / "results.json"
    proc, result = _grade(tmp_path, "--jobs", "0", "-k", "add", "--gradescope", str(gradescope))
    assert result["isolation"] == "process" and result["isolation_warning"].startswith("WARNING: NOT ISOLATED")
    assert f"${sandbox.ISOLATION_ENV}=process asked for it" in result["isolation_warning"]
    assert proc.stdout.count("WARNING: NOT ISOLATED") == 2, proc.stdout[-3000:]  # before the table and after it
    gs = json.loads(gradescope.read_text())
    assert gs["output"].startswith("WARNING: NOT ISOLATED") and gs["extra_data"]["isolation"] == "process"
    assert result["earned"] == pytest.approx(1.0)  # the grade itself is made the same way

    monkeypatch.delenv(sandbox.ISOLATION_ENV)
    if sandbox.isolation() == "process":
        return  # this machine has no namespaces: nothing to compare with
    proc, result = _grade(tmp_path, "--jobs", "0", "-k", "add", "--gradescope", str(gradescope))
    assert result["isolation"] != "process" and "isolation_warning" not in result
    assert "NOT ISOLATED" not in proc.stdout and "NOT ISOLATED" not in gradescope.read_text()


def test_the_gradebook_flags_each_grade_made_without_namespaces(tmp_path, monkeypatch):
    import csv

    from gandalf_tools.grading import batch

    monkeypatch.setenv(sandbox.ISOLATION_ENV, "process")
    warning = sandbox.isolation_warning("process")
    exercise = {"step": "step01_window", "exercise": "hsv_to_rgb", "earned": 1.0, "possible": 1.0, "passed": 3,
                "tests": 3}
    flagged = batch.Graded("alice", ["step01_window"], result={
        "earned": 1.0, "possible": 1.0, "score": 1.0, "exercises": [exercise], "tests": [], "isolation": "process",
        "isolation_warning": warning})
    kept = batch.Graded("bob", ["step01_window"], result={
        "earned": 1.0, "possible": 1.0, "score": 1.0, "exercises": [exercise], "tests": [], "isolation": "user+mount"})
    csv_path, json_path = batch.write_gradebook([flagged, kept], tmp_path)
    rows = {row["student"]: row for row in csv.DictReader(csv_path.open())}
    assert rows["alice"]["isolation"] == "process" and rows["bob"]["isolation"] == "user+mount"
    book = {entry["student"]: entry for entry in json.loads(json_path.read_text())}
    assert book["alice"]["isolation_warning"] == warning and "isolation_warning" not in book["bob"]
    batch.write_report(flagged, tmp_path / "alice.md")
    batch.write_report(kept, tmp_path / "bob.md")
    assert f"**Not isolated:** {warning}" in (tmp_path / "alice.md").read_text()
    assert "Not isolated" not in (tmp_path / "bob.md").read_text()


def test_the_batch_grader_refuses_a_machine_that_cannot_isolate(tmp_path, monkeypatch, capsys):
    """A class graded where the student's code could read the solutions and rewrite the gradebook would get grades
    nobody can defend: the batch grader says why and what to do, and grades nothing unless asked to anyway."""
    from gandalf_tools.grading import batch

    (tmp_path / "class" / "alice").mkdir(parents=True)
    monkeypatch.setenv(sandbox.ISOLATION_ENV, "process")
    assert batch.main([str(tmp_path / "class"), "--out", str(tmp_path / "out"), "--steps", "step01"]) == 2
    said = capsys.readouterr().err
    assert said.startswith("not grading: WARNING: NOT ISOLATED") and "--allow-unisolated" in said, said
    assert "as root" in said and "gandalf_tools.doctor" in said
    assert not (tmp_path / "out" / "gradebook.json").exists()
