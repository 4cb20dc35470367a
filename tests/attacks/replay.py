"""Replays the hostile submissions kept in ``tests/attacks/<step>/``: each file is a replacement of one exercise module.

Three ways the course grades, each through its real entry point:

* **front end**: ``python -m gandalf_tools.grading tests/<step> --impl <step>=<folder> --json grade.json``;
* **Gradescope**: the instructors page's ``run_autograder`` (``GANDALF_IMPL=<step>=<folder> python -m
  gandalf_tools.grading tests/<step> --gradescope results.json``): the same run gives both files, so one run per attack
  reads the points of both;
* **batch**: ``python -m gandalf_tools.grading.batch CLASS --out OUT --jobs 2`` over a class of honest classmates
  (a correct submission before the attackers; a correct one, a partial one and the untouched stub after them) and every
  attacker, next to a batch of the same classmates alone.

An attack may name the instructor's paths it aims at (assumed known: they are on the instructors page) with
placeholders the replay fills in: ``@@ROOT@@`` (the checkout), ``@@SITE@@`` (the venv's site-packages),
``@@PYCACHE@@`` (the graders' bytecode cache), ``@@CLASS@@``, ``@@OUT@@``, ``@@RESULTS@@`` (the class folder, the
output folder, the Gradescope results file) and ``@@ME@@`` (its own student folder's name). Attacks that would harm
the machine's other work if they got through act only in processes with ``GANDALF_ATTACK_REPLAY`` set (the replay's).

:func:`Damage` records every file outside the attacker's own output that a grading run must not change (the class
folder, the checkout's conftest files, the venv's ``.pth`` files, the bytecode cache's and the standard library's
``colorsys``) and puts back what changed.

``python tests/attacks/replay.py [--batch]`` prints the table: attack, points (front end / Gradescope / batch),
classmates affected, flags.
"""

from __future__ import annotations

import argparse
import colorsys
import hashlib
import importlib.util
import json
import marshal
import os
import shutil
import subprocess
import sys
import sysconfig
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
ATTACKS = Path(__file__).resolve().parent
#: step package -> the exercise module each attack of its folder replaces.
TARGETS = {"step01_window": "hue.py"}
#: step package -> the points its exercises are worth.
FULL_MARKS = {"step01_window": 2.0}
REPLAY_ENV = "GANDALF_ATTACK_REPLAY"
SITE = Path(sysconfig.get_paths()["purelib"])
#: Seconds a detached process is given to act after a grading run ends, before the files are checked.
AFTERMATH = 3.0
#: The kinds of honest classmates in a batch.
HONEST = ("correct", "partial", "stub")
PARTIAL_TAIL = '''

def hsv_to_rgb(hue, saturation, value):  # noqa: F811 - the first exercise done, the second not
    import colorsys
    return colorsys.hsv_to_rgb((hue % 360.0) / 360.0, saturation, value)
'''


def attacks(step: str = "step01_window") -> list[Path]:
    """The step's attack files (``_common.py`` is the parts they share, shipped beside each)."""
    return sorted(p for p in ATTACKS.glob(f"{step.split('_')[0]}/*.py") if not p.name.startswith("_"))


def honest_module(step: str, kind: str, root: Path = ROOT) -> str | None:
    """The exercise module's text of an honest classmate: "correct" (the reference), "partial" (the first exercise
    done), "stub" (None: untouched)."""
    if kind == "correct":
        return (root / step / "solutions" / TARGETS[step]).read_text()
    if kind == "partial":
        return (root / step / "exercises" / TARGETS[step]).read_text() + PARTIAL_TAIL
    return None


def render(text: str, places: dict[str, str]) -> str:
    for name, value in places.items():
        text = text.replace(f"@@{name}@@", value)
    return text


def places(out: Path, klass: Path, results: Path | None, me: str, root: Path = ROOT) -> dict[str, str]:
    from gandalf_tools.grading import pycache_dir

    return {"ROOT": str(root), "SITE": str(SITE), "PYCACHE": pycache_dir() or "", "CLASS": str(klass),
            "OUT": str(out), "RESULTS": str(results or ""), "ME": me}


def submission(step: str, module: Path | str | None, into: Path, root: Path = ROOT,
               fill: dict[str, str] | None = None) -> Path:
    """A copy of the step's exercises under ``into/<step>/exercises`` with ``module`` (a file, or its text) as its
    exercise module, its placeholders filled (None: the untouched stub)."""
    folder = into / step / "exercises"
    shutil.copytree(root / step / "exercises", folder, ignore=shutil.ignore_patterns("__pycache__"))
    if module is not None:
        text = module.read_text() if isinstance(module, Path) else module
        (folder / TARGETS[step]).write_text(render(text, fill or {}))
        common = ATTACKS / step.split("_")[0] / "_common.py"
        if "attack_common" in text and common.is_file():  # a submission is a package: it may bring a module of its own
            shutil.copy(common, folder / "attack_common.py")
    return folder


def _digest(path: Path) -> str | None:
    try:
        return hashlib.sha256(path.read_bytes()).hexdigest()
    except OSError:
        return None


def _compiled_colorsys(data: bytes | None) -> bool:
    """Whether ``data`` is absent or the bytecode of the real ``colorsys`` (any Python process without a bytecode
    cache may write that one, for instance after it was removed)."""
    if data is None:
        return True
    try:
        code = marshal.loads(data[16:])
    except (ValueError, EOFError, TypeError):
        return False
    return code.co_names == compile(Path(colorsys.__file__).read_text(), colorsys.__file__, "exec").co_names


@dataclass
class Damage:
    """The files a grading run must leave alone, taken before it; :meth:`check` says what changed and restores it."""

    klass: Path | None = None
    root: Path = ROOT
    saved: dict[Path, bytes | None] = field(default_factory=dict)
    class_files: dict[Path, str | None] = field(default_factory=dict)

    def __post_init__(self) -> None:
        from gandalf_tools.grading import pycache_dir

        watched = [self.root / "conftest.py", *self.root.glob("tests/conftest.py"),
                   *self.root.glob("tests/*/conftest.py"), Path(importlib.util.cache_from_source(colorsys.__file__))]
        cache = pycache_dir()
        if cache:
            watched.append(Path(cache + str(watched[-1])))
        for path in watched:
            self.saved[path] = path.read_bytes() if path.is_file() else None
        self.pth = set(SITE.glob("*.pth"))
        if self.klass is not None:
            self.class_files = {p: _digest(p) for p in self.klass.rglob("*") if p.is_file()}

    def check(self) -> list[str]:
        """What changed (``path: what``), after putting it back."""
        changed = []
        for path, before in self.saved.items():
            now = path.read_bytes() if path.is_file() else None
            if now != before and not (path.suffix == ".pyc" and _compiled_colorsys(now)):
                changed.append(f"{path}: changed")
                if before is None:
                    path.unlink(missing_ok=True)
                else:
                    path.write_bytes(before)
        for path in set(SITE.glob("*.pth")) - self.pth:
            changed.append(f"{path}: new")
            path.unlink(missing_ok=True)
        if self.klass is not None:
            now = {p: _digest(p) for p in self.klass.rglob("*") if p.is_file()}
            changed += [f"{p}: changed" for p in sorted(set(now) | set(self.class_files))
                        if now.get(p) != self.class_files.get(p)]
        return changed


def replay_env() -> dict[str, str]:
    return {**os.environ, REPLAY_ENV: "1"}


@dataclass
class Single:
    """One submission graded as the front end and Gradescope's ``run_autograder`` do."""

    front_end: float  # grade.json's earned
    gradescope: float  # results.json's score
    changed: list[str]  # files outside its own output that changed (put back)
    flags: str = ""


def _points(path: Path, key: str) -> float:
    try:
        return float(json.loads(path.read_text())[key])
    except (OSError, ValueError, KeyError, TypeError):
        return 0.0


def grade_single(step: str, module: Path | str | None, root: Path = ROOT, timeout: float = 600) -> Single:
    """Grade ``module`` alone, the way ``run_autograder`` does: the submission in ``<tmp>/submission/<step>/exercises``,
    ``GANDALF_IMPL`` set, ``--json`` and ``--gradescope`` in ``<tmp>/results``; both files are read after the run and
    a short wait (what a detached process left there counts)."""
    with tempfile.TemporaryDirectory(prefix="gandalf-attack-") as tmp:
        results = Path(tmp) / "results"
        results.mkdir()
        klass = Path(tmp) / "submission"
        fill = places(results, klass, results / "results.json", "submission", root)
        folder = submission(step, module, klass, root, fill)
        damage = Damage(klass, root)
        cmd = [sys.executable, "-m", "gandalf_tools.grading", f"tests/{step}", "--json", str(results / "grade.json"),
               "--gradescope", str(results / "results.json")]
        env = {**replay_env(), "GANDALF_IMPL": f"{step}={folder}"}
        try:
            subprocess.run(cmd, cwd=root, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                           timeout=timeout, check=False)
        except subprocess.TimeoutExpired:
            pass
        if module is not None and "@@RESULTS@@" in (module.read_text() if isinstance(module, Path) else module):
            time.sleep(AFTERMATH)  # an attack that aims at the results file has had its chance after the run
        grade = json.loads((results / "grade.json").read_text()) if (results / "grade.json").is_file() else {}
        return Single(_points(results / "grade.json", "earned"), _points(results / "results.json", "score"),
                      damage.check(), ", ".join(grade.get("flags", [])))


def grade_attack(step: str, module: Path | None, root: Path = ROOT) -> float:
    """The points the front end's grade file says for ``module`` (0 when there is none)."""
    return grade_single(step, module, root).front_end


@dataclass
class Batch:
    """The gradebook of one batch (student -> its row) and the files outside the attackers' outputs that changed."""

    rows: dict[str, dict]
    changed: list[str]
    seconds: float


def grade_batch(step: str, modules: dict[str, Path | str | None], *, jobs: int = 2, root: Path = ROOT,
                timeout: float = 900) -> Batch:
    """Grade a class (student -> its exercise module) with the batch grader; read the gradebook after a short wait."""
    with tempfile.TemporaryDirectory(prefix="gandalf-attack-batch-") as tmp:
        klass, out = Path(tmp) / "class", Path(tmp) / "out"
        klass.mkdir()
        for student, module in modules.items():
            submission(step, module, klass / student, root, places(out, klass, None, student, root))
        damage = Damage(klass, root)
        cmd = [sys.executable, "-m", "gandalf_tools.grading.batch", str(klass), "--out", str(out), "--jobs",
               str(jobs), "--steps", step, "--allow-unisolated"]  # a machine without namespaces: what can be kept
        start = time.perf_counter()
        subprocess.run(cmd, cwd=root, env=replay_env(), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                       timeout=timeout, check=False)
        seconds = time.perf_counter() - start
        gradebook = out / "gradebook.json"
        before = {p: _digest(p) for p in out.rglob("*") if p.is_file()}
        if any(isinstance(m, Path) and "@@OUT@@" in m.read_text() for m in modules.values()):
            time.sleep(AFTERMATH)
        after = {p: _digest(p) for p in out.rglob("*") if p.is_file()}
        changed = damage.check() + [f"{p}: changed after the batch" for p in sorted(set(before) | set(after))
                                    if before.get(p) != after.get(p)]
        rows = {row["student"]: row for row in json.loads(gradebook.read_text())} if gradebook.is_file() else {}
        for student, row in rows.items():  # each student's own grade file must say what its row says
            own = out / student / "grade.json"
            if own.is_file() and abs(_points(own, "earned") - row["earned"]) > 1e-9:
                changed.append(f"{own}: says {_points(own, 'earned')}, the gradebook {row['earned']}")
        return Batch(rows, changed, seconds)


def honest_class(step: str, root: Path = ROOT) -> dict[str, str | None]:
    """The honest classmates: a correct one graded before the attackers (``a_``: beside the first of them), and each
    kind graded after them (``z_``: what the attackers left behind reaches them)."""
    return {"a_correct": honest_module(step, "correct", root),
            **{f"z_{kind}": honest_module(step, kind, root) for kind in HONEST}}


def contained_here(attack: Path) -> bool:
    """Whether this machine can keep ``attack`` from the grader's files: one that reads the checkout or writes the
    instructor's files is not replayed where the grader has no namespaces (its student's process can read and write
    what the grader's user can; such a grade is flagged, see the instructors page)."""
    from gandalf_tools.grading import sandbox

    return not (sandbox.isolation() == "process" and ("solution" in attack.stem or "@@" in attack.read_text()))


def classmates_affected(alone: Batch, both: Batch) -> list[str]:
    """The honest classmates whose row in the batch with attackers differs from their row in the batch of the
    classmates alone (other points per exercise, or an error)."""
    def row(batch: Batch, student: str) -> tuple:
        return batch.rows.get(student, {}).get("exercises"), batch.rows.get(student, {}).get("error")

    return [s for s, r in alone.rows.items() if row(both, s) != (r["exercises"], "")]


def batch_verdict(alone: Batch, both: Batch, hostile: dict[str, Path]) -> list[str]:
    """What is wrong with a batch of attackers among classmates (empty: nothing): a file outside the outputs
    changed, a classmate affected, an attacker above the stub's row or without a row."""
    wrong = [f"batch: {c}" for c in both.changed]
    wrong += [f"batch: classmate {s} affected" for s in classmates_affected(alone, both)]
    floor = alone.rows.get("z_stub", {}).get("earned", 0.0)
    wrong += [f"batch: {s} gained points" for s in hostile if both.rows.get(s, {}).get("earned", 0.0) > floor]
    wrong += [f"batch: {s} has no row" for s in hostile if s not in both.rows]
    return wrong


def verdict(step: str, singles: dict[str, Single], alone: Batch | None, both: Batch | None,
            hostile: dict[str, Path]) -> list[str]:
    """What is wrong with a replay (empty: nothing): the reference without full marks, an attacker above the
    stub in any mode, a file outside an attacker's output changed, a classmate whose row differs from the batch of
    the classmates alone."""
    wrong = []
    stub, solution = singles["stub"], singles["solution"]
    if min(solution.front_end, solution.gradescope) < FULL_MARKS[step] - 1e-9:
        wrong.append(f"the reference solution got {solution.front_end} / {solution.gradescope}, not full marks")
    for name, s in singles.items():
        if name in ("stub", "solution"):
            continue
        if s.front_end > stub.front_end + 1e-9 or s.gradescope > stub.gradescope + 1e-9:
            wrong.append(f"{name}: gained points ({s.front_end} front end, {s.gradescope} Gradescope)")
        wrong += [f"{name}: {c}" for c in s.changed]
    if alone is not None and both is not None:
        wrong += batch_verdict(alone, both, hostile)
    return wrong


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", type=Path, default=ROOT, help="the checkout whose grader is attacked")
    parser.add_argument("--step", default="step01_window")
    parser.add_argument("--batch", action="store_true", help="also grade every attacker in one batch with classmates")
    parser.add_argument("--check", action="store_true",
                        help="exit 1 when an attacker gains a point or changes a file, or a classmate is affected "
                             "(attacks this machine cannot contain are left out and named)")
    args = parser.parse_args(argv)
    step = args.step
    start = time.perf_counter()
    chosen = [a for a in attacks(step) if not args.check or contained_here(a)]
    for attack in sorted(set(attacks(step)) - set(chosen)):
        print(f"left out (this machine has no namespaces): {attack.stem}")
    singles = {"stub": grade_single(step, None, args.root),
               "solution": grade_single(step, args.root / step / "solutions" / TARGETS[step], args.root)}
    singles |= {a.stem: grade_single(step, a, args.root) for a in chosen}
    rows: dict[str, dict] = {}
    alone = both = None
    hostile = {f"m_{a.stem}": a for a in chosen}
    if args.batch:
        alone = grade_batch(step, honest_class(step, args.root), root=args.root)
        both = grade_batch(step, {**honest_class(step, args.root), **hostile}, root=args.root)
        rows = both.rows
        hurt = classmates_affected(alone, both)
        affected = "yes: " + ", ".join(hurt) if hurt else "no"
        print(f"batch of {len(both.rows)} in {both.seconds:.0f} s (classmates alone {alone.seconds:.0f} s); "
              f"classmates affected: {affected}; files changed: {both.changed or 'none'}")
    print(f"{'attack':<28} {'front':>6} {'gs':>6} {'batch':>6}  flags / files changed")
    for name, s in singles.items():
        row = rows.get(f"m_{name}", {})
        batch = f"{row['earned']:6.2f}" if row else "     -"
        flags = "; ".join(x for x in (s.flags, row.get("error", ""), *s.changed) if x)
        print(f"{name:<28} {s.front_end:6.2f} {s.gradescope:6.2f} {batch}  {flags}", flush=True)
    if not args.check:
        return 0
    wrong = verdict(step, singles, alone, both, hostile)
    for line in wrong:
        print("ATTACK GOT THROUGH:", line)
    print(f"{len(chosen)} attacks replayed in {time.perf_counter() - start:.0f} s: "
          f"{'0 points gained, 0 files changed' if not wrong else f'{len(wrong)} problems'}"
          f"{', 0 classmates affected' if args.batch and not wrong else ''}")
    return 1 if wrong else 0


if __name__ == "__main__":
    sys.exit(main())
