"""Replays the hostile submissions kept in ``tests/attacks/<step>/``: each file is a replacement of one exercise module,
graded through the real front end (``python -m gandalf_tools.grading ... --impl <step>=<folder>``).

``python tests/attacks/replay.py [--root CHECKOUT]`` prints the points each attack gets (the grade file as the platform
would read it after the grading process ends) next to the untouched stub's and the reference solution's.
"""

from __future__ import annotations

import argparse
import json
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
ATTACKS = Path(__file__).resolve().parent
#: step package -> the exercise module each attack of its folder replaces.
TARGETS = {"step01_window": "hue.py"}


def attacks(step: str = "step01_window") -> list[Path]:
    return sorted(ATTACKS.glob(f"{step.split('_')[0]}/*.py"))


def submission(step: str, module: Path | None, into: Path, root: Path = ROOT) -> Path:
    """A copy of the step's exercises with ``module`` as its exercise module (None: the stub; "solution": the
    reference's)."""
    folder = into / "exercises"
    shutil.copytree(root / step / "exercises", folder, ignore=shutil.ignore_patterns("__pycache__"))
    if module is not None:
        shutil.copy(module, folder / TARGETS[step])
    return folder


def grade(step: str, folder: Path, out: Path, root: Path = ROOT, timeout: float = 600) -> float:
    """The points the grade file says after the front end ran on ``folder`` (0 when there is none)."""
    grade_file = out / "grade.json"
    cmd = [sys.executable, "-m", "gandalf_tools.grading", f"tests/{step}", "--impl", f"{step}={folder}",
           "--json", str(grade_file)]
    try:
        subprocess.run(cmd, cwd=root, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=timeout,
                       check=False)
    except subprocess.TimeoutExpired:
        pass
    try:
        return float(json.loads(grade_file.read_text())["earned"])
    except (OSError, ValueError, KeyError, TypeError):
        return 0.0


def grade_attack(step: str, module: Path | None, root: Path = ROOT) -> float:
    with tempfile.TemporaryDirectory(prefix="gandalf-attack-") as tmp:
        out = Path(tmp) / "out"
        out.mkdir()
        return grade(step, submission(step, module, Path(tmp), root), out, root)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", type=Path, default=ROOT, help="the checkout whose grader is attacked")
    parser.add_argument("--step", default="step01_window")
    args = parser.parse_args(argv)
    solution = args.root / args.step / "solutions" / TARGETS[args.step]
    print(f"{'stub':<28} {grade_attack(args.step, None, args.root):5.2f}", flush=True)
    print(f"{'solution':<28} {grade_attack(args.step, solution, args.root):5.2f}", flush=True)
    for attack in attacks(args.step):
        print(f"{attack.stem:<28} {grade_attack(args.step, attack, args.root):5.2f}", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
