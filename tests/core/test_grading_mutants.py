"""The mutation check itself: a mutant that breaks ``hsv_to_rgb`` is killed (and the message its failed test gives
says input, expected and got), one that changes nothing survives and fails the run, and a survivor listed in
``known_gaps.txt`` is reported without failing it.

Each case runs ``python -m gandalf_tools.grading.mutants`` in a subprocess on step 01's ``hsv_to_rgb`` only.
"""

from __future__ import annotations

from pathlib import Path

from grading_checks import run_check

DEFINITIONS = """
import math

from gandalf_tools.grading.mutants import Mutant, mutant, patch

MUTANTS: list[Mutant] = []


@mutant(MUTANTS, "step01_window", "hsv_to_rgb", "radians", "reads the hue as radians")
def _(pkg):
    original = pkg.hue.hsv_to_rgb
    patch(pkg, "hue.hsv_to_rgb", lambda h, s, v: original(math.degrees(h), s, v))


@mutant(MUTANTS, "step01_window", "hsv_to_rgb", "unchanged", "no change at all: must survive")
def _(pkg):
    pass
"""


def _run(tmp_path: Path, *args: str) -> tuple[int, str, list[dict]]:
    return run_check("mutants", tmp_path, "mutants", DEFINITIONS, *args)


def test_a_wrong_mutant_is_killed_and_an_unchanged_one_survives(tmp_path):
    code, output, outcomes = _run(tmp_path, "--jobs", "2")
    by_name = {o["mutant"]: o for o in outcomes}
    assert by_name["step01_window:hsv_to_rgb:radians"]["status"] == "killed", output[-2000:]
    assert "hsv_to_rgb(" in by_name["step01_window:hsv_to_rgb:radians"]["detail"]  # the test's own message
    # What the student would read names the input, the expected and the got, and the check counts it.
    assert by_name["step01_window:hsv_to_rgb:radians"]["message_lacks"] == []
    assert "1/1 killed mutants' messages name the input, the expected and the got" in output
    assert by_name["step01_window:hsv_to_rgb:unchanged"]["status"] == "survived", output[-2000:]
    assert by_name["step01_window:*:control"]["status"] == "passed", output[-2000:]
    assert code == 1 and "SURVIVED step01_window:hsv_to_rgb:unchanged" in output


def test_a_known_gap_is_listed_but_does_not_fail_the_run(tmp_path):
    (tmp_path / "mutants").mkdir()
    (tmp_path / "mutants" / "known_gaps.txt").write_text("step01_window:hsv_to_rgb:unchanged  # a test for the test\n")
    code, output, outcomes = _run(tmp_path, "-k", "unchanged", "--no-control")
    assert [o["status"] for o in outcomes] == ["known-gap"], output[-2000:]
    assert code == 0 and "KNOWN GAP step01_window:hsv_to_rgb:unchanged" in output
    code, output, _ = _run(tmp_path, "-k", "unchanged", "--no-control", "--strict")
    assert code == 1, output[-2000:]
