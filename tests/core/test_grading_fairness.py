"""The fairness check itself: a correct alternative written differently from the reference is accepted, a wrong
one is rejected and fails the run.

Each case runs ``python -m gandalf_tools.grading.fairness`` in a subprocess on step 01's ``hsv_to_rgb`` only.
"""

from __future__ import annotations

from pathlib import Path

from grading_checks import run_check

DEFINITIONS = """
import colorsys

from gandalf_tools.grading.fairness import alternative
from gandalf_tools.grading.mutants import Mutant, patch

ALTERNATIVES: list[Mutant] = []


@alternative(ALTERNATIVES, "step01_window", "hsv_to_rgb", "colorsys", "the standard library's conversion")
def _(pkg):
    patch(pkg, "hue.hsv_to_rgb", lambda h, s, v: colorsys.hsv_to_rgb((h % 360.0) / 360.0 % 1.0, s, v))


@alternative(ALTERNATIVES, "step01_window", "hsv_to_rgb", "grb", "wrong: green and red swapped, must be rejected")
def _(pkg):
    original = pkg.hue.hsv_to_rgb

    def hsv_to_rgb(h, s, v):
        r, g, b = original(h, s, v)
        return g, r, b

    patch(pkg, "hue.hsv_to_rgb", hsv_to_rgb)
"""


def _run(tmp_path: Path, *args: str) -> tuple[int, str, dict[str, dict]]:
    code, output, outcomes = run_check("fairness", tmp_path, "fairness", DEFINITIONS, *args)
    return code, output, {o["alternative"]: o for o in outcomes}


def test_a_correct_alternative_is_accepted_and_a_wrong_one_fails_the_run(tmp_path):
    code, output, outcomes = _run(tmp_path, "--jobs", "2")
    assert outcomes["step01_window:hsv_to_rgb:colorsys"]["status"] == "accepted", output[-2000:]
    assert outcomes["step01_window:hsv_to_rgb:grb"]["status"] == "rejected", output[-2000:]
    assert "hsv_to_rgb(" in outcomes["step01_window:hsv_to_rgb:grb"]["detail"]  # the test's own message
    assert outcomes["step01_window:*:control"]["status"] == "passed", output[-2000:]
    assert code == 1 and "REJECTED step01_window:hsv_to_rgb:grb" in output


def test_only_accepted_alternatives_pass_the_run(tmp_path):
    code, output, outcomes = _run(tmp_path, "-k", "colorsys", "--no-control")
    assert [o["status"] for o in outcomes.values()] == ["accepted"], output[-2000:]
    assert code == 0 and "1/1 alternatives accepted" in output
