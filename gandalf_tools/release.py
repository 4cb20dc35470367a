"""The student release: ``python -m gandalf_tools.release OUT [--zip]`` makes what students get.

A template repository folder ``OUT`` (and with ``--zip``, ``OUT.zip`` beside it) built from the course's tracked files
(``git ls-files``; outside a git checkout, the files of that copy, or of the installed wheel's packages only): the
engine, the steps with their exercise stubs, the public tests, the docs, the notebooks, README, ``run.sh`` and the
scripts. Left out, each for a stated reason:

* every ``solutions/`` folder: the reference answers;
* ``tests/mutants/``: plausible wrong answers, most of them the reference with one thing changed;
* **hidden tests**: any file or folder whose name is ``hidden``, starts with ``hidden_`` or whose stem ends with
  ``_hidden`` (``tests/step01_window/test_hue_hidden.py``, ``tests/step01_window/hidden/``). Hidden graded tests
  live only in the instructor's copy and grade the class there (the batch grader, the Gradescope image);
* the instructor's tools and data (:data:`INSTRUCTOR_ONLY`): the course's CI, the mutation check, the sample-class
  script, the grading benchmark and benchmark results, the grader's own tests;
* every test module that names a ``solutions`` package (imports it, or names it in a string) or holds lines of the
  reference's source: it cannot run without the reference, or it would show it. Such modules are listed when the
  release is built; a public graded test belongs in a module that needs neither.

The release is then checked (:func:`check_release`): no path of a solution, a mutant or a hidden test; no Python
file, notebook or page that imports a ``solutions`` package; no file holding the reference's lines (two or more
lines, of 20 characters or more, that occur in a ``solutions/`` file and in no engine or stub file); no file equal
to a solution file. Everything in the release runs without the solutions: where a step has no ``solutions/``, its
launcher, the tour and the grader use the student's ``exercises/`` (``gandalf_core.app.cli.load_impl``), so
``./run.sh test`` grades the student.

``--solved DIR`` also writes a copy of the release with the reference solutions copied over the exercises: its
graded tests must all pass, as they must all fail on the release's stubs (the course's CI checks both).
"""

from __future__ import annotations

import argparse
import ast
import functools
import hashlib
import json
import re
import shutil
import subprocess
import sys
import time
import zipfile
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
#: What a copy of the course that is not a git checkout holds besides the course (environments, build output).
_NOT_COURSE = {".git", ".venv", "build", "dist", "site", "out", ".pytest_cache", ".ruff_cache", ".hypothesis",
               "__pycache__"}

#: Tracked paths (a folder ends with ``/``; a name ending in ``*`` is a prefix) that only the instructor gets.
INSTRUCTOR_ONLY = {
    ".ci/": "the course's own CI: it grades the solutions and runs the mutation check",
    "tests/mutants/": "plausible wrong answers, most of them the reference with one thing changed",
    "gandalf_tools/grading/mutants.py": "the mutation check: it needs the solutions and tests/mutants/",
    "scripts/make_sample_submissions.py": "makes a sample class out of the solutions",
    "benchmarks/bench_grading.py": "grades the solutions as one student's submission",
    "benchmarks/results/": "the instructor's measured runs, the whole suite's outcomes included",
    "tests/core/test_grading_*": "the grader's own tests: fake steps with solutions, sample classes, mutants",
    "tests/core/test_release.py": "builds a release out of the instructor's tree",
}
#: A solution line this long or longer is the reference's own text (shorter ones are idioms every file shares).
FINGERPRINT_MIN = 20
#: A file holding this many of the reference's lines holds a copy of it.
FINGERPRINT_HITS = 2
_SCANNED = (".py", ".glsl", ".wgsl", ".vert", ".frag", ".geom", ".tesc", ".tese", ".comp", ".md", ".ipynb", ".txt",
            ".json", ".toml", ".yml", ".yaml", ".sh", ".cfg", ".csv", ".jsonl")
_MD_IMPORT = re.compile(r"^\s*(?:from\s+\S*\bsolutions\b\S*\s+import|from\s+\S+\s+import\s+.*\bsolutions\b|"
                        r"import\s+\S*\.solutions\b)", re.M)


# ---------------------------------------------------------------------------------------------------
# What is tracked, and what of it a student gets
# ---------------------------------------------------------------------------------------------------


def tracked_files(root: Path = ROOT) -> tuple[Path, list[str]]:
    """(base folder, the course's files relative to it): ``git ls-files`` in a checkout; elsewhere every file of a
    copy of the course (a folder with ``pyproject.toml``), or of the course's packages where they are installed from
    the wheel (no tests, docs or scripts there)."""
    root = Path(root).resolve()
    if (root / ".git").exists() and shutil.which("git"):
        out = subprocess.run(["git", "ls-files", "-z"], cwd=root, capture_output=True, check=True).stdout
        return root, sorted(p for p in out.decode().split("\0") if p and (root / p).is_file())
    if (root / "pyproject.toml").is_file():
        tops = [p for p in root.iterdir() if p.name not in _NOT_COURSE and not p.name.endswith(".egg-info")]
    else:
        packages = ("gandalf_core", "gandalf_tools", "step0")
        tops = [p for p in root.iterdir() if p.is_dir() and p.name.startswith(packages)]
    files = []
    for top in tops:
        for path in [top] if top.is_file() else top.rglob("*"):
            if path.is_file() and "__pycache__" not in path.parts and path.suffix != ".pyc":
                files.append(path.relative_to(root).as_posix())
    return root, sorted(files)


def is_hidden(path: str) -> bool:
    """The hidden-test convention: a file or folder named ``hidden``, ``hidden_*`` or ``*_hidden``."""
    for part in path.split("/"):
        stem = part.split(".")[0]
        if stem == "hidden" or stem.startswith("hidden_") or stem.endswith("_hidden"):
            return True
    return False


def excluded(path: str) -> str | None:
    """Why ``path`` (relative, with ``/``) stays out of the release by its name alone; None when it ships."""
    parts = path.split("/")
    if "solutions" in parts[:-1]:
        return "a reference solution"
    if is_hidden(path):
        return "a hidden test"
    for pattern, why in INSTRUCTOR_ONLY.items():
        if pattern.endswith("/") and path.startswith(pattern):
            return why
        if pattern.endswith("*") and path.startswith(pattern[:-1]):
            return why
        if path == pattern:
            return why
    return None


# ---------------------------------------------------------------------------------------------------
# Reading files for the reference: imports of a solutions package, and the reference's own lines
# ---------------------------------------------------------------------------------------------------


def _names_solutions(dotted: str | None) -> bool:
    return bool(dotted) and "solutions" in dotted.split(".")


def python_solution_refs(text: str, strings: bool = False) -> list[str]:
    """What in Python source ``text`` reaches a ``solutions`` package: its imports, and with ``strings`` the
    string constants that name it (``"solutions"``, ``"x.solutions"``, ``"solutions/..."``; docstrings are
    prose and do not count)."""
    return list(_python_solution_refs(text, strings))


@functools.lru_cache(maxsize=4096)
def _python_solution_refs(text: str, strings: bool) -> tuple[str, ...]:
    # Remembered by text: a build reads each file once to choose it and once more in the release it checks.
    found = []
    docstrings = set()
    # One breadth-first walk: a body's first statement is met after its function, class or module, so a docstring
    # is known as one before its constant is reached.
    for node in ast.walk(ast.parse(text)):
        if isinstance(node, (ast.Module, ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)) and node.body:
            first = node.body[0]
            if isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant):
                docstrings.add(id(first.value))
        elif isinstance(node, ast.Import):
            found += [f"line {node.lineno}: import {a.name}" for a in node.names if _names_solutions(a.name)]
        elif isinstance(node, ast.ImportFrom):
            module = ("." * node.level) + (node.module or "")
            if _names_solutions(node.module) or any(a.name == "solutions" for a in node.names):
                found.append(f"line {node.lineno}: from {module} import {', '.join(a.name for a in node.names)}")
        elif strings and isinstance(node, ast.Constant) and isinstance(node.value, str) and id(node) not in docstrings:
            value = node.value
            if value == "solutions" or value.endswith(".solutions") or "solutions/" in value or ".solutions." in value:
                found.append(f"line {node.lineno}: the string {value[:60]!r}")
    return tuple(found)


def solution_refs(path: str, text: str) -> list[str]:
    """Imports of a ``solutions`` package in a file of the release (test modules: also strings naming one)."""
    if path.endswith(".py"):
        try:
            return python_solution_refs(text, strings=path.startswith("tests/"))
        except SyntaxError:
            return [m.group(0).strip() for m in _MD_IMPORT.finditer(text)]
    if path.endswith(".ipynb"):
        cells = json.loads(text).get("cells", [])
        code = "\n".join("".join(c.get("source", "")) for c in cells if c.get("cell_type") == "code")
        return [m.group(0).strip() for m in _MD_IMPORT.finditer(code)]
    if path.endswith(".md"):
        return [m.group(0).strip() for m in _MD_IMPORT.finditer(text)]
    return []


def _read(base: Path, path: str) -> str | None:
    if not path.endswith(_SCANNED):
        return None
    try:
        return (base / path).read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError):
        return None


@dataclass
class Reference:
    """What the release is checked against: the solution files' hashes and their own lines."""

    hashes: dict[str, str] = field(default_factory=dict)  # sha256 -> solution path
    lines: set[str] = field(default_factory=set)

    def hits(self, text: str) -> list[str]:
        """The reference's own lines found in ``text`` (anywhere in it: a string in a test holds one too)."""
        return sorted(line for line in self.lines if line in text)


def reference_of(base: Path, files: Iterable[str]) -> Reference:
    """The reference of the tree at ``base``: every solution file's hash, and every solution line of
    :data:`FINGERPRINT_MIN` characters or more that no engine, step or stub file holds (tests, docs and notebooks
    are what is searched, so they do not count as the reference's public home)."""
    files = list(files)
    public: set[str] = set()
    ref = Reference()
    solution_texts = []
    for path in files:
        parts = path.split("/")
        text = _read(base, path)
        if "solutions" in parts[:-1]:
            data = (base / path).read_bytes()
            ref.hashes[hashlib.sha256(data).hexdigest()] = path
            if text is not None:
                solution_texts.append(text)
        elif text is not None and parts[0] not in ("tests", "docs", "notebooks") and not path.endswith(".md"):
            public.update(line.strip() for line in text.splitlines())
    for text in solution_texts:
        for line in text.splitlines():
            line = line.strip()
            if len(line) >= FINGERPRINT_MIN and line not in public:
                ref.lines.add(line)
    stub_hashes = {hashlib.sha256((base / p).read_bytes()).hexdigest() for p in files if "exercises" in p.split("/")}
    for digest in stub_hashes:  # a solution file equal to its stub (an __init__ re-exporting the same names)
        ref.hashes.pop(digest, None)
    return ref


def leaks(base: Path, path: str, ref: Reference) -> list[str]:
    """Why the file ``path`` of a tree must not be in a release (empty: it may)."""
    why = []
    digest = hashlib.sha256((base / path).read_bytes()).hexdigest()
    if digest in ref.hashes:
        why.append(f"equal to {ref.hashes[digest]}")
    text = _read(base, path)
    if text is not None:
        why += solution_refs(path, text)
        hits = ref.hits(text)
        if len(hits) >= FINGERPRINT_HITS:
            why.append(f"holds {len(hits)} lines of the reference solutions, e.g. {hits[0][:70]!r}")
    return why


# ---------------------------------------------------------------------------------------------------
# Building and checking
# ---------------------------------------------------------------------------------------------------


_EXERCISE_MARK = re.compile(r"mark\.exercise\(\s*[\"']([^\"']+)")


def graded_exercises(folder: Path) -> set[tuple[str, str]]:
    """(step, exercise) of every graded test module in ``folder``/tests (read from the modules' markers)."""
    found = set()
    for path in sorted(Path(folder, "tests").glob("step*/**/test_*.py")):
        found |= {(path.relative_to(folder / "tests").parts[0], m) for m in _EXERCISE_MARK.findall(path.read_text())}
    return found


@dataclass
class Release:
    """What :func:`build` made: the folder, its files, and what it left out and why."""

    folder: Path
    files: list[str]
    left_out: dict[str, str]
    instructor_tests: dict[str, list[str]]
    size: int = 0
    archive: Path | None = None
    without_public_tests: list[tuple[str, str]] = field(default_factory=list)

    def summary(self) -> str:
        lines = [f"release: {self.folder} ({len(self.files)} files, {self.size / 2**20:.1f} MiB)"]
        if self.archive is not None:
            lines.append(f"zip: {self.archive} ({self.archive.stat().st_size / 2**20:.1f} MiB)")
        reasons: dict[str, int] = {}
        for why in self.left_out.values():
            reasons[why] = reasons.get(why, 0) + 1
        lines.append(f"left out: {len(self.left_out)} files")
        lines += [f"  {n:4d}  {why}" for why, n in sorted(reasons.items(), key=lambda kv: -kv[1])]
        if self.instructor_tests:
            lines.append(f"test modules kept for the instructor ({len(self.instructor_tests)}): they name the "
                         "solutions or hold their lines")
            lines += [f"  {path}: {why[0]}" for path, why in sorted(self.instructor_tests.items())]
        if self.without_public_tests:
            lines.append(f"exercises with no public graded test in the release ({len(self.without_public_tests)}): "
                         + ", ".join(f"{step}:{name}" for step, name in self.without_public_tests))
        return "\n".join(lines)


STUDENT_README = """\
# gandalf — your course repository

A progressive course in real-time graphics, in Python: a small Entity-Component-System engine (`gandalf_core/`)
with an **OpenGL** and a **WebGPU** renderer side by side, and tutorial steps (`step01_window/` ... `step07_advanced/`)
that each add one concept. Your work goes into each step's `exercises/` folder: the stubs there say, in their
docstrings, what each function, system or shader function must do.

## Three commands

```bash
./run.sh test tests/step01_window     # set everything up (first time: about a minute), then grade step 01
./run.sh tour                         # every step in a window (or, with no display, PNGs in out/)
./run.sh test                         # every test: the steps' graded tests and the engine's own
```

`./run.sh test tests/stepNN_topic` prints a score per exercise (`gandalf grade — exercises (student)`); a test fails
with the input, the expected and the actual value and a hint. The same, shorter:
`.venv/bin/python -m gandalf_tools.grading tests/step01_window`.

## Running a step

```bash
source .venv/bin/activate
python -m step01_window.opengl                  # runs YOUR exercises (this repository has no solutions)
python -m step01_window.webgpu --headless --out step01.png
python -m step05_scenegraph.opengl --concept house
```

While an exercise is still a stub, its step stops with one sentence naming the exercise and the file to fill in.
The tour skips such parts and says which, and so do the tests without a grade that run the step with your code.

## What is here, and what is not

| here | what |
|---|---|
| `gandalf_core/` | the engine (read it, do not change it: the tests run against it) |
| `stepNN_topic/exercises/` | **your code**: the stubs to fill in |
| `tests/stepNN_topic/` | each step's public graded tests (your feedback), and checks of the step's own code |
| `tests/core/` | the engine's own tests |
| `docs/`, `notebooks/` | the course pages (`mkdocs serve`) and the notebooks of weeks 1-2 |

The reference solutions are not in this repository, and your course may grade with further (hidden) tests of the
same exercises on the instructor's machine: the public tests are your feedback, not the grade. A correct
solution passes both: the tests check what the docstrings state, never the text of your code.
"""


def _imported_names(text: str) -> set[str]:
    """The first name of every module a Python source imports (absolute imports only)."""
    names = set()
    for node in ast.walk(ast.parse(text)):
        if isinstance(node, ast.Import):
            names |= {a.name.split(".")[0] for a in node.names}
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            names.add(node.module.split(".")[0])
    return names


def _without_dependents(base: Path, ship: list[str], left_out: dict[str, str],
                        instructor_tests: dict[str, list[str]]) -> list[str]:
    """``ship`` less the test modules that import a test module left out (tests import their folder's helpers by
    name), until none does; each one left out is recorded with the module it needs."""
    packages = {Path(p.split("/")[0]).stem for p in ship}  # the course's own packages keep their names
    while True:
        gone = {Path(p).stem for p in left_out if p.startswith("tests/") and p.endswith(".py")} - packages
        needing = {}
        for path in ship:
            if path.startswith("tests/") and path.endswith(".py"):
                missing = sorted(_imported_names((base / path).read_text()) & gone)
                if missing:
                    needing[path] = f"imports {missing[0]}, which stays with the instructor"
        if not needing:
            return ship
        for path, why in needing.items():
            left_out[path] = "a test module that needs or shows the reference solutions"
            instructor_tests[path] = [why]
        ship = [p for p in ship if p not in needing]


def _copy(base: Path, path: str, out: Path) -> int:
    target = out / path
    target.parent.mkdir(parents=True, exist_ok=True)
    shutil.copy2(base / path, target)
    return target.stat().st_size


def _progress(text: str, done: int = 0, total: int = 0) -> None:
    """What the build is doing, on one line rewritten in place, for a person at a terminal (a log stays as it was:
    its first line is the summary)."""
    if not sys.stderr.isatty():
        return
    now = time.monotonic()
    if total and 0 < done < total and now - _progress_shown[0] < 0.5:
        return
    _progress_shown[0] = now
    count = f" {done}/{total}" if total else ""
    sys.stderr.write(f"\r\033[K{text}{count}" + ("\n" if total and done >= total else ""))
    sys.stderr.flush()


_progress_shown = [0.0]


def build(out: Path, root: Path = ROOT, *, make_zip: bool = False, force: bool = False) -> Release:
    """Write the student release of the tree at ``root`` into ``out`` (which must not exist unless ``force``);
    raise ValueError when something that must ship reaches the solutions (a bug of the course)."""
    out = Path(out).resolve()
    if out.exists():
        if not force:
            raise FileExistsError(f"{out} exists: remove it or pass --force")
        shutil.rmtree(out)
    _progress("reading the course's tracked files and the reference solutions")
    base, files = tracked_files(root)
    ref = reference_of(base, files)
    left_out: dict[str, str] = {}
    instructor_tests: dict[str, list[str]] = {}
    ship = []
    for number, path in enumerate(files, 1):
        _progress("choosing the files to ship (none may reach the solutions):", number, len(files))
        why = excluded(path)
        if why is not None:
            left_out[path] = why
            continue
        found = leaks(base, path, ref)
        if found and path.startswith("tests/"):
            instructor_tests[path] = found
            left_out[path] = "a test module that needs or shows the reference solutions"
            continue
        if found:
            raise ValueError(f"{path} must ship but reaches the reference solutions: {'; '.join(found)}")
        ship.append(path)
    ship = _without_dependents(base, ship, left_out, instructor_tests)
    out.mkdir(parents=True)
    _progress(f"copying {len(ship)} files to {out}")
    size = sum(_copy(base, path, out) for path in ship)
    if "README.md" in ship or not (base / ".git").exists():
        (out / "README.md").write_text(STUDENT_README)
        if "README.md" not in ship:
            ship.append("README.md")
    release = Release(out, sorted(ship), left_out, instructor_tests, size)
    release.without_public_tests = sorted(graded_exercises(base) - graded_exercises(out)) if (base / "tests").is_dir() \
        else []
    _progress("checking the release: nothing in it may reach the solutions")
    problems = check_release(out, root, ref)
    _progress("")
    if problems:
        raise ValueError("the release holds the reference:\n  " + "\n  ".join(problems))
    if make_zip:
        release.archive = make_archive(out)
    return release


def make_archive(folder: Path) -> Path:
    """``folder.zip`` beside ``folder``, its files under the folder's name (scripts stay executable)."""
    archive = folder.parent / f"{folder.name}.zip"
    with zipfile.ZipFile(archive, "w", zipfile.ZIP_DEFLATED) as zf:
        for path in sorted(p for p in folder.rglob("*") if p.is_file()):
            zf.write(path, f"{folder.name}/{path.relative_to(folder).as_posix()}")
    return archive


def check_release(release: Path, root: Path = ROOT, ref: Reference | None = None) -> list[str]:
    """What in the release folder reaches the reference of the tree at ``root`` (``ref``: already read from it):
    paths of solutions, mutants or hidden tests, imports of a ``solutions`` package, copies of the reference's files
    or lines (empty: none)."""
    if ref is None:
        base, files = tracked_files(root)
        ref = reference_of(base, files)
    problems = []
    shipped = sorted(p.relative_to(release).as_posix() for p in Path(release).rglob("*") if p.is_file())
    for number, path in enumerate(shipped, 1):
        _progress("checking the release: nothing in it may reach the solutions:", number, len(shipped))
        if "__pycache__" in path or path.startswith((".venv/", "out/")):
            continue
        why = excluded(path)
        if why is not None:
            problems.append(f"{path}: {why}")
        problems += [f"{path}: {w}" for w in leaks(Path(release), path, ref)]
    return problems


def copy_solutions_over(release: Path, root: Path = ROOT) -> list[str]:
    """Copy every step's reference solutions over the release's exercises (to check that its graded tests pass on
    the reference); returns the steps done."""
    steps = []
    for solutions in sorted(Path(root).glob("step*/solutions")):
        exercises = Path(release) / solutions.parent.name / "exercises"
        if not exercises.is_dir():
            continue
        for source in solutions.rglob("*"):
            if source.is_file() and "__pycache__" not in source.parts:
                target = exercises / source.relative_to(solutions)
                target.parent.mkdir(parents=True, exist_ok=True)
                shutil.copy2(source, target)
        steps.append(solutions.parent.name)
    return steps


def borrow_environment(folder: Path, python: str = sys.executable) -> Path:
    """Give ``folder`` a ``.venv`` that uses the packages installed for ``python`` (this one) but not its editable
    install of the course, whose import hook would find the instructor's ``solutions`` from any folder: for
    checking a release on the instructor's machine without installing anything. The release's own folder comes
    first on its path, as its editable install would put it; ``./run.sh`` then uses the environment as is."""
    venv = Path(folder) / ".venv"
    subprocess.run([python, "-m", "venv", "--without-pip", str(venv)], check=True)
    # Installed packages: the site folders, and folders on PYTHONPATH that hold installed distributions
    # (``pip install --target``), never the course checkout itself.
    probe = ("import os, sys; from pathlib import Path\n"
             "extra = [p for p in os.environ.get('PYTHONPATH', '').split(os.pathsep)\n"
             "         if p and any(Path(p).glob('*.dist-info'))]\n"
             "print('\\n'.join(p for p in sys.path if p.endswith('-packages') or p in extra))")
    paths = subprocess.run([python, "-c", probe], capture_output=True, text=True, check=True).stdout.split()
    site = next(venv.glob("lib/python*/site-packages"))
    # The release itself first (as its own editable install would put it), then the borrowed folders: plain folder
    # lines, whose own .pth files (the editable install's hook among them) are not run.
    lines = [str(Path(folder).resolve()), *(p for p in paths if Path(p).is_dir())]
    (site / "borrowed.pth").write_text("".join(f"{line}\n" for line in lines))
    (venv / ".gandalf-installed").touch()  # scripts/setup.sh: installed, nothing to do
    return venv


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="python -m gandalf_tools.release",
        description="Make the student release: a template repository folder OUT (and OUT.zip) from the course's "
        "tracked files, without the solutions/ folders, tests/mutants/, hidden tests (files or folders named hidden, "
        "hidden_* or *_hidden) and the instructor's tools, then check that nothing in it reaches the solutions.",
        epilog="Example: python -m gandalf_tools.release /tmp/gandalf-student --zip",
    )
    parser.add_argument("out", type=Path, help="the release folder to write (must not exist; see --force)")
    parser.add_argument("--zip", action="store_true", help="also write OUT.zip")
    parser.add_argument("--force", action="store_true", help="replace OUT when it exists")
    parser.add_argument("--solved", type=Path, metavar="DIR",
                        help="also write DIR: the release with the reference solutions copied over its exercises "
                        "(its graded tests must all pass; for checking the grader, never for students)")
    parser.add_argument("--left-out-tests", type=Path, metavar="FILE",
                        help="write the step test modules the release leaves out (hidden, or needing the reference) "
                        "to FILE, one a line: the instructor's copy must still check them on the stubs")
    parser.add_argument("--borrow-venv", action="store_true",
                        help="give OUT (and DIR) a .venv that uses this Python's installed packages without its "
                        "editable install of the course (to check the release here without installing anything)")
    parser.add_argument("--root", type=Path, default=ROOT, help="the course checkout to release (default: this one)")
    args = parser.parse_args(argv)
    try:
        release = build(args.out, args.root, make_zip=args.zip, force=args.force)
    except (FileExistsError, ValueError) as error:
        print(f"gandalf_tools.release: {error}", file=sys.stderr)
        return 1
    print(release.summary())
    if args.solved:
        if args.solved.exists():
            shutil.rmtree(args.solved)
        shutil.copytree(release.folder, args.solved)
        print(f"solved copy: {args.solved} (reference solutions over the exercises of "
              f"{', '.join(copy_solutions_over(args.solved, args.root))})")
    if args.left_out_tests:
        modules = [p for p in release.left_out if p.startswith("tests/step") and Path(p).name.startswith("test_")
                   and p.endswith(".py")]
        args.left_out_tests.write_text("".join(f"{p}\n" for p in modules))
    if args.borrow_venv:
        for folder in [release.folder] + ([args.solved] if args.solved else []):
            print(f"borrowed environment: {borrow_environment(folder)}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
