"""Hostile submissions gain nothing and touch no classmate: each file of ``tests/attacks/step01/`` (a replacement
``hue.py`` saying what it tries) is graded

* alone, the way the instructors page's Gradescope ``run_autograder`` does (``GANDALF_IMPL=step01_window=<folder>
  python -m gandalf_tools.grading tests/step01_window --json grade.json --gradescope results.json``): neither file,
  read after the run and a wait for detached processes, gives it a point over the untouched stub, and no file outside
  its output changed (the checkout's conftest files, the venv's ``.pth`` files, the cached ``colorsys``);
* in one batch (``python -m gandalf_tools.grading.batch --jobs 2``) with honest classmates graded before, beside and
  after the attackers: no attacker's row earns more than the stub's, each classmate's row is the one a batch of the
  classmates alone gives (no error, the same points per exercise), each grade file says what its row says, and no
  file of the class folder, the output (after the wait) or the shared world changed.

The reference solution handed in the same way still gets full marks. See ``tests/attacks/replay.py``."""

from __future__ import annotations

import pytest
from attacks.replay import ATTACKS, ROOT, TARGETS, attacks, grade_batch, grade_single, honest_class

from gandalf_tools.grading import sandbox

STEP = "step01_window"


def _uncontained(attack) -> bool:
    """Whether ``attack`` reads the checkout or writes the instructor's files, which a machine without namespaces
    cannot prevent (its student's process can read and write what the grader's user can): not replayed there."""
    return sandbox.isolation() == "process" and ("solution" in attack.stem or "@@" in attack.read_text())


@pytest.fixture(scope="module")
def stub():
    return grade_single(STEP, None)


def test_the_reference_solution_handed_in_gets_full_marks():
    graded = grade_single(STEP, ROOT / STEP / "solutions" / TARGETS[STEP])
    assert (graded.front_end, graded.gradescope, graded.changed) == (pytest.approx(2.0), pytest.approx(2.0), [])


@pytest.mark.parametrize("attack", attacks(STEP), ids=lambda p: p.stem)
def test_an_attack_gains_no_point_over_the_stub_and_changes_nothing(attack, stub):
    if _uncontained(attack):
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
    hostile = {f"m_{a.stem}": a for a in attacks(STEP) if not _uncontained(a)}
    both = grade_batch(STEP, {**honest, **hostile})
    assert both.changed == []
    assert set(both.rows) == set(honest) | set(hostile)
    for student, row in alone.rows.items():
        assert (both.rows[student]["exercises"], both.rows[student]["error"]) == (row["exercises"], ""), student
    gained = {s: both.rows[s]["earned"] for s in hostile if both.rows[s]["earned"] > alone.rows["z_stub"]["earned"]}
    assert gained == {}, [(s, (ATTACKS / "step01" / f"{s[2:]}.py").read_text().splitlines()[0]) for s in gained]
