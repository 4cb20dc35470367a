"""Feedback that teaches: every failed graded test shows the student one sentence, the same everywhere.

One graded run of every step's untouched stubs (``python -m gandalf_tools.grading --jobs 2``, as a student or a
platform runs it) and one of a plausible wrong answer per step (``pytest --student -n 2``: a solution copy with one
bug, graded through ``GANDALF_IMPL`` in the sandbox like a submission). Each failed graded test's message must be one
line of at most :data:`~gandalf_tools.grading.feedback.LIMIT` characters naming its function or file; a stub's says
it is a stub and where; a wrong answer's holds the call with its input, the expected value and what came back. The
terminal shows exactly those lines (no worker lines, no tracebacks), Gradescope's ``results.json`` the same words, and
the full tracebacks go to the log file beside the grade.
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

from gandalf_tools.grading import feedback
from gandalf_tools.grading.mutants import Mutant, build, load_mutants

ROOT = Path(__file__).resolve().parents[2]
STEPS = sorted(p.name for p in ROOT.glob("step0*") if (p / "exercises").is_dir())

# One plausible bug per step, as a student would write it: (exercise, file, the solution's text, the bug).
WRONG = {
    "step01_window": ("hsv_to_rgb", "hue.py", "chroma = value * saturation", "chroma = saturation"),
    "step02_triangle": ("interleave", "vertex_data.py", "stride=7 * FLOAT_BYTES", "stride=7"),
    "step03_textures": ("cube_cross_uvs", "uvs.py", "t = 0.5 - centred", "t = 0.5 + centred"),
    "step04_camera": ("perspective", "projection.py", "math.radians(fovy_deg) / 2.0", "fovy_deg / 2.0"),
    "step05_scenegraph": ("semi_implicit_euler_step", "integrators.py", "return x + v_new * dt, v_new",
                          "return x + v * dt, v_new"),
    "step06_lighting": ("reflect_refract", "optics.py", "return i - 2.0 * np.sum", "return i - 1.0 * np.sum"),
}
SHADER_BUG = ("step07_advanced", "blur_kernel", "not-normalised")  # one of the course's shader mutants


def _grade(command: list[str], folder: Path, env: dict[str, str] | None = None) -> dict[str, Any]:
    run = subprocess.run([sys.executable, *command], cwd=ROOT, capture_output=True, text=True, timeout=600,
                         env={**os.environ, **(env or {})})
    out = folder / "grade.json"
    assert out.is_file(), f"no grade written (exit {run.returncode}):\n{run.stdout[-3000:]}\n{run.stderr[-3000:]}"
    grade = json.loads(out.read_text())
    grade["stdout"], grade["folder"] = run.stdout + run.stderr, folder
    return grade


@pytest.fixture(scope="module")
def stubs(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Any]:
    """Every step's untouched stubs, graded once by the student's command (the front end, two xdist workers)."""
    folder = tmp_path_factory.mktemp("stubs")
    return _grade(["-m", "gandalf_tools.grading", "--jobs", "2", "--json", str(folder / "grade.json"),
                   "--gradescope", str(folder / "results.json"), *[f"tests/{step}" for step in STEPS]], folder)


@pytest.fixture(scope="module")
def wrong(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Any]:
    """One wrong answer per step, graded in the sandbox like a submission (only the bug's exercise)."""
    folder = tmp_path_factory.mktemp("wrong")
    overlays, only = [], []
    for step, (exercise, file, old, new) in WRONG.items():
        bug = Mutant(step, exercise, "feedback", "one bug", edits=((file, old, new),))
        overlays.append(f"{step}={build(bug, step, folder / step)}")
        only += ["--grade-only", exercise]
    step, exercise, name = SHADER_BUG
    shader = next(m for m in load_mutants() if (m.step, m.exercise, m.name) == SHADER_BUG)
    overlays.append(f"{step}={build(shader, step, folder / name)}")
    only += ["--grade-only", exercise]
    steps = [*WRONG, step]
    overlay = {"GANDALF_IMPL": os.pathsep.join(overlays)}
    command = ["-m", "pytest", "--student", "-n", "2", "-p", "no:cacheprovider", "-q", "-m", "exercise",
               "--grade-json", str(folder / "grade.json"), *only, *[f"tests/{s}" for s in steps]]
    return _grade(command, folder, overlay)


def _failed(grade: dict[str, Any]) -> list[dict[str, Any]]:
    return [t for t in grade["tests"] if not t["passed"]]


def _names_its_exercise(entry: dict[str, Any]) -> bool:
    message = entry["message"]
    files = feedback.exercise_file(entry["step"], entry["exercise"]).split(" / ")
    return (entry["exercise"].split(".")[0] in message or f"{entry['step']}/exercises/" in message
            or any(Path(f).name in message for f in files if f))


def _one_line(entry: dict[str, Any]) -> str | None:
    message = entry["message"]
    if "\n" in message or len(message) > feedback.LIMIT or not message.strip():
        return f"not one line of at most {feedback.LIMIT} characters: {message[:400]!r}"
    if not _names_its_exercise(entry):
        return f"names neither {entry['exercise']} nor its file: {message!r}"
    if re.search(r"\[gw\d|Traceback|^E |\bassert \w+ [=<>!]|Mismatched elements|/work/|site-packages", message):
        return f"holds pytest's, numpy's or the worker's noise: {message!r}"
    return None


def test_every_stub_failure_is_one_sentence_naming_its_exercise(stubs: dict[str, Any]) -> None:
    failed = _failed(stubs)
    assert len(failed) == stubs["graded_tests"] > 0, "every graded test must fail on the untouched stubs"
    problems = [f"{t['test']}: {why}" for t in failed if (why := _one_line(t))]
    assert not problems, f"{len(problems)} of {len(failed)} messages:\n" + "\n".join(problems[:40])
    exercises = {(x["step"], x["exercise"]) for x in stubs["exercises"]}
    assert {t["step"] for t in failed} == set(STEPS)
    for step, exercise in sorted(exercises):
        mine = [t["message"] for t in failed if (t["step"], t["exercise"]) == (step, exercise)]
        assert mine, f"{step} {exercise}: no failed graded test"
        if feedback.exercise_file(step, exercise).endswith(".py"):  # a Python stub: which function, in which file
            assert any(re.search(rf"is still a stub: write it in {step}/exercises/\w+\.py", m) for m in mine), (
                f"{step} {exercise}: no test says it is a stub and where: {mine[:2]}")


def test_the_terminal_shows_the_same_one_line_per_failed_test(stubs: dict[str, Any]) -> None:
    out = stubs["stdout"]
    assert "[gw" not in out and "Traceback" not in out and "NotImplementedError" not in out, out[:3000]
    for entry in _failed(stubs):
        line = f"{entry['test'].split('::', 1)[-1]}: {entry['message']}"
        assert line in out.splitlines(), f"the terminal lacks the line {line!r}"


def _page_examples() -> list[str]:
    """The example lines of docs/grading.md's "One sentence per failed test"."""
    page = (ROOT / "docs" / "grading.md").read_text()
    part = page.split("**One sentence per failed test.**", 1)[1].split("**Scoring.**", 1)[0]
    return re.findall(r"```text\n(.+?)\n```", part)


def test_the_page_shows_lines_the_grader_prints(stubs: dict[str, Any], wrong: dict[str, Any]) -> None:
    stub, bug = _page_examples()
    assert stub in stubs["stdout"].splitlines()
    assert bug in wrong["stdout"].splitlines(), "docs/grading.md's wrong-answer line is not what the grader prints"


def test_gradescope_and_the_log_hold_the_same_words(stubs: dict[str, Any]) -> None:
    results = json.loads((stubs["folder"] / "results.json").read_text())
    outputs = {t["extra_data"]["nodeid"]: t["output"] for t in results["tests"]}
    for entry in _failed(stubs):
        assert outputs[entry["test"]] == entry["message"]
    log = (stubs["folder"] / "grade.tracebacks.log").read_text()
    assert "NotImplementedError" in log and "Traceback" not in stubs["stdout"]
    assert log.count("\n=== ") + 1 >= len(_failed(stubs))
    assert f"full tracebacks of the failed tests: {stubs['folder'] / 'grade.tracebacks.log'}" in stubs["stdout"]


def test_a_wrong_answer_says_input_expected_and_got(wrong: dict[str, Any]) -> None:
    failed = _failed(wrong)
    steps = {t["step"] for t in failed}
    assert steps == set(WRONG) | {SHADER_BUG[0]}, f"a bug went unnoticed: only {sorted(steps)} failed"
    problems = []
    for entry in failed:
        message = entry["message"]
        why = _one_line(entry)
        if why is None and (gaps := feedback.teaching_gaps(message)):  # the words the mutation check counts too
            why = f"names no {' and no '.join(gaps)}: {message!r}"
        if why is not None:
            problems.append(f"{entry['test']}: {why}")
    assert not problems, f"{len(problems)} of {len(failed)} messages:\n" + "\n".join(problems[:40])
    assert "[gw" not in wrong["stdout"] and "Traceback" not in wrong["stdout"]


# --- the shapes one by one (no grading run) -----------------------------------------------------------------------
def test_a_stub_raised_in_process_names_its_function_and_file() -> None:
    from step01_window.exercises import hue

    with pytest.raises(NotImplementedError) as caught:
        hue.hsv_to_rgb(0.0, 1.0, 1.0)
    assert feedback.sentence(caught.value, exercise="hsv_to_rgb") == (
        "hsv_to_rgb is still a stub: write it in step01_window/exercises/hue.py (its docstring says what it must do).")


def test_numpy_and_pytest_reports_become_got_and_expected() -> None:
    import numpy as np

    feedback.reset_calls()
    feedback.record_call("look_at((0, 0, 5), (0, 0, 0), (0, 1, 0))", np.eye(4) * 2)
    with pytest.raises(AssertionError) as caught:
        np.testing.assert_allclose(np.eye(4) * 2, np.eye(4), atol=1e-9)
    text = feedback.sentence(caught.value, exercise="look_at", file="step04_camera/exercises/projection.py")
    assert text.startswith("look_at((0, 0, 5), (0, 0, 0), (0, 1, 0)) returned [[2., 0.") and "\n" not in text
    assert "got array([[2., 0., 0., 0.]" in text and "expected array([[1., 0., 0., 0.]" in text
    # A bare assert: its comparison found again, the student's call replaced by the value it returned.
    values = feedback.values_sentence("assert np.allclose(impl.look_at(eye, target, up), want, atol=1e-6)",
                                      {"np": np}, {"want": np.eye(4), "eye": None, "target": None, "up": None})
    assert values == ("at row 0: got [2., 0., 0., 0.], expected [1., 0., 0., 0.] (4 of 16 values differ; "
                      "tolerance 1e-06 + 1e-05·|expected|)")
    feedback.reset_calls()
    assert feedback.values_sentence("assert np.allclose(impl.look_at(eye), want)", {"np": np}, {"want": 1}) == (
        "expected `np.allclose(impl.look_at(eye), want)` to hold")  # never a second call of the student's code


def test_a_sentence_is_one_line_within_the_limit() -> None:
    error = AssertionError("x" * 1000 + "\nassert False")
    text = feedback.sentence(error, exercise="perspective", hint="the field of view is in degrees")
    assert "\n" not in text and len(text) <= feedback.LIMIT and text.startswith("perspective: xxx")


def test_a_call_that_should_have_raised_or_raised_otherwise_says_so() -> None:
    feedback.reset_calls()
    feedback.record_call("ngon_mesh(4.5, 1.0)", (4, 3))
    with pytest.raises(pytest.fail.Exception) as caught:
        with pytest.raises(ValueError):
            pass
    text = feedback.sentence(caught.value, exercise="ngon_mesh", expected_raise="ValueError matching 'sides'")
    assert text == "ngon_mesh(4.5, 1.0) returned (4, 3); expected it to raise ValueError matching 'sides'"
    feedback.reset_calls()
    error = ZeroDivisionError("float division by zero")
    feedback.record_raise("perspective(0, 1, 0.1, 10)", error)
    text = feedback.sentence(error, exercise="perspective", expected_raise="ValueError")
    assert text == ("perspective(0, 1, 0.1, 10) raised ZeroDivisionError: float division by zero; expected it to "
                    "raise ValueError")
    assert feedback.teaching_gaps(text) == []
    source = "def test_x(args):\n    with pytest.raises(ValueError, match=name):\n        impl.perspective(*args)\n"
    assert feedback.raises_expected(source, 3, {"pytest": pytest}, {"name": "fovy"}) == (
        "ValueError with a message matching 'fovy'")
    assert feedback.raises_expected(source, 1, {"pytest": pytest}, {"name": "fovy"}) == ""


def test_an_ordering_assert_says_got_against_its_bound() -> None:
    assert feedback.values_sentence("assert worst <= TOLERANCE", {"TOLERANCE": 1}, {"worst": 3}) == (
        "got worst = 3, expected ≤ 1")
    assert feedback.values_sentence("assert 0.03 * TOTAL < roof", {"TOTAL": 100}, {"roof": 0}) == (
        "got roof = 0, expected > 3")
    assert feedback.values_sentence("assert a < b", {}, {"a": 2, "b": 1}) == "expected a < b, got 2 < 1"
    assert feedback.values_sentence("assert worst <= 1", {}, {"worst": 0}) is not None  # holds: the source only


def test_teaching_gaps_names_what_a_sentence_leaves_out() -> None:
    assert feedback.teaching_gaps("hsv_to_rgb(0.5, 1, 1) returned (0, 0.5, 1); expected (0, 1, 1)") == []
    assert feedback.teaching_gaps("house_meshes() returned (…): got (-1, 0, -1), expected (-0.5, 0, -0.5)") == []
    assert feedback.teaching_gaps("for a sphere in opengl: worst pixel got [1, 2, 3], expected [4, 5, 6]") == []
    assert feedback.teaching_gaps("expected 3 <= 1 to hold") == ["input", "got"]
    assert feedback.teaching_gaps("DID NOT RAISE ValueError") == ["input", "expected", "got"]
