"""The student release (``python -m gandalf_tools.release``): built into a temporary folder, it holds no solution,
mutant or hidden test, its check finds a planted leak of each kind, and a step's demo on an untouched stub stops with
one sentence. Its graded tests failing on its stubs and passing with the reference copied over them is CI's stub check
(``.ci/run``, every step).
"""

from __future__ import annotations

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


def test_ci_grades_the_release_on_its_stubs_and_with_the_reference():
    """The graded tests failing on the release's stubs and passing with the reference copied over them (in a
    ``.venv`` borrowing this one's packages) is CI's stub check, for every step: ``.ci/run`` builds the release with
    ``--solved`` and ``--borrow-venv`` and grades both copies. The suite leaves that run (two graded runs of a
    step in the release's own environment) to CI and checks here that CI makes it."""
    ci = (ROOT / ".ci" / "run").read_text()
    check = ci.split("[start:stub-check]", 1)[1].split("[end:stub-check]", 1)[0]
    assert "gandalf_tools.release" in check and "--solved" in check and "--borrow-venv" in check
    assert 'grade "$release/student" "$release/stubs.json" tests/step*' in check
    assert 'grade "$release/solved" "$release/solved.json" tests/step*' in check
    assert 'stubs["mode"] != "exercises (student)"' in check and "passed or failed" in check


def test_a_step_on_an_untouched_stub_stops_with_one_sentence(built):
    if not (built.folder / ".venv").is_dir():
        release.borrow_environment(built.folder)
    proc = subprocess.run([str(built.folder / ".venv/bin/python"), "-m", "step01_window.opengl", "--headless",
                           "--frames", "1"], cwd=built.folder, env=_env(), capture_output=True, text=True, timeout=120)
    assert proc.returncode == 1, proc.stdout + proc.stderr
    assert "Traceback" not in proc.stderr, proc.stderr
    assert "HueCycleSystem" in proc.stderr and "step01_window/exercises/hue.py" in proc.stderr, proc.stderr
