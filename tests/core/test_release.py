"""The student release (``python -m gandalf_tools.release``): built into a temporary folder, it holds no solution,
mutant or hidden test, its check finds a planted leak of each kind, step 01's graded tests fail on its stubs and
pass with the reference copied over them, and a step's demo on an untouched stub stops with one sentence.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
from pathlib import Path

import pytest

from gandalf_tools import release

ROOT = Path(__file__).resolve().parents[2]
pytestmark = pytest.mark.skipif(not (ROOT / ".git").exists() or shutil.which("git") is None,
                                reason="the release is built from a git checkout's tracked files")


@pytest.fixture(scope="module")
def built(tmp_path_factory: pytest.TempPathFactory) -> release.Release:
    return release.build(tmp_path_factory.mktemp("release") / "student")


def _env() -> dict[str, str]:
    return {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "GANDALF_IMPL", "PYTEST_ADDOPTS")}


def test_the_hidden_test_convention():
    for path in ("tests/step01_window/hidden/test_hue.py", "tests/step01_window/test_hue_hidden.py",
                 "tests/step01_window/hidden_inputs.json", "tests/step07_advanced/hidden/data/seeds.txt"):
        assert release.excluded(path) == "a hidden test", path
    for path in ("tests/step01_window/test_step01.py", "tests/step01_window/test_hidden_surface.py",
                 "step01_window/exercises/hue.py"):
        assert release.excluded(path) is None, path
    assert release.excluded("step01_window/solutions/hue.py") == "a reference solution"
    assert release.excluded("tests/mutants/step01_window.py") is not None


def test_the_release_holds_no_solution_mutant_or_hidden_test(built):
    files = [p.relative_to(built.folder).as_posix() for p in built.folder.rglob("*") if p.is_file()]
    assert set(files) == set(built.files)
    assert not [f for f in files if "solutions" in f.split("/")[:-1]]
    assert not [f for f in files if f.startswith(("tests/mutants/", ".ci/")) or release.is_hidden(f)]
    assert release.check_release(built.folder) == []
    # Every step ships its stubs, and the README tells a student what to run.
    steps = sorted(p.name for p in ROOT.glob("step0*") if (p / "solutions").is_dir())
    assert steps and all((built.folder / s / "exercises" / "__init__.py").is_file() for s in steps)
    assert "./run.sh test tests/step01_window" in (built.folder / "README.md").read_text()
    # The tests that need the reference (or hold its text) stay with the instructor, listed with the reason; every
    # exercise still has public graded tests (those live in modules that need neither).
    assert "tests/step07_advanced/test_pbr_model_reference.py" in built.instructor_tests
    assert "tests/step07_advanced/test_terrain_mutants.py" in built.instructor_tests
    assert built.without_public_tests == [], built.summary()


def test_the_check_finds_each_kind_of_leak(built, tmp_path):
    copy = tmp_path / "leaky"
    shutil.copytree(built.folder, copy)
    (copy / "tests/step01_window/test_hue_hidden.py").write_text("def test_x():\n    pass\n")
    (copy / "tests/step01_window/test_peek.py").write_text("from step01_window.solutions import hue\n")
    (copy / "step01_window/peek.py").write_text("from .solutions.hue import hsv_to_rgb\n")
    shutil.copy2(ROOT / "step01_window/solutions/hue.py", copy / "step01_window/copied.py")
    shutil.copytree(ROOT / "step01_window/solutions", copy / "step01_window/solutions")
    problems = "\n".join(release.check_release(copy))
    for expected in ("test_hue_hidden.py: a hidden test", "test_peek.py: line 1: from step01_window.solutions",
                     "peek.py: line 1: from .solutions.hue import",
                     "copied.py: equal to step01_window/solutions/hue.py",
                     "step01_window/solutions/hue.py: a reference solution"):
        assert expected in problems, f"not found: {expected!r} in\n{problems}"
    # Lines of the reference inside a test (a table of shader edits, say) count too.
    lines = [line.strip() for line in (ROOT / "step01_window/solutions/hue.py").read_text().splitlines()]
    reference = release.reference_of(*release.tracked_files(ROOT)).lines
    own = [line for line in lines if line in reference and not {"'", '"', "\\"} & set(line)][:2]
    assert len(own) == 2
    (copy / "tests/step01_window/test_table.py").write_text("".join(f"EDIT = {line!r}\n" for line in own))
    assert any("test_table.py: holds 2 lines of the reference" in p for p in release.check_release(copy))


def _grade(folder: Path, out: Path) -> dict:
    proc = subprocess.run([str(folder / ".venv/bin/python"), "-m", "pytest", "-q", "-p", "no:cacheprovider",
                           "-m", "exercise", "--grade-json", str(out), "tests/step01_window"],
                          cwd=folder, env=_env(), capture_output=True, text=True, timeout=300)
    assert out.is_file(), proc.stdout[-2000:] + proc.stderr[-2000:]
    return json.loads(out.read_text())


def test_graded_tests_fail_on_the_stubs_and_pass_on_the_reference(built, tmp_path):
    release.borrow_environment(built.folder)
    stubs = _grade(built.folder, tmp_path / "stubs.json")
    assert stubs["mode"] == "exercises (student)"  # plain pytest grades the student where there are no solutions
    assert stubs["graded_tests"] > 0 and stubs["graded_tests_passed"] == 0, \
        [t["test"] for t in stubs["tests"] if t["passed"]]
    solved = tmp_path / "solved"
    shutil.copytree(built.folder, solved, ignore=shutil.ignore_patterns(".venv"))
    assert "step01_window" in release.copy_solutions_over(solved)
    release.borrow_environment(solved)
    result = _grade(solved, tmp_path / "solved.json")
    assert result["graded_tests"] == stubs["graded_tests"]
    assert result["graded_tests_passed"] == result["graded_tests"], \
        [(t["test"], t["message"]) for t in result["tests"] if not t["passed"]]


def test_a_step_on_an_untouched_stub_stops_with_one_sentence(built):
    if not (built.folder / ".venv").is_dir():
        release.borrow_environment(built.folder)
    proc = subprocess.run([str(built.folder / ".venv/bin/python"), "-m", "step01_window.opengl", "--headless",
                           "--frames", "1"], cwd=built.folder, env=_env(), capture_output=True, text=True, timeout=120)
    assert proc.returncode == 1, proc.stdout + proc.stderr
    assert "Traceback" not in proc.stderr, proc.stderr
    assert "HueCycleSystem" in proc.stderr and "step01_window/exercises/hue.py" in proc.stderr, proc.stderr
