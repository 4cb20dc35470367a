"""Shared by the tests of the mutation check and the fairness check: run one of the two commands in a subprocess
on definitions written to a temporary folder, and read its outcomes back."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import textwrap
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def run_check(module: str, tmp_path: Path, folder: str, definitions: str, *args: str) -> tuple[int, str, list[dict]]:
    """``python -m gandalf_tools.grading.<module> --dir <tmp_path/folder>`` with ``definitions`` as the folder's
    ``step01_window.py``: (exit code, output, the outcomes of ``--json``)."""
    where = tmp_path / folder
    where.mkdir(exist_ok=True)
    (where / "step01_window.py").write_text(textwrap.dedent(definitions))
    out = tmp_path / "outcomes.json"
    env = {k: v for k, v in os.environ.items() if k != "GANDALF_IMPL"}
    proc = subprocess.run(
        [sys.executable, "-m", f"gandalf_tools.grading.{module}", "--dir", str(where), "--json", str(out), *args],
        cwd=ROOT, env=env, capture_output=True, text=True, timeout=300,
    )
    return proc.returncode, proc.stdout + proc.stderr, json.loads(out.read_text()) if out.exists() else []
