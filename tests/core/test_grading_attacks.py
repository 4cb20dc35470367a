"""Hostile submissions gain nothing: each file of ``tests/attacks/step01/`` (a replacement ``hue.py`` saying what it
tries) is graded through the real front end (``python -m gandalf_tools.grading tests/step01_window --impl
step01_window=<folder> --json grade.json``), and the grade file the platform would read afterwards gives it no point
over the untouched stub, while the reference solution handed in the same way still gets full marks."""

from __future__ import annotations

import pytest
from attacks.replay import attacks, grade_attack

from gandalf_tools.grading import sandbox

STEP = "step01_window"


@pytest.fixture(scope="module")
def stub_points() -> float:
    return grade_attack(STEP, None)


def test_the_reference_solution_handed_in_gets_full_marks():
    from attacks.replay import ROOT, TARGETS

    assert grade_attack(STEP, ROOT / STEP / "solutions" / TARGETS[STEP]) == pytest.approx(2.0)


@pytest.mark.parametrize("attack", attacks(STEP), ids=lambda p: p.stem)
def test_an_attack_gains_no_point_over_the_stub(attack, stub_points):
    if sandbox.isolation() == "process" and "solution" in attack.stem:
        pytest.skip("this machine allows no namespaces: the student's process can read the checkout's files")
    assert grade_attack(STEP, attack) <= stub_points + 1e-9, f"{attack.stem}: {attack.read_text().splitlines()[0]}"
