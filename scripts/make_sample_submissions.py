"""Make a sample class for the batch grader: ``--out DIR [--count 30] [--seed 0] [--steps step01 ...]``.

Each student folder ``DIR/student_NN/`` holds a copy of every step's ``exercises/`` folder (the layout
``python -m gandalf_tools.grading.batch`` expects). Each *unit* of a step (an exercise file, or the files that one
exercise's graded tests read together: a shader's GLSL and WGSL twins, step 06's ``optics.py`` with the shading
shaders) is either the reference solution ("done") or the untouched stub. Deterministic for a seed, and varied:

* ``student_01`` hands in the untouched stubs, ``student_02`` every solution;
* ``student_03`` .. ``student_05`` are broken on purpose (with the rest drawn at random): a runaway loop in
  step 02's ``NGonSystem``, a hard exit (``os._exit``) there, and a Python syntax error in step 03's ``uvs.py``
  (which breaks the import of that step's whole ``exercises`` package);
* everyone else did a random share of the units (a per-student diligence of 0.2 .. 1.0).

``DIR/manifest.json`` records per student what was done and what was broken; :func:`expected_points` turns an
entry and a student's ``grade.json`` into the points each exercise must get (an exercise earns its points when
every file its graded tests read is a solution and none is broken, else 0), and ``--check GRADES`` compares a
batch gradebook with it, so the grader's arithmetic is checked end to end. ``EXERCISE_FILES`` says which files
each exercise's graded tests read; an exercise missing from it is reported as unchecked, never guessed.
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

# Which exercise files each exercise's graded tests read (stems stand for both .glsl and .wgsl).
EXERCISE_FILES: dict[str, dict[str, list[str]]] = {
    "step01_window": {"hsv_to_rgb": ["hue.py"], "HueCycleSystem": ["hue.py"]},
    "step02_triangle": {"interleave": ["vertex_data.py"], "ngon_mesh": ["ngon.py"], "NGonSystem": ["ngon.py"]},
    "step03_textures": {"brick_texture": ["bricks.py"], "cube_cross_uvs": ["uvs.py"]},
    "step04_camera": {"look_at": ["projection.py"], "perspective": ["projection.py"],
                      "OrbitCameraSystem": ["orbit.py"]},
    "step05_scenegraph": {**{name: ["house.py"] for name in ("brick_texture_data", "house_camera",
                                                              "house_material_data", "house_meshes",
                                                              "HouseRotationSystem")},
                          "rk4_step": ["integrators.py"], "semi_implicit_euler_step": ["integrators.py"]},
    "step06_lighting": {"blinn_phong": ["shading"], "reflect_refract": ["optics.py", "shading"],
                        "LightCollectionSystem": ["lights.py"]},
    "step07_advanced": {**{name: ["brdf"] for name in ("fresnel", "ggx_distribution", "ggx_specular",
                                                        "metallic_roughness", "smith_geometry")},
                        **{name: ["terrain"] for name in ("terrain_lod", "terrain_height", "terrain_normal")},
                        "normal_map": ["normal_map"], "particle_step": ["particle_step"],
                        "explode_offset": ["explode"], "blur_kernel": ["blur_kernel"], "convolve": ["convolve"],
                        "parallax": ["parallax"], "hit_sphere": ["ray_sphere"],
                        "scatter_dielectric": ["dielectric"]},
}

# Broken on purpose: (student number, step, file, what breaks, (anchor text, replacement), exercises it breaks;
# "*" = the step's whole package fails to import).
_NGON_ANCHOR = "    def on_create_entity(self, entity, components) -> None:\n"
BROKEN = [
    (3, "step02_triangle", "ngon.py", "runaway loop",
     (_NGON_ANCHOR, _NGON_ANCHOR + "        while True:  # sample submission: a runaway loop\n            pass\n"),
     ["NGonSystem"]),
    (4, "step02_triangle", "ngon.py", "hard exit",
     (_NGON_ANCHOR, _NGON_ANCHOR + "        import os\n\n        os._exit(3)  # sample submission: a hard exit\n"),
     ["NGonSystem"]),
    (5, "step03_textures", "uvs.py", "syntax error",
     ("def cube_cross_uvs(", "def cube_cross_uvs_broken(positions normals):  # a syntax error\n    pass\n\n\n"
      "def cube_cross_uvs("), ["*"]),
]


def _stem(name: str) -> str:
    return name.rsplit(".", 1)[0] if name.endswith((".glsl", ".wgsl")) else name


def exercise_units(step: Path) -> list[list[str]]:
    """The step's exercise files in groups that are done or not together: shader twins (``x.glsl`` + ``x.wgsl``)
    and, through ``EXERCISE_FILES``, the files one exercise's tests read together."""
    names = sorted(p.name for p in (step / "exercises").iterdir() if p.is_file() and p.name not in SKIP)
    parent = {name: name for name in names}

    def find(x: str) -> str:
        while parent[x] != x:
            x = parent[x]
        return x

    def union(a: str, b: str) -> None:
        parent[find(a)] = find(b)

    by_stem: dict[str, list[str]] = {}
    for name in names:
        by_stem.setdefault(_stem(name), []).append(name)
    for group in by_stem.values():
        for other in group[1:]:
            union(group[0], other)
    for files in EXERCISE_FILES.get(step.name, {}).values():
        present = [n for f in files for n in by_stem.get(f, [])]
        for other in present[1:]:
            union(present[0], other)
    units: dict[str, list[str]] = {}
    for name in names:
        units.setdefault(find(name), []).append(name)
    return sorted(units.values())


def _break(target: Path, step: str, file: str, anchor: str, replacement: str) -> None:
    path = target / file
    text = path.read_text()
    if text.count(anchor) != 1:
        raise SystemExit(f"make_sample_submissions: {step}/solutions/{file} no longer holds {anchor!r} exactly "
                         f"once; update BROKEN in {Path(__file__).name}")
    path.write_text(text.replace(anchor, replacement))


def make(out: Path, count: int, seed: int = 0, steps: list[str] | None = None) -> dict[str, dict]:
    """Write ``count`` submissions and ``manifest.json`` into ``out``; return the manifest."""
    rng = random.Random(seed)
    step_dirs = sorted(p.parent.parent for p in ROOT.glob("step*/exercises/__init__.py"))
    if steps:
        step_dirs = [d for d in step_dirs if any(d.name.startswith(s) for s in steps)]
    if not step_dirs:
        raise SystemExit(f"make_sample_submissions: --steps {steps} matches no step with exercises")
    manifest: dict[str, dict] = {}
    out.mkdir(parents=True, exist_ok=True)
    for i in range(1, count + 1):
        student = f"student_{i:02d}"
        kind, diligence = "random", rng.choice([0.2, 0.4, 0.6, 0.8, 1.0])
        if i == 1:
            kind, diligence = "stubs", 0.0
        elif i == 2:
            kind, diligence = "solutions", 1.0
        broken = [b for b in BROKEN if b[0] == i and b[1] in {d.name for d in step_dirs}]
        if broken:
            kind = broken[0][3]
        done: dict[str, list[str]] = {}
        broken_entry: dict[str, dict[str, list[str]]] = {}
        for step in step_dirs:
            target = out / student / step.name / "exercises"
            if target.exists():
                shutil.rmtree(target)
            shutil.copytree(step / "exercises", target, ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
            for unit in exercise_units(step):
                forced = any(b[1] == step.name and b[2] in unit for b in broken)
                if (forced or rng.random() < diligence) and all((step / "solutions" / n).is_file() for n in unit):
                    for name in unit:
                        shutil.copy2(step / "solutions" / name, target / name)
                    done.setdefault(step.name, []).extend(unit)
            for _, b_step, file, _what, (anchor, replacement), exercises in broken:
                if b_step == step.name:
                    _break(target, step.name, file, anchor, replacement)
                    broken_entry.setdefault(step.name, {})[file] = exercises
        manifest[student] = {"kind": kind, "done": done, "broken": broken_entry}
    (out / "manifest.json").write_text(json.dumps(manifest, indent=2, sort_keys=True))
    return manifest


def expected_points(entry: dict, exercises: list[dict]) -> dict[tuple[str, str], float | None]:
    """The points each exercise must earn: ``exercises`` are a ``grade.json``'s (step, exercise, possible);
    None where ``EXERCISE_FILES`` does not know the exercise (unchecked)."""
    expected: dict[tuple[str, str], float | None] = {}
    for x in exercises:
        step, name = x["step"], x["exercise"]
        files = EXERCISE_FILES.get(step, {}).get(name)
        if files is None:
            expected[(step, name)] = None
            continue
        done = {_stem(f) for f in entry["done"].get(step, [])}
        broken = entry["broken"].get(step, {})
        whole_step_broken = any("*" in hit for hit in broken.values())
        hit = any(name in exercises_hit for exercises_hit in broken.values())
        ok = all(_stem(f) in done for f in files) and not whole_step_broken and not hit
        expected[(step, name)] = float(x["possible"]) if ok else 0.0
    return expected


def check(submissions: Path, grades: Path) -> list[str]:
    """Compare a batch run's per-student ``grade.json`` with the manifest; return the mismatches."""
    manifest = json.loads((submissions / "manifest.json").read_text())
    problems: list[str] = []
    unchecked: set[str] = set()
    for student, entry in sorted(manifest.items()):
        grade_file = grades / student / "grade.json"
        if not grade_file.is_file():
            problems.append(f"{student}: no grade.json in {grades / student}")
            continue
        grade = json.loads(grade_file.read_text())
        expected = expected_points(entry, grade["exercises"])
        for x in grade["exercises"]:
            want = expected[(x["step"], x["exercise"])]
            if want is None:
                unchecked.add(f"{x['step']}:{x['exercise']}")
            elif abs(want - x["earned"]) > 1e-9:
                problems.append(f"{student} ({entry['kind']}): {x['step']}:{x['exercise']} earned {x['earned']:.4f}, "
                                f"expected {want:.4f} ({int(x['passed'])}/{int(x['tests'])} tests passed)")
        total = sum(v for v in expected.values() if v is not None)
        checked = sum(x["earned"] for x in grade["exercises"] if expected[(x["step"], x["exercise"])] is not None)
        if abs(total - checked) > 1e-9 and not any(p.startswith(student + " ") for p in problems):
            problems.append(f"{student}: total {checked:.4f} != expected {total:.4f}")
    for name in sorted(unchecked):
        print(f"unchecked (not in EXERCISE_FILES): {name}")
    return problems


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, help="folder for the submissions (and manifest.json)")
    parser.add_argument("--count", type=int, default=30, help="number of students (default 30)")
    parser.add_argument("--seed", type=int, default=0, help="random seed (default 0)")
    parser.add_argument("--steps", nargs="+", default=None, help="only these steps (prefixes, e.g. step01)")
    parser.add_argument("--check", type=Path, metavar="GRADES",
                        help="instead: compare the batch grader's output folder GRADES with --out's manifest")
    args = parser.parse_args(argv)
    if args.out is None:
        parser.error("--out is required")
    if args.check is not None:
        problems = check(args.out, args.check)
        for line in problems:
            print(f"MISMATCH {line}")
        students = len(json.loads((args.out / "manifest.json").read_text()))
        print(f"{students} students checked against the manifest: {len(problems)} mismatches")
        return 1 if problems else 0
    if args.count < 1:
        parser.error("--count must be at least 1")
    manifest = make(args.out, args.count, args.seed, args.steps)
    done = sum(len(files) for student in manifest.values() for files in student["done"].values())
    kinds = sorted({entry["kind"] for entry in manifest.values()})
    print(f"{len(manifest)} submissions in {args.out} ({done} exercise files done in all; kinds: {', '.join(kinds)}); "
          f"manifest.json lists them")
    return 0


if __name__ == "__main__":
    sys.exit(main())
