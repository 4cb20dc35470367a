"""The grading front end's arguments, checked before anything is graded: a test path that does not exist, an
``--impl`` folder that does not exist or is no package, an unknown step, an exercise that is a directory. Each
exits with status 2 and one sentence naming the argument (an instructor's typo must not become a student's 0 %
with exit status 0)."""

from __future__ import annotations

from pathlib import Path

import pytest

from gandalf_tools.grading.__main__ import main

from .catalogue import params, result, run

ROOT = Path(__file__).resolve().parents[3]


def graded(*argv: str):
    """Run the front end (from the project's root) on ``argv``: (exit status, what it wrote to stderr)."""
    def action(tmp: Path, capsys, monkeypatch):
        monkeypatch.chdir(ROOT)
        status = main([a.replace("{tmp}", str(tmp)) for a in argv])
        return status, capsys.readouterr().err
    return action


def says(*words: str):
    return lambda got: got[0] == 2 and all(w in got[1] for w in words) and "nothing was graded" in got[1]


def _folders(tmp: Path) -> None:
    (tmp / "empty").mkdir()
    (tmp / "dir_exercise").mkdir()
    (tmp / "dir_exercise" / "__init__.py").write_text("")
    (tmp / "dir_exercise" / "hue.py").mkdir()


CASES = [
    result("missing-test-path", graded("tests/step01_windw"), says("'tests/step01_windw'", "does not exist")),
    result("missing-test-file-of-a-node-id", graded("tests/nope.py::test_x"), says("'tests/nope.py::test_x'")),
    result("missing-impl-folder", graded("tests/step01_window", "--impl", "step01_window={tmp}/gone"),
           says("--impl", "gone", "does not exist")),
    result("impl-folder-not-a-package", graded("tests/step01_window", "--impl", "step01_window={tmp}/empty"),
           says("--impl", "empty", "no __init__.py")),
    result("impl-unknown-step", graded("tests/step01_window", "--impl", "step01_windw={tmp}/empty"),
           says("no step package named 'step01_windw'")),
    result("impl-without-step", graded("tests/step01_window", "--impl", "{tmp}/empty"), says("expected STEP=PATH")),
    result("exercise-is-a-directory", graded("tests/step01_window", "--impl", "step01_window={tmp}/dir_exercise"),
           says("hue.py", "is a directory")),
]


@pytest.mark.parametrize("case", params(CASES))
def test_grading_arguments(case, tmp_path, capsys, monkeypatch):
    _folders(tmp_path)
    run(case, tmp_path, capsys, monkeypatch)


def test_a_bare_word_may_be_an_option_value(monkeypatch):
    """``-k hue`` leaves 'hue' among the positional arguments: it is pytest's, not a test path to refuse."""
    from gandalf_tools.grading.__main__ import argument_problem

    monkeypatch.chdir(ROOT)
    assert argument_problem(["hue", "exercise", "tests/step01_window"], []) is None
    assert argument_problem(["tests"], [f"step01_window={ROOT / 'step01_window' / 'solutions'}"]) is None
