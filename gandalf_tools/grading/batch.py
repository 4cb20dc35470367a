"""``python -m gandalf_tools.grading.batch SUBMISSIONS_DIR --out DIR [--jobs N] [--steps step01 ...]``: grade a class.

**Layout.** ``SUBMISSIONS_DIR`` holds one folder per student (its name is the student's id in the gradebook).
Each holds the student's ``stepNN_topic/exercises/`` folders — either just those (what a Classroom or LMS
download of the exercise folders gives) or a whole checkout of the repository (only its
``step*/exercises/`` folders are used; nothing else of it is imported). A step a student did not hand in is
graded on this checkout's own ``exercises/`` (the untouched stubs: CI checks they fail every graded test).

**Isolation.** No grading process imports a student's code. Each submission is graded by its own
``python -m gandalf_tools.grading`` process with ``GANDALF_IMPL`` pointing every step's ``exercises`` at the
submission's folder; that process runs the student's package in a sandboxed process of its own (a private copy, its
own user when the grader runs as root, limits, a time budget per call: see :mod:`gandalf_tools.grading.sandbox`),
which sees neither the other submissions nor ``--out`` (``GANDALF_SANDBOX_HIDE``), and only data comes back from
it: the grade files and the gradebook are written by the grading processes and this one alone. A runaway test
fails on its time limit and the run goes on (pytest-timeout). By default
(``--isolation auto``) that process runs the tests itself, the fastest way (no worker to start: about 3 s less
per submission, the same grade); only when it does not finish cleanly — a hard exit or a crash in the student's
code, a hang in native code past ``--fast-limit`` — is the submission graded again with the tests in a
pytest-xdist worker, so that the crash fails only its own test (see the front end). ``--isolation always`` uses
workers from the start.

**Output** in ``--out``: ``gradebook.csv`` (one row per student: total, percent and every exercise's points),
``gradebook.json`` (the same plus failed-test counts), and per student ``<id>/grade.json`` (the plugin's
JSON), ``<id>/results.json`` (Gradescope's format), ``<id>/report.md`` (score per exercise and every failed
test with its message) and ``<id>/log.txt`` (the grader's output).
"""

from __future__ import annotations

import argparse
import csv
import json
import os
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor, as_completed
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from . import bytecode_cache_env
from .sandbox import HIDE_ENV, isolation, isolation_warning

ROOT = Path(__file__).resolve().parents[2]


def step_packages(root: Path = ROOT) -> list[str]:
    """The step packages of the checkout that have exercises and tests (``step01_window``, ...)."""
    return sorted(
        p.parent.parent.name
        for p in root.glob("step*/exercises/__init__.py")
        if (root / "tests" / p.parent.parent.name).is_dir()
    )


def find_steps(submission: Path, steps: list[str]) -> dict[str, Path]:
    """Step package -> the submission's ``exercises`` folder, for the steps it hands in."""
    found = {}
    for step in steps:
        for candidate in (submission / step / "exercises", submission / "exercises" / step):
            if (candidate / "__init__.py").is_file():
                found[step] = candidate.resolve()
                break
    return found


@dataclass
class Graded:
    student: str
    steps: list[str]
    seconds: float = 0.0
    result: dict[str, Any] = field(default_factory=dict)
    error: str = ""
    regraded: bool = False  # the fast run did not finish cleanly; graded again with workers

    @property
    def earned(self) -> float:
        return float(self.result.get("earned", 0.0))

    @property
    def possible(self) -> float:
        return float(self.result.get("possible", 0.0))


ISOLATION = ("auto", "always", "never")


def grade_submission(
    student: str,
    folder: Path,
    out: Path,
    steps: list[str],
    *,
    workers: int = 1,
    timeout: float = 60.0,
    limit: float = 1800.0,
    isolation: str = "auto",
    fast_limit: float = 600.0,
) -> Graded:
    """Grade one submission in its own process; write its files under ``out/<student>/``.

    ``isolation``: "always" runs the tests in xdist workers (``workers``), so a crash costs only its test;
    "never" runs them in the grading process itself (``--jobs 0``: about 3 s faster, the same grade); "auto"
    (the default) does the fast run first and, only when that process does not finish cleanly (a hard exit or
    a crash in the student's code, a hang past ``fast_limit`` seconds), grades the submission again with workers.
    """
    if isolation not in ISOLATION:
        raise ValueError(f"isolation must be one of {ISOLATION}, got {isolation!r}")
    target = out / student
    target.mkdir(parents=True, exist_ok=True)
    handed_in = find_steps(folder, steps)
    start = time.perf_counter()
    env = {k: v for k, v in os.environ.items() if k != "GANDALF_IMPL"}
    env["GANDALF_IMPL"] = os.pathsep.join(f"{step}={path}" for step, path in handed_in.items())
    env = bytecode_cache_env(env)  # bytecode in a cache outside the submission and the checkout
    # The sandboxed student process must not see the other submissions nor the gradebook.
    env[HIDE_ENV] = os.pathsep.join(str(p.resolve()) for p in (folder.parent, out))
    graded = Graded(student, sorted(handed_in))
    runs = {"auto": [(0, min(limit, fast_limit)), (workers, limit)], "always": [(workers, limit)],
            "never": [(0, limit)]}[isolation]
    with open(target / "log.txt", "w") as log:
        for attempt, (jobs, seconds) in enumerate(runs):
            graded.error = ""
            for stale in ("grade.json", "results.json"):
                (target / stale).unlink(missing_ok=True)
            cmd = [sys.executable, "-m", "gandalf_tools.grading", *[str(ROOT / "tests" / s) for s in steps]]
            cmd += ["--json", str(target / "grade.json"), "--gradescope", str(target / "results.json")]
            cmd += ["--jobs", str(jobs), "--timeout", f"{timeout:g}"]
            log.write(f"$ grading with --jobs {jobs} (attempt {attempt + 1} of {len(runs)})\n")
            log.flush()
            try:
                proc = subprocess.run(cmd, cwd=ROOT, env=env, stdout=log, stderr=subprocess.STDOUT, timeout=seconds)
                if proc.returncode != 0:
                    graded.error = f"the grader exited with {proc.returncode} (see {student}/log.txt)"
            except subprocess.TimeoutExpired:
                graded.error = f"grading took over {seconds:g} s and was stopped"
            if not graded.error and not (target / "grade.json").exists():
                graded.error = "no grade was written (see log.txt)"
            if not graded.error:
                break
            if attempt + 1 < len(runs):
                log.write(f"\n$ {graded.error}: grading again with each test in a worker process\n")
                graded.regraded = True
    graded.seconds = time.perf_counter() - start
    grade_file = target / "grade.json"
    if grade_file.exists():
        graded.result = json.loads(grade_file.read_text())
    write_report(graded, target / "report.md")
    return graded


def write_report(graded: Graded, path: Path) -> None:
    """A short markdown report for one student: points per exercise and each failed test's message."""
    result = graded.result
    lines = [f"# {graded.student}", ""]
    if graded.error:
        lines += [f"**Grading problem:** {graded.error}", ""]
    if result.get("isolation_warning"):
        lines += [f"**Not isolated:** {result['isolation_warning']}", ""]
    if graded.regraded and not graded.error:
        lines += ["Graded with each test in a worker process: the first run's process did not finish (a crash, a "
                  "hard exit or a hang in the submission's code); the tests that caused it fail below.", ""]
    for nodeid, message in result.get("collection_errors", {}).items():
        lines += [f"**Grading problem:** the test module `{nodeid}` failed to import ({message}); its tests are "
                  "missing from this score (a problem of the course, not of the submission).", ""]
    if result:
        lines += [
            f"Score: **{result['earned']:.2f} / {result['possible']:.2f}** ({result['score']:.0%}); "
            f"steps handed in: {', '.join(graded.steps) or 'none'}.",
            "",
            "| step | exercise | points | tests passed |",
            "|---|---|---|---|",
        ]
        for x in result["exercises"]:
            lines.append(
                f"| {x['step']} | {x['exercise']} | {x['earned']:.2f} / {x['possible']:.2f} "
                f"| {int(x['passed'])} / {int(x['tests'])} |"
            )
        failed = [t for t in result["tests"] if not t["passed"]]
        if failed:
            lines += ["", f"## Failed tests ({len(failed)})", ""]
            for t in failed:
                message = " ".join(t["message"].split())[:400]
                lines.append(f"- `{t['test'].split('::', 1)[-1]}` ({t['exercise']}): {message}")
    path.write_text("\n".join(lines) + "\n")


def write_gradebook(graded: list[Graded], out: Path) -> tuple[Path, Path]:
    """``gradebook.csv`` and ``gradebook.json`` for every student."""
    columns: list[tuple[str, str]] = sorted(
        {(x["step"], x["exercise"]) for g in graded for x in g.result.get("exercises", [])}
    )
    csv_path = out / "gradebook.csv"
    with open(csv_path, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["student", "earned", "possible", "percent", *[f"{s}:{e}" for s, e in columns], "error",
                         "isolation"])
        for g in graded:
            points = {(x["step"], x["exercise"]): x["earned"] for x in g.result.get("exercises", [])}
            percent = 100.0 * g.earned / g.possible if g.possible else 0.0
            writer.writerow(
                [
                    g.student,
                    f"{g.earned:.4f}",
                    f"{g.possible:.4f}",
                    f"{percent:.2f}",
                    *[f"{points.get(c, 0.0):.4f}" for c in columns],
                    g.error,
                    g.result.get("isolation", ""),
                ]
            )
    json_path = out / "gradebook.json"
    json_path.write_text(
        json.dumps(
            [
                {
                    "student": g.student,
                    "earned": g.earned,
                    "possible": g.possible,
                    "score": g.result.get("score", 0.0),
                    "steps_handed_in": g.steps,
                    "exercises": {f"{x['step']}:{x['exercise']}": x["earned"] for x in g.result.get("exercises", [])},
                    "failed_tests": sum(1 for t in g.result.get("tests", []) if not t["passed"]),
                    "collection_errors": sorted(g.result.get("collection_errors", {})),
                    "seconds": round(g.seconds, 2),
                    "regraded_in_workers": g.regraded,
                    "error": g.error,
                    "isolation": g.result.get("isolation", ""),
                    **({"isolation_warning": g.result["isolation_warning"]}
                       if g.result.get("isolation_warning") else {}),
                }
                for g in graded
            ],
            indent=2,
        )
    )
    return csv_path, json_path


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="python -m gandalf_tools.grading.batch", description=__doc__.splitlines()[0].split(": ", 1)[-1]
    )
    parser.add_argument("submissions", type=Path, help="a folder with one folder per student")
    parser.add_argument("--out", type=Path, required=True, help="where the gradebook and reports go")
    parser.add_argument(
        "--jobs", "-j", type=int, default=max(1, (os.cpu_count() or 2) // 2), help="submissions graded at once"
    )
    parser.add_argument("--workers", type=int, default=1, help="xdist workers per submission (default 1)")
    parser.add_argument(
        "--isolation",
        choices=ISOLATION,
        default="auto",
        help="auto (default): grade in one process, and again with workers only if that process crashes or hangs; "
        "always: workers from the start; never: one process only",
    )
    parser.add_argument(
        "--fast-limit", type=float, default=600.0, help="seconds for the one-process run of --isolation auto (600)"
    )
    parser.add_argument("--steps", nargs="+", default=None, help="step packages to grade (default: all; prefixes ok)")
    parser.add_argument("--students", nargs="+", default=None, help="only these students (folder names)")
    parser.add_argument("--timeout", type=float, default=60.0, help="seconds per test (default 60)")
    parser.add_argument("--limit", type=float, default=1800.0, help="seconds per submission (default 1800)")
    parser.add_argument(
        "--allow-unisolated", action="store_true",
        help="grade even where the student's code cannot be kept from the solutions, the tests, the other "
        "submissions and the gradebook (isolation 'process'); every row is then flagged",
    )
    args = parser.parse_args(argv)

    if not args.submissions.is_dir():
        parser.error(f"SUBMISSIONS_DIR {args.submissions} is not a folder")
    all_steps = step_packages()
    steps = all_steps if not args.steps else [s for s in all_steps if any(s.startswith(p) for p in args.steps)]
    if not steps:
        parser.error(f"--steps {args.steps} matches none of {all_steps}")
    students = sorted(p for p in args.submissions.iterdir() if p.is_dir() and not p.name.startswith("."))
    if args.students:
        students = [p for p in students if p.name in set(args.students)]
    if not students:
        parser.error(f"no student folders in {args.submissions}")
    args.out.mkdir(parents=True, exist_ok=True)
    print(f"grading {len(students)} submissions, steps {', '.join(steps)}, {args.jobs} at a time", flush=True)
    warning = isolation_warning(isolation())
    if warning and not args.allow_unisolated:
        print(f"not grading: {warning}.\nEach student's code could read the solutions and rewrite a classmate's "
              "grade or the gradebook, so no grade made here can be defended. Grade as root (each student's code then "
              "runs as a user of its own), or as a user where unprivileged user namespaces are allowed (Ubuntu: "
              "sysctl kernel.apparmor_restrict_unprivileged_userns=0); `python -m gandalf_tools.doctor` says which "
              "applies. --allow-unisolated grades anyway and flags every row.", file=sys.stderr, flush=True)
        return 2
    if warning:
        print(warning, file=sys.stderr, flush=True)
    start = time.perf_counter()
    graded: list[Graded] = []
    with ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        futures = [
            pool.submit(
                grade_submission,
                p.name,
                p,
                args.out,
                steps,
                workers=args.workers,
                isolation=args.isolation,
                fast_limit=args.fast_limit,
                timeout=args.timeout,
                limit=args.limit,
            )
            for p in students
        ]
        for done, future in enumerate(as_completed(futures), 1):
            g = future.result()
            graded.append(g)
            elapsed = time.perf_counter() - start
            eta = elapsed / done * (len(students) - done)
            status = f"{g.earned:6.2f} / {g.possible:<6.2f}" if g.result else "  no grade     "
            print(
                f"[{done:>3}/{len(students)}] {g.student:<24} {status} {g.seconds:6.1f} s"
                f"  (elapsed {elapsed:5.0f} s, ~{eta:4.0f} s left){'  regraded in workers' if g.regraded else ''}"
                f"{'  ' + g.error if g.error else ''}",
                flush=True,
            )
    graded.sort(key=lambda g: g.student)
    csv_path, json_path = write_gradebook(graded, args.out)
    print(f"gradebook: {csv_path} and {json_path}; reports in {args.out}/<student>/report.md")
    if warning:
        print(f"{warning} (the gradebook's isolation column says \"process\" for each grade made so)", file=sys.stderr)
    return 1 if any(g.error for g in graded) else 0


if __name__ == "__main__":
    sys.exit(main())
