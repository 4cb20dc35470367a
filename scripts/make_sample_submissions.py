"""Make sample class submissions for trying the batch grader: ``--out DIR --count 30 [--seed 0]``.

Each student folder ``DIR/student_NN/`` holds a copy of every step's ``exercises/`` folder (the layout
``python -m gandalf_core.grading.batch`` expects) in which each exercise file (``hue.py``, ``ngon.py``,
``shading.glsl`` + ``shading.wgsl`` together, ...) is either the reference solution ("done") or the
untouched stub, drawn at random with a per-student probability (seeded: the same seed, the same class).
``DIR/manifest.json`` records which files each student has "done", so a test can check the gradebook.
"""

from __future__ import annotations

import argparse
import json
import random
import shutil
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SKIP = {"__init__.py"}


def exercise_units(step: Path) -> list[list[str]]:
    """The step's exercise files, grouped so that a shader's GLSL and WGSL twins go together."""
    names = sorted(p.name for p in (step / "exercises").iterdir() if p.is_file() and p.name not in SKIP)
    groups: dict[str, list[str]] = {}
    for name in names:
        stem, suffix = name.rsplit(".", 1) if "." in name else (name, "")
        key = stem if suffix in ("glsl", "wgsl") else name
        groups.setdefault(key, []).append(name)
    return [groups[k] for k in sorted(groups)]


def make(out: Path, count: int, seed: int = 0, steps: list[str] | None = None) -> dict[str, dict[str, list[str]]]:
    rng = random.Random(seed)
    step_dirs = sorted(p.parent.parent for p in ROOT.glob("step*/exercises/__init__.py"))
    if steps:
        step_dirs = [d for d in step_dirs if any(d.name.startswith(s) for s in steps)]
    manifest: dict[str, dict[str, list[str]]] = {}
    out.mkdir(parents=True, exist_ok=True)
    for i in range(count):
        student = f"student_{i + 1:02d}"
        diligence = rng.choice([0.0, 0.3, 0.6, 0.9, 1.0])  # how much of the work this student did
        done: dict[str, list[str]] = {}
        for step in step_dirs:
            target = out / student / step.name / "exercises"
            if target.exists():
                shutil.rmtree(target)
            shutil.copytree(step / "exercises", target, ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
            for unit in exercise_units(step):
                if rng.random() < diligence and all((step / "solutions" / n).is_file() for n in unit):
                    for name in unit:
                        shutil.copy2(step / "solutions" / name, target / name)
                    done.setdefault(step.name, []).extend(unit)
        manifest[student] = done
    (out / "manifest.json").write_text(json.dumps(manifest, indent=2, sort_keys=True))
    return manifest


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, required=True, help="folder for the submissions")
    parser.add_argument("--count", type=int, default=30, help="number of students (default 30)")
    parser.add_argument("--seed", type=int, default=0, help="random seed (default 0)")
    parser.add_argument("--steps", nargs="+", default=None, help="only these steps (prefixes, e.g. step01)")
    args = parser.parse_args(argv)
    if args.count < 1:
        parser.error("--count must be at least 1")
    manifest = make(args.out, args.count, args.seed, args.steps)
    done = sum(len(files) for student in manifest.values() for files in student.values())
    print(f"{len(manifest)} submissions in {args.out} ({done} exercise files done in all); manifest.json lists them")
    return 0


if __name__ == "__main__":
    sys.exit(main())
