"""The grader's outputs for course platforms: the batch grader's gradebook, GitHub Classroom's configuration.

* ``scripts/make_sample_submissions.py`` makes 30 seeded submissions of step 01 (each exercise file either the
  solution or the stub); ``python -m gandalf_core.grading.batch`` grades 3 of them in parallel, a process per
  submission, and its gradebook must give exactly the points the manifest says (2 for ``hue.py`` done, else 0).
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


def test_batch_grades_three_sample_submissions(tmp_path):
    subs, out = tmp_path / "subs", tmp_path / "out"
    make = [sys.executable, str(ROOT / "scripts" / "make_sample_submissions.py"), "--out", str(subs)]
    subprocess.run(make + ["--count", "30", "--seed", "1", "--steps", "step01"], check=True, env=ENV, timeout=60)
    manifest = json.loads((subs / "manifest.json").read_text())
    assert len(manifest) == 30 and len(list(subs.glob("student_*/step01_window/exercises/hue.py"))) == 30
    manifest = {k: manifest[k] for k in ("student_01", "student_02", "student_03")}
    proc = subprocess.run(
        [sys.executable, "-m", "gandalf_core.grading.batch", str(subs), "--out", str(out), "--steps", "step01"]
        + ["--jobs", "2", "--students", *manifest],
        cwd=ROOT,
        env=ENV,
        capture_output=True,
        text=True,
        timeout=400,
    )
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    assert "[  3/3]" in proc.stdout, proc.stdout  # the progress line
    rows = {row["student"]: row for row in csv.DictReader((out / "gradebook.csv").open())}
    assert sorted(rows) == sorted(manifest)
    for student, done in manifest.items():
        expected = 2.0 if "hue.py" in done.get("step01_window", []) else 0.0
        row = rows[student]
        assert float(row["possible"]) == 2.0, row
        assert float(row["earned"]) == pytest.approx(expected), f"{student}: done {done}, gradebook {row}"
        assert float(row["step01_window:hsv_to_rgb"]) == pytest.approx(expected / 2)
        assert (out / student / "report.md").read_text().startswith(f"# {student}")
        gradescope = json.loads((out / student / "results.json").read_text())
        assert gradescope["score"] == pytest.approx(expected)
    book = json.loads((out / "gradebook.json").read_text())
    assert [b["student"] for b in book] == sorted(manifest) and all(not b["error"] for b in book)
    assert {round(b["earned"]) for b in book} == {0, 2}, "seed 1 should give a mix of done and not done"


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
        assert shlex.split(t["run"])[:3] == [".venv/bin/python", "-m", "gandalf_core.grading"]
    workflow = (ROOT / ".github" / "workflows" / "classroom.yml").read_text()
    assert "education/autograding" in workflow and "scripts/setup.sh" in workflow


@pytest.mark.parametrize("entry", range(7))
def test_each_classroom_command_collects_its_graded_tests(entry):
    t = _classroom()[entry]
    args = shlex.split(t["run"])
    assert args[0] == ".venv/bin/python"
    proc = subprocess.run(
        [sys.executable, *args[1:], "--collect-only", "-m", "exercise"],
        cwd=ROOT,
        env=ENV,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert proc.returncode == 0, proc.stdout[-2000:] + proc.stderr[-2000:]
    collected = [line for line in proc.stdout.splitlines() if "::" in line]
    step = args[3].split("/")[-1]
    assert collected and all(line.startswith(f"tests/{step}/") for line in collected), proc.stdout[-2000:]
