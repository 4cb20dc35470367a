"""The grade is the same with and without pytest-xdist.

Runs ``pytest --student tests/step01_window`` (the untouched stubs, so every graded test fails with its own
message) in a subprocess once in one process and once with ``-n 2``, and compares the two grade JSON files
whole: scores, the per-test list and every failure message.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def _grade(tmp_path: Path, name: str, *args: str) -> dict:
    out = tmp_path / f"{name}.json"
    env = {k: v for k, v in os.environ.items() if k != "GANDALF_IMPL"}
    proc = subprocess.run(
        [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", "--student", "--grade-json", str(out)]
        + list(args)
        + ["tests/step01_window"],
        cwd=ROOT,
        env=env,
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert proc.returncode == 1, f"expected failed tests (exit 1), got {proc.returncode}:\n{proc.stdout[-3000:]}"
    return json.loads(out.read_text())


def test_grade_json_is_identical_with_and_without_xdist(tmp_path):
    serial = _grade(tmp_path, "serial")
    parallel = _grade(tmp_path, "parallel", "-n", "2")
    assert serial["graded_tests"] > 0
    assert [t["test"] for t in parallel["tests"]] == [t["test"] for t in serial["tests"]]
    assert parallel == serial
