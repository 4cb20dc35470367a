"""The grader's outputs for course platforms: the batch grader's gradebook, GitHub Classroom's configuration.

* ``scripts/make_sample_submissions.py`` makes 5 seeded submissions of steps 01-02 (the stubs, the solutions, a
  runaway loop, a hard exit, random shares); ``python -m gandalf_tools.grading.batch`` grades all five in
  parallel, a process per submission, and the gradebook must give exactly the points of the exercises done from
  the solutions (the script's ``--check``); the runaway loop and the hard exit lose only their own exercise.
* ``.github/classroom/autograding.json`` parses, has one entry per step with points, and each entry's command
  really runs the grader: run with ``--collect-only`` it collects that step's graded tests.
"""

from __future__ import annotations

import csv
import json
import os
import shlex
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
ENV = {k: v for k, v in os.environ.items() if k != "GANDALF_IMPL"}


def _run(args: list[str], timeout: float) -> subprocess.CompletedProcess:
    """``args`` run from the repository root in the test environment, their output captured as text."""
    return subprocess.run(args, cwd=ROOT, env=ENV, capture_output=True, text=True, timeout=timeout)


def test_batch_grades_sample_submissions_into_the_right_gradebook(tmp_path):
    subs, out = tmp_path / "subs", tmp_path / "out"
    make = [sys.executable, str(ROOT / "scripts" / "make_sample_submissions.py"), "--out", str(subs)]
    subprocess.run(make + ["--count", "5", "--seed", "1", "--steps", "step01", "step02"], check=True, env=ENV,
                   timeout=60)
    manifest = json.loads((subs / "manifest.json").read_text())
    assert len(manifest) == 5 and len(list(subs.glob("student_*/step02_triangle/exercises/ngon.py"))) == 5
    students = sorted(manifest)
    kinds = ["stubs", "solutions", "runaway loop", "hard exit", "random"]  # student_05's syntax error is in step 03
    assert [manifest[s]["kind"] for s in students] == kinds
    proc = _run([sys.executable, "-m", "gandalf_tools.grading.batch", str(subs), "--out", str(out), "--steps", "step01",
                 "step02", "--jobs", "2", "--timeout", "20"], timeout=600)
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    assert "[  5/5]" in proc.stdout, proc.stdout  # the progress line
    rows = {row["student"]: row for row in csv.DictReader((out / "gradebook.csv").open())}
    assert sorted(rows) == students
    possible = float(rows["student_02"]["possible"])
    assert possible == 5.0 and float(rows["student_02"]["earned"]) == pytest.approx(possible)
    assert float(rows["student_01"]["earned"]) == 0.0
    # The runaway loop and the hard exit cost NGonSystem only; the rest of their work is graded.
    for student, why in (("student_03", "did not return within"), ("student_04", "ended its process")):
        assert float(rows[student]["step02_triangle:NGonSystem"]) == 0.0, rows[student]
        report = (out / student / "report.md").read_text()
        assert report.startswith(f"# {student}") and why in report, report[-2000:]
    # Every student's points equal the points of the exercises done from the solutions (the manifest).
    checked = _run(make + ["--check", str(out)], timeout=60)
    assert checked.returncode == 0 and "5 students checked against the manifest: 0 mismatches" in checked.stdout, (
        checked.stdout + checked.stderr
    )
    for student in students:
        gradescope = json.loads((out / student / "results.json").read_text())
        assert gradescope["score"] == pytest.approx(float(rows[student]["earned"]))
    book = json.loads((out / "gradebook.json").read_text())
    assert [b["student"] for b in book] == students and all(not b["error"] for b in book)


def _classroom() -> list[dict]:
    return json.loads((ROOT / ".github" / "classroom" / "autograding.json").read_text())["tests"]


def test_classroom_configuration_has_one_entry_per_step():
    tests = _classroom()
    steps = sorted(p.name for p in (ROOT / "tests").glob("step0[1-7]_*") if p.is_dir())
    named = [shlex.split(t["run"])[3] for t in tests]
    assert named == [f"tests/{s}" for s in steps]
    for t in tests:
        assert {"name", "setup", "run", "input", "output", "comparison", "timeout", "points"} <= set(t)
        assert t["points"] > 0 and 0 < t["timeout"] <= 60 and t["comparison"] in ("included", "exact", "regex")
        assert shlex.split(t["run"])[:3] == [".venv/bin/python", "-m", "gandalf_tools.grading"]
    workflow = (ROOT / ".github" / "workflows" / "classroom.yml").read_text()
    assert "education/autograding" in workflow and "scripts/setup.sh" in workflow


@pytest.mark.parametrize("entry", range(7))
def test_each_classroom_command_collects_its_graded_tests(entry):
    t = _classroom()[entry]
    args = shlex.split(t["run"])
    assert args[0] == ".venv/bin/python"
    proc = _run([sys.executable, *args[1:], "--collect-only", "-m", "exercise"], timeout=120)
    assert proc.returncode == 0, proc.stdout[-2000:] + proc.stderr[-2000:]
    collected = [line for line in proc.stdout.splitlines() if "::" in line]
    step = args[3].split("/")[-1]
    assert collected and all(line.startswith(f"tests/{step}/") for line in collected), proc.stdout[-2000:]
