"""Hostile submissions gain nothing and touch no classmate: files of ``tests/attacks/step01/`` (each a replacement
``hue.py`` saying what it tries) are graded

* alone, the way the instructors page's Gradescope ``run_autograder`` does (``GANDALF_IMPL=step01_window=<folder>
  python -m gandalf_tools.grading tests/step01_window --json grade.json --gradescope results.json``): neither file,
  read after the run and a wait for detached processes, gives it a point over the untouched stub (which earns none),
  and no file outside its output changed (the checkout's conftest files, the venv's ``.pth`` files, the cached
  ``colorsys``);
* in one batch (``python -m gandalf_tools.grading.batch --jobs 2``) with honest classmates graded before, beside and
  after the attackers: no attacker's row earns more than the stub's, each classmate's row is the one a batch of the
  classmates alone gives (:data:`HONEST_ROWS`: no error, the same points per exercise; CI's replay grades that batch
  too and compares), each grade file says what its row says, and no file of the class folder, the output (after the
  wait) or the shared world changed.

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
    Batch,
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
#: What the untouched stub earns, in the front end's grade and in Gradescope's file: nothing (every graded test
#: fails on it: test_grading_feedback grades every step's stubs with both outputs, and the batch below grades one).
STUB_POINTS = 0.0
#: The honest classmates' rows, each exercise's points: a batch of the classmates alone gives exactly these (the
#: reference earns both exercises, the partial work the one it did, the stub none), and so must the batch with the
#: attackers.
HONEST_ROWS = {
    "a_correct": {"step01_window:HueCycleSystem": 1.0, "step01_window:hsv_to_rgb": 1.0},
    "z_correct": {"step01_window:HueCycleSystem": 1.0, "step01_window:hsv_to_rgb": 1.0},
    "z_partial": {"step01_window:HueCycleSystem": 0.0, "step01_window:hsv_to_rgb": 1.0},
    "z_stub": {"step01_window:HueCycleSystem": 0.0, "step01_window:hsv_to_rgb": 0.0},
}


def _attack(name: str):
    return ATTACKS / "step01" / f"{name}.py"


def test_the_reference_solution_handed_in_gets_full_marks():
    graded = grade_single(STEP, ROOT / STEP / "solutions" / TARGETS[STEP])
    assert (graded.front_end, graded.gradescope, graded.changed) == (pytest.approx(2.0), pytest.approx(2.0), [])


@pytest.mark.parametrize("name", SAMPLE)
def test_an_attack_gains_no_point_over_the_stub_and_changes_nothing(name):
    attack = _attack(name)
    if not contained_here(attack):
        pytest.skip("this machine allows no namespaces: the student's process can read and write the grader's files")
    graded = grade_single(STEP, attack)
    said = f"{attack.stem}: {attack.read_text().splitlines()[0]}"
    assert graded.front_end <= STUB_POINTS + 1e-9, f"front end: {said}"
    assert graded.gradescope <= STUB_POINTS + 1e-9, f"Gradescope's results.json: {said}"
    assert graded.changed == [], said


def test_a_batch_of_attackers_costs_honest_classmates_nothing():
    honest = honest_class(STEP)
    assert set(honest) == set(HONEST_ROWS)
    # The batch of the classmates alone, as it comes out (rows of known points; CI's replay grades it).
    rows = {s: {"exercises": x, "error": "", "earned": sum(x.values())} for s, x in HONEST_ROWS.items()}
    alone = Batch(rows, changed=[], seconds=0.0)
    hostile = {f"m_{name}": _attack(name) for name in AT_CLASSMATES if contained_here(_attack(name))}
    both = grade_batch(STEP, {**honest, **hostile})
    assert set(both.rows) == set(honest) | set(hostile)
    assert {s: both.rows[s]["earned"] for s in honest} == {s: r["earned"] for s, r in alone.rows.items()}
    assert batch_verdict(alone, both, hostile) == [], {s: a.read_text().splitlines()[0] for s, a in hostile.items()}


def test_ci_replays_every_attack_in_both_modes():
    """The sample above is a part; the rest is CI's step, which must replay the whole folder, alone and in a batch,
    and fail on any point gained."""
    assert "tests/attacks/replay.py --batch --check" in CI.read_text()
    assert set(SAMPLE) | set(AT_CLASSMATES) <= {a.stem for a in attacks(STEP)}
