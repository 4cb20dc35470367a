"""Hostile submissions gain nothing and touch no classmate: files of ``tests/attacks/step01/`` (each a replacement
``hue.py`` saying what it tries) are graded

* alone, the way the instructors page's Gradescope ``run_autograder`` does (``GANDALF_IMPL=step01_window=<folder>
  python -m gandalf_tools.grading tests/step01_window --json grade.json --gradescope results.json``): neither file,
  read after the run and a wait for detached processes, gives it a point over the untouched stub, and no file outside
  its output changed (the checkout's conftest files, the venv's ``.pth`` files, the cached ``colorsys``);
* in one batch (``python -m gandalf_tools.grading.batch --jobs 2``) with honest classmates graded before, beside and
  after the attackers: no attacker's row earns more than the stub's, each classmate's row is the one a batch of the
  classmates alone gives (no error, the same points per exercise), each grade file says what its row says, and no
  file of the class folder, the output (after the wait) or the shared world changed.

The suite replays one attack of each kind (:data:`SAMPLE`: a forged grade file, the reference imported, the verdict
patched in the student's process, the shared bytecode cache poisoned, processes left behind) and, in the batch, those
aimed at classmates (:data:`AT_CLASSMATES`). Every attack of the folder is replayed by CI's own step
(``python tests/attacks/replay.py --batch --check``, as the mutation and fairness checks are), and a test here checks
that every attack file is of a kind that step replays. The reference solution handed in the same way still gets full
marks. See ``tests/attacks/replay.py``."""

from __future__ import annotations

import pytest
from attacks.replay import (
    ATTACKS,
    ROOT,
    TARGETS,
    attacks,
    batch_verdict,
    contained_here,
    grade_batch,
    grade_single,
    honest_class,
)

STEP = "step01_window"
#: One attack of each kind, replayed alone in the suite.
SAMPLE = ("forge_then_exit", "import_solution", "patch_test_report", "pycache_colorsys", "fork_20")
#: The attacks aimed at classmates, replayed in the suite's batch.
AT_CLASSMATES = ("sibling_overwrite", "kill_siblings", "venv_pth", "conftest_checkout")
CI = ROOT / ".ci" / "run"


@pytest.fixture(scope="module")
def stub():
    return grade_single(STEP, None)


def _attack(name: str):
    return ATTACKS / "step01" / f"{name}.py"


def test_the_reference_solution_handed_in_gets_full_marks():
    graded = grade_single(STEP, ROOT / STEP / "solutions" / TARGETS[STEP])
    assert (graded.front_end, graded.gradescope, graded.changed) == (pytest.approx(2.0), pytest.approx(2.0), [])


@pytest.mark.parametrize("name", SAMPLE)
def test_an_attack_gains_no_point_over_the_stub_and_changes_nothing(name, stub):
    attack = _attack(name)
    if not contained_here(attack):
        pytest.skip("this machine allows no namespaces: the student's process can read and write the grader's files")
    graded = grade_single(STEP, attack)
    said = f"{attack.stem}: {attack.read_text().splitlines()[0]}"
    assert graded.front_end <= stub.front_end + 1e-9, f"front end: {said}"
    assert graded.gradescope <= stub.gradescope + 1e-9, f"Gradescope's results.json: {said}"
    assert graded.changed == [], said


def test_a_batch_of_attackers_costs_honest_classmates_nothing():
    honest = honest_class(STEP)
    alone = grade_batch(STEP, honest)
    assert {s: r["earned"] for s, r in alone.rows.items()} == {
        "a_correct": 2.0, "z_correct": 2.0, "z_partial": 1.0, "z_stub": 0.0}
    hostile = {f"m_{name}": _attack(name) for name in AT_CLASSMATES if contained_here(_attack(name))}
    both = grade_batch(STEP, {**honest, **hostile})
    assert set(both.rows) == set(honest) | set(hostile)
    assert batch_verdict(alone, both, hostile) == [], {s: a.read_text().splitlines()[0] for s, a in hostile.items()}


def test_ci_replays_every_attack_in_both_modes():
    """The sample above is a part; the rest is CI's step, which must replay the whole folder, alone and in a batch,
    and fail on any point gained."""
    assert "tests/attacks/replay.py --batch --check" in CI.read_text()
    assert set(SAMPLE) | set(AT_CLASSMATES) <= {a.stem for a in attacks(STEP)}
