"""The mutation check: every plausible wrong implementation of an exercise must fail one of its graded tests.

``python -m gandalf_tools.grading.mutants [--step STEP] [--exercise NAME] [-k TEXT] [--jobs N] [--json FILE]``

A *mutant* is a copy of a step's ``solutions`` package with one thing wrong, defined in
``tests/mutants/<step>.py`` (a list ``MUTANTS``):

* Python: :func:`mutant` registers a function that receives the copied package after it was imported and
  replaces one function, method or class (:func:`patch` replaces an object everywhere the package refers
  to it) — usually wrapping or subclassing the solution's own code;
* shaders: :func:`shader_mutant` lists textual edits ``(file, old, new)`` applied to the copied shader
  files (``old`` must occur exactly once, so a changed solution makes a stale mutant an error, not a pass).

Each mutant is graded in its own subprocess: ``pytest --student -x --grade-only <exercise> tests/<step>``
with ``GANDALF_IMPL=<step>=<copy>`` so the ``impl`` fixture (and ``load_impl(step, student=True)``) import
the mutant as the step's ``exercises``. A mutant that passes every graded test of its exercise *survives*:
the tests have a gap. Before the mutants and again after them, an unchanged copy of each step's solutions
(the control) must pass every graded test, so a failure is the mutation's doing and not the copying's, nor
a change of the engine during the run (in a shared working tree).

The run exits with 1 when a mutant survives, a control fails, a mutant cannot be built, or the message a killed
mutant's first failed test gives the student does not name the input, the expected and the got (VAGUE).
Survivors already reported to the test authors are listed in ``tests/mutants/known_gaps.txt``: they are printed as
KNOWN GAP and do not fail the run (``--strict`` fails on them too), and an entry whose mutant is killed now is
STALE and fails the run, so the list shrinks as the tests improve.
"""

from __future__ import annotations

import argparse
import importlib.util
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from pathlib import Path
from types import ModuleType
from typing import Any

from . import SPEED_OPTIONS, bytecode_cache_env, feedback, use_bytecode_cache

ROOT = Path(__file__).resolve().parents[2]
DEFAULT_DIR = ROOT / "tests" / "mutants"


@dataclass
class Mutant:
    """One plausible wrong implementation of one exercise."""

    step: str
    exercise: str
    name: str
    description: str
    apply: Callable[[ModuleType], None] | None = None
    edits: tuple[tuple[str, str, str], ...] = ()
    source: str = ""  # the definition file (set when loaded)

    @property
    def ident(self) -> str:
        return f"{self.step}:{self.exercise}:{self.name}"

    @property
    def is_control(self) -> bool:
        """The stand-in of an unchanged copy of the solutions (see :meth:`_Job.placeholder`)."""
        return self.exercise == "*" and self.name == "control"


@dataclass
class Outcome:
    mutant: Mutant
    status: str  # "killed", "survived", "error" (for a control: "passed", "failed", "error")
    tests: int = 0
    failed: int = 0
    seconds: float = 0.0
    detail: str = ""
    first_failure: dict[str, Any] = field(default_factory=dict)


def mutant(registry: list[Mutant], step: str, exercise: str, name: str, description: str) -> Callable:
    """Decorator: register ``fn(package)`` as a Python mutant of ``exercise``."""

    def register(fn: Callable[[ModuleType], None]) -> Callable[[ModuleType], None]:
        registry.append(Mutant(step, exercise, name, description, apply=fn))
        return fn

    return register


def shader_mutant(
    registry: list[Mutant], step: str, exercise: str, name: str, description: str, edits: Iterable[tuple[str, str, str]]
) -> None:
    """Register a shader mutant: ``edits`` are ``(file, old, new)`` replacements in the copied package."""
    registry.append(Mutant(step, exercise, name, description, edits=tuple(edits)))


def patch(package: ModuleType, dotted: str, new: Any) -> Any:
    """Replace ``package.<dotted>`` (e.g. ``"hue.hsv_to_rgb"``) by ``new`` in every module of the package that
    refers to the same object. Returns the original."""
    *path, attr = dotted.split(".")
    owner: Any = package
    for part in path:
        owner = getattr(owner, part)
    original = getattr(owner, attr)
    try:  # the replacement counts as the package's own code: the grader guards and records its calls as a student's
        new.__module__ = original.__module__
        if getattr(new, "__name__", "") == "<lambda>":  # and names it as the student would
            new.__name__ = new.__qualname__ = original.__name__
    except (AttributeError, TypeError):
        pass
    setattr(owner, attr, new)
    prefix = package.__name__
    for name, module in list(sys.modules.items()):
        if module is None or not (name == prefix or name.startswith(prefix + ".")):
            continue
        for key, value in list(vars(module).items()):
            if value is original:
                setattr(module, key, new)
    return original


# ---------------------------------------------------------------------------------------------------
# Loading the definitions and applying one inside the graded process
# ---------------------------------------------------------------------------------------------------


def _load_definitions(path: Path) -> ModuleType:
    name = f"_gandalf_{path.parent.name}_{path.stem}"  # tests/mutants/ and tests/fairness/ share file names
    if name in sys.modules:
        return sys.modules[name]
    spec = importlib.util.spec_from_file_location(name, path)
    if spec is None or spec.loader is None:
        raise ImportError(f"cannot load mutant definitions {path}")
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


#: The lists a definitions file may hold: wrong implementations (``tests/mutants/``) and correct alternatives
#: (``tests/fairness/``, see :mod:`gandalf_tools.grading.fairness`); both are built and graded the same way.
DEFINITION_LISTS = ("MUTANTS", "ALTERNATIVES")


def load_mutants(folder: Path = DEFAULT_DIR, attr: str = "MUTANTS") -> list[Mutant]:
    """Every mutant (or, with ``attr="ALTERNATIVES"``, every alternative) defined in ``folder/step*.py``."""
    mutants: list[Mutant] = []
    for path in sorted(folder.glob("step*.py")):
        for m in getattr(_load_definitions(path), attr, []):
            m.source = str(path)
            mutants.append(m)
    return mutants


def load_known_gaps(path: Path) -> dict[str, str]:
    """``known_gaps.txt``: one ``step:exercise:mutant  # why`` per line, survivors already reported."""
    gaps: dict[str, str] = {}
    if not path.is_file():
        return gaps
    for line in path.read_text().splitlines():
        ident, _, why = line.partition("#")
        if ident.strip():
            gaps[ident.strip()] = why.strip() or "known gap"
    return gaps


def apply_mutant(package_name: str, definitions: str, ident: str) -> None:
    """Called from the copied package's ``__init__.py`` in the graded process: apply mutant ``ident``."""
    module = _load_definitions(Path(definitions))
    for m in (m for attr in DEFINITION_LISTS for m in getattr(module, attr, [])):
        if m.ident == ident:
            if m.apply is not None:
                m.apply(sys.modules[package_name])
            return
    raise LookupError(f"mutant {ident} is not defined in {definitions}")


def build(m: Mutant | None, step: str, folder: Path) -> Path:
    """Copy ``step``'s solutions into ``folder/<step>`` and apply mutant ``m`` (None: the control)."""
    source = ROOT / step / "solutions"
    target = folder / step
    shutil.copytree(source, target, ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
    if m is None:
        return target
    for file, old, new in m.edits:
        path = target / file
        if not path.is_file():
            raise FileNotFoundError(f"mutant {m.ident}: {step}/solutions/{file} does not exist")
        text = path.read_text()
        count = text.count(old)
        if count != 1:
            raise ValueError(
                f"mutant {m.ident}: expected the text to replace exactly once in {file}, found it {count} times "
                f"(the solution changed? update the mutant): {old!r}"
            )
        path.write_text(text.replace(old, new))
    if m.apply is not None:
        init = target / "__init__.py"
        init.write_text(
            init.read_text()
            + "\n\n# --- mutation check: make this copy wrong in one way ---\n"
            + "from gandalf_tools.grading.mutants import apply_mutant as _apply_mutant  # noqa: E402\n\n"
            + f"_apply_mutant(__name__, {m.source!r}, {m.ident!r})\n"
        )
    return target


# ---------------------------------------------------------------------------------------------------
# Grading one mutant in a subprocess
# ---------------------------------------------------------------------------------------------------


def _tests_dir(step: str) -> Path:
    return ROOT / "tests" / step


# wgpu is left out: its native library is loaded fresh in each grader (no shared driver state across a fork).
PRELOAD = ("numpy", "PIL.Image", "pytest", "xdist", "gandalf_core", "gandalf_core.resources")


@dataclass
class _Job:
    mutant: Mutant | None
    step: str
    exercises: list[str]
    tmp: tempfile.TemporaryDirectory
    package: Path | None = None
    pid: int = 0
    popen: subprocess.Popen | None = None
    start: float = 0.0
    error: str = ""

    @property
    def placeholder(self) -> Mutant:
        return self.mutant or Mutant(self.step, "*", "control", "the unchanged solutions, copied like a mutant")

    @property
    def folder(self) -> Path:
        return Path(self.tmp.name)

    def pytest_args(self, timeout: float) -> list[str]:
        args = ["-q", "-p", "no:cacheprovider", "--student", "--grade-in-process", "--tb=line", "-p",
                "gandalf_tools.grading.plugin"]
        args += SPEED_OPTIONS
        args += ["--grade-json", str(self.folder / "grade.json"), f"--timeout={timeout:g}"]
        if self.mutant is not None:
            args.append("-x")  # one failed test kills the mutant
        for name in self.exercises:
            args += ["--grade-only", name]
        return [*args, str(_tests_dir(self.step))]


def _start(job: _Job, timeout: float, fork: bool) -> None:
    """Start grading ``job`` in its own process: forked from this (pre-imported) one, or a fresh interpreter."""
    try:
        job.package = build(job.mutant, job.step, job.folder)
    except (OSError, ValueError) as error:
        job.error = str(error)
        return
    job.start = time.perf_counter()
    impl = f"{job.step}={job.package}"
    log = job.folder / "log.txt"
    if fork:
        sys.stdout.flush()
        sys.stderr.flush()
        pid = os.fork()
        if pid == 0:  # the child: grade, never return into the runner
            code = 3
            try:
                fd = os.open(log, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o644)
                os.dup2(fd, 1)
                os.dup2(fd, 2)
                os.environ["GANDALF_IMPL"] = impl
                os.environ["GANDALF_FAILURE_DIR"] = str(job.folder / "failures")  # not the checkout's tests/_failures
                use_bytecode_cache()
                os.chdir(ROOT)
                import pytest

                code = int(pytest.main(job.pytest_args(timeout)))
            except BaseException:  # noqa: B036 - report anything, then leave
                import traceback

                traceback.print_exc()
            finally:
                sys.stdout.flush()
                sys.stderr.flush()
                os._exit(code)
        job.pid = pid
    else:
        env = bytecode_cache_env({**os.environ, "GANDALF_IMPL": impl,
                                  "GANDALF_FAILURE_DIR": str(job.folder / "failures")})
        with open(log, "w") as out:
            job.popen = subprocess.Popen(
                [sys.executable, "-m", "pytest", *job.pytest_args(timeout)], cwd=ROOT, env=env, stdout=out, stderr=out
            )
        job.pid = job.popen.pid


def _finish(job: _Job) -> Outcome:
    placeholder = job.placeholder
    seconds = time.perf_counter() - job.start if job.start else 0.0
    if job.error:
        return Outcome(placeholder, "error", detail=job.error)
    out = job.folder / "grade.json"
    if not out.exists():
        log = job.folder / "log.txt"
        tail = log.read_text(errors="replace").strip().splitlines()[-15:] if log.exists() else []
        return Outcome(placeholder, "error", seconds=seconds, detail="no grade written:\n" + "\n".join(tail))
    tests = json.loads(out.read_text())["tests"]
    failed = [t for t in tests if not t["passed"]]
    real = [t for t in failed if not t["message"].startswith("not run")]
    ran = [t for t in tests if not t["message"].startswith("not run")]
    if not tests:
        return Outcome(placeholder, "error", seconds=seconds, detail="no graded test ran")
    if job.mutant is None:
        detail = "; ".join(f"{t['test']}: {t['message']}" for t in failed[:5])
        return Outcome(placeholder, "failed" if failed else "passed", len(tests), len(failed), seconds, detail)
    first = (real or failed or [{}])[0]
    status = "killed" if failed else "survived"
    detail = f"{first.get('test', '').split('::')[-1]}: {first.get('message', '')}" if first else ""
    return Outcome(job.mutant, status, len(ran), len(failed), seconds, detail, first)


def run_jobs(
    jobs: list[tuple[Mutant | None, str, list[str]]],
    parallel: int,
    timeout: float = 60.0,
    progress: Callable[[int, int, Outcome], None] | None = None,
) -> list[Outcome]:
    """Grade every ``(mutant or None, step, exercises)`` job, ``parallel`` processes at a time."""
    fork = hasattr(os, "fork") and os.environ.get("GANDALF_MUTANTS_NO_FORK") != "1"
    if fork:  # import the heavy modules once; every forked grader starts with them (no GPU context is made here)
        for name in PRELOAD:
            try:
                importlib.import_module(name)
            except ImportError:
                pass
    pending = [_Job(m, s, ex, tempfile.TemporaryDirectory(prefix="gandalf-mutant-")) for m, s, ex in jobs]
    pending.reverse()
    running: dict[int, _Job] = {}
    outcomes: list[Outcome] = []
    limit = max(120.0, 20 * timeout)

    def done(job: _Job) -> None:
        outcome = _finish(job)
        job.tmp.cleanup()
        outcomes.append(outcome)
        if progress:
            progress(len(outcomes), len(jobs), outcome)

    while pending or running:
        while pending and len(running) < max(1, parallel):
            job = pending.pop()
            _start(job, timeout, fork)
            if job.error:
                done(job)
            else:
                running[job.pid] = job
        if not running:
            continue
        pid, _ = os.waitpid(-1, os.WNOHANG) if fork else (0, 0)
        if not fork:
            for p, job in list(running.items()):
                if job.popen is not None and job.popen.poll() is not None:
                    pid = p
                    break
        if pid and pid in running:
            done(running.pop(pid))
            continue
        now = time.perf_counter()
        for p, job in list(running.items()):
            if now - job.start > limit:
                os.kill(p, 9)
                if fork:
                    os.waitpid(p, 0)
                else:
                    job.popen.wait()  # type: ignore[union-attr]
                job.error = f"the run took over {limit:g} s and was ended"
                done(running.pop(p))
        time.sleep(0.02)
    return outcomes


def grade(m: Mutant | None, step: str, exercises: list[str], timeout: float = 60.0) -> Outcome:
    """Grade one mutant (None: the unchanged control of ``step``) on the graded tests of ``exercises``."""
    return run_jobs([(m, step, exercises)], 1, timeout)[0]


# ---------------------------------------------------------------------------------------------------
# The command
# ---------------------------------------------------------------------------------------------------


def _select(mutants: list[Mutant], steps: list[str], exercises: list[str], keyword: str | None) -> list[Mutant]:
    chosen = []
    for m in mutants:
        if steps and not any(m.step.startswith(s) for s in steps):
            continue
        if exercises and m.exercise not in exercises:
            continue
        if keyword and keyword.lower() not in m.ident.lower():
            continue
        chosen.append(m)
    return chosen


def command_parser(module: str, description: str, noun: str, folder: Path) -> argparse.ArgumentParser:
    """The options the mutation check and the fairness check share: where the definitions of ``noun`` (mutants,
    alternatives) are, which of them to grade, how many at once, and where the outcomes go."""
    parser = argparse.ArgumentParser(prog=f"python -m gandalf_tools.grading.{module}", description=description)
    parser.add_argument("--dir", type=Path, default=folder, help=f"{noun} (default: {folder.relative_to(ROOT)})")
    parser.add_argument("--step", action="append", default=[], help="only this step (prefix, e.g. step01)")
    parser.add_argument("--exercise", action="append", default=[], help="only this exercise")
    parser.add_argument("-k", dest="keyword", help=f"only {noun} whose step:exercise:name contains this")
    parser.add_argument("--jobs", "-j", type=int, default=os.cpu_count() or 2, help=f"{noun} graded at once")
    parser.add_argument("--timeout", type=float, default=60.0, help="seconds per test (default 60)")
    parser.add_argument("--no-control", action="store_true", help="skip the unchanged-solutions control runs")
    parser.add_argument("--list", action="store_true", help=f"list the {noun} and exit")
    parser.add_argument("--json", type=Path, help="write the outcomes as JSON to this file")
    return parser


def print_list(chosen: list[Mutant], noun: str) -> int:
    """``--list``: one line per mutant or alternative (ident, kind, description) and the count."""
    for m in chosen:
        print(f"{m.ident:<60} {'shader' if m.edits else 'python':<7} {m.description}")
    print(f"{len(chosen)} {noun}")
    return 0


def selected(args: argparse.Namespace, attr: str, noun: str) -> list[Mutant] | int:
    """The mutants (``attr="MUTANTS"``) or alternatives the command's ``args`` select, or its exit code when there
    is nothing to grade: 0 after ``--list`` printed them, 2 when none is selected."""
    chosen = _select(load_mutants(args.dir, attr), args.step, args.exercise, args.keyword)
    if args.list:
        return print_list(chosen, noun)
    if not chosen:
        print(f"no {noun} selected", file=sys.stderr)
        return 2
    return chosen


def exercises_by_step(chosen: list[Mutant]) -> dict[str, list[str]]:
    """The exercises ``chosen`` touch, per step (steps and exercises sorted): what each control run grades."""
    return {s: sorted({m.exercise for m in chosen if m.step == s}) for s in sorted({m.step for m in chosen})}


def main(argv: list[str] | None = None) -> int:
    parser = command_parser(
        "mutants", "Grade every mutant (a plausible wrong implementation) of the exercises; fail if one passes.",
        "mutants", DEFAULT_DIR,
    )
    parser.add_argument(
        "--known-gaps",
        type=Path,
        default=None,
        help="survivors already reported (default: <dir>/known_gaps.txt); they are listed but do not fail the run",
    )
    parser.add_argument("--strict", action="store_true", help="fail on every survivor, known gaps too")
    args = parser.parse_args(argv)

    mutants = selected(args, "MUTANTS", "mutants")
    if isinstance(mutants, int):
        return mutants
    by_step = exercises_by_step(mutants)
    steps = list(by_step)
    jobs: list[tuple[Mutant | None, str, list[str]]] = []
    if not args.no_control:
        jobs += [(None, s, by_step[s]) for s in steps]
    jobs += [(m, m.step, [m.exercise]) for m in mutants]
    if not args.no_control:
        # The controls again at the end: a change to the engine or the tests during the run (a shared working
        # tree) would kill mutants for the wrong reason; a control that fails afterwards flags that run.
        jobs += [(None, s, by_step[s]) for s in steps]
    print(
        f"mutation check: {len(mutants)} mutants of {sum(len(v) for v in by_step.values())} exercises in "
        f"{len(steps)} steps, {len(jobs) - len(mutants)} control runs (each step before and after), "
        f"{args.jobs} at a time",
        flush=True,
    )
    start = time.perf_counter()

    known = {} if args.strict else load_known_gaps(args.known_gaps or args.dir / "known_gaps.txt")

    def progress(done: int, total: int, outcome: Outcome) -> None:
        mark = {"killed": "ok", "passed": "ok"}.get(outcome.status, outcome.status.upper())
        if outcome.status == "survived" and outcome.mutant.ident in known:
            mark = "KNOWN"
        print(f"[{done:>3}/{total}] {mark:<8} {outcome.mutant.ident:<58} {outcome.seconds:5.1f} s", flush=True)

    outcomes = run_jobs(jobs, args.jobs, args.timeout, progress)

    controls = [o for o in outcomes if o.mutant.is_control]
    results = [o for o in outcomes if o not in controls]
    for o in results:
        if o.status == "survived" and o.mutant.ident in known:
            o.status = "known-gap"
    stale = [o for o in results if o.mutant.ident in known and o.status == "killed"]
    survivors = [o for o in results if o.status == "survived"]
    errors = [o for o in results if o.status == "error"] + [o for o in controls if o.status != "passed"]
    results.sort(key=lambda o: o.mutant.ident)
    print()
    print(f"{'mutant':<58} {'status':<9} {'tests':>5}  first failure / note")
    for o in results:
        note = (o.detail or "").replace("\n", " ")[:90]
        print(f"{o.mutant.ident:<58} {o.status:<9} {o.tests:>5}  {note}")
    for o in controls:
        print(f"{o.mutant.step + ':control':<58} {o.status:<9} {o.tests:>5}  {(o.detail or '')[:90]}")
    killed = sum(o.status == "killed" for o in results)
    # What the student would read for each killed mutant: its first failed test's sentence must say the input, the
    # expected and the got (feedback.teaching_gaps).
    vague = [(o, gaps) for o in results if o.status == "killed"
             and (gaps := feedback.teaching_gaps(o.first_failure.get("message", "")))]
    print(
        f"\n{killed}/{len(results)} mutants killed, {len(survivors)} survived, "
        f"{sum(o.status == 'known-gap' for o in results)} known gaps, {len(errors)} errors "
        f"in {time.perf_counter() - start:.1f} s"
    )
    print(f"{killed - len(vague)}/{killed} killed mutants' messages name the input, the expected and the got")
    for o, gaps in vague:
        print(f"VAGUE {o.mutant.ident}: its message names no {' and no '.join(gaps)}: {o.detail}")
    for o in results:
        if o.status == "known-gap":
            print(f"KNOWN GAP {o.mutant.ident}: {o.mutant.description} ({known[o.mutant.ident]})")
    for o in survivors:
        print(f"SURVIVED {o.mutant.ident}: {o.mutant.description} (passed all {o.tests} graded tests)")
    for o in stale:
        print(f"STALE {o.mutant.ident} is listed in known_gaps.txt but a test kills it now: remove the line")
    for o in errors:
        print(f"ERROR {o.mutant.ident}: {o.detail}")
    if args.json:
        args.json.parent.mkdir(parents=True, exist_ok=True)
        args.json.write_text(
            json.dumps(
                [
                    {
                        "mutant": o.mutant.ident,
                        "description": o.mutant.description,
                        "kind": "shader" if o.mutant.edits else "python",
                        "status": o.status,
                        "tests": o.tests,
                        "failed": o.failed,
                        "seconds": round(o.seconds, 2),
                        "detail": o.detail,
                        "message_lacks": feedback.teaching_gaps(o.first_failure.get("message", ""))
                        if o.status == "killed" else [],
                    }
                    for o in results + controls
                ],
                indent=2,
            )
        )
    return 1 if survivors or errors or stale or vague else 0


if __name__ == "__main__":
    sys.exit(main())
