"""``python -m gandalf_tools.grading [TESTS ...] [--json FILE] [--gradescope FILE]``: grade your exercises.

A thin front end over ``pytest --student`` that prints one line per failed test and the score table
(``pytest --student`` itself shows full tracebacks). Other arguments go to pytest.

The student's code runs in a sandboxed process of its own (:mod:`gandalf_tools.grading.sandbox`), never in a
pytest process: a call that ends that process or runs past its budget fails (with every later call of that
function), a fresh process serves the other functions, and only plain data comes back. The tests themselves run in
a pytest-xdist worker (``--jobs``, default 1): a test that crashes the engine fails on its own, its worker is
replaced and the other tests are graded. Each test has a time limit (``--timeout``, default 60 s): pytest-timeout's
signal method fails a runaway Python loop in place; a hang inside native code (a driver call) that a
signal cannot interrupt ends the worker after ``--hard-timeout`` seconds, and that test fails too.
"""

from __future__ import annotations

import argparse
import importlib.util
import os
import sys
from pathlib import Path

import pytest

from . import SPEED_OPTIONS, use_bytecode_cache

PLUGIN = "gandalf_tools.grading.plugin"
# A test module that fails to import (a course bug, never the student's: their code is imported by the tests, not
# at collection) must not zero the other steps: grade the rest; that module's tests are missing from the grade.
ROBUST_OPTIONS = ("--continue-on-collection-errors",)


def _has(module: str) -> bool:
    # find_spec, not import: a plugin imported before pytest starts cannot have its asserts rewritten.
    return importlib.util.find_spec(module) is not None


def _has_xdist() -> bool:
    return _has("xdist")


def _has_timeout() -> bool:
    return _has("pytest_timeout")


def pytest_options(
    *,
    jobs: int = 1,
    timeout: float = 60.0,
    hard_timeout: float | None = None,
    json_path: str | None = None,
    gradescope: str | None = None,
    max_worker_restart: int = 20,
    quiet: bool = True,
) -> list[str]:
    """The pytest arguments the front end (and the batch grader) uses."""
    options = ["-p", PLUGIN, "--student", "-p", "no:cacheprovider", "--tb=line", "-rN", *SPEED_OPTIONS, *ROBUST_OPTIONS]
    if quiet:
        options.append("-q")
    if jobs > 0 and _has_xdist():
        options += ["-n", str(jobs), "--max-worker-restart", str(max_worker_restart)]
        if hard_timeout is None:
            hard_timeout = 2 * timeout + 30 if timeout > 0 else 0
        if hard_timeout > 0:
            options += ["--grade-hard-timeout", f"{hard_timeout:g}"]
    if timeout > 0 and _has_timeout():
        options += [f"--timeout={timeout:g}", "--timeout-method=signal"]
    if json_path:
        options += ["--grade-json", json_path]
    if gradescope:
        options += ["--gradescope", gradescope]
    return options


def argument_problem(tests: list[str], impls: list[str]) -> str | None:
    """A sentence saying what is wrong with the test paths and ``--impl`` entries, or None. Checked before pytest
    runs: a typo must not grade as 0 % with exit status 0."""
    for test in tests:
        # Only what reads as a path: a bare word may be the value of a pytest option (-k hue, -m exercise).
        if not ("/" in test or os.sep in test or "::" in test or test.endswith(".py") or test == "tests"):
            continue
        path = Path(test.split("::", 1)[0])
        if not path.exists():
            return f"the test path {test!r} does not exist (from {Path.cwd()})"
    for entry in impls:
        step, sep, folder = entry.partition("=")
        if not sep or not step.strip() or not folder.strip():
            return f"--impl {entry!r}: expected STEP=PATH, e.g. step01_window=my_work/step01"
        step, folder_path = step.strip(), Path(folder.strip()).expanduser()
        try:
            spec = importlib.util.find_spec(step)
        except (ImportError, ValueError):
            spec = None
        if spec is None or not spec.submodule_search_locations:
            return f"--impl {entry!r}: there is no step package named {step!r}"
        if not folder_path.is_dir():
            return f"--impl {entry!r}: the folder {str(folder_path)!r} does not exist"
        if not (folder_path / "__init__.py").is_file():
            return f"--impl {entry!r}: the folder {str(folder_path)!r} has no __init__.py (it is not a package)"
        own = Path(next(iter(spec.submodule_search_locations))) / "exercises"
        for module in sorted(own.glob("*.py")):
            if (folder_path / module.name).is_dir():
                return (f"--impl {entry!r}: the exercise {module.name} in {str(folder_path)!r} is a directory, "
                        "not a Python file")
    return None


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(prog="python -m gandalf_tools.grading", description=__doc__.splitlines()[0])
    parser.add_argument("tests", nargs="*", default=["tests"], help="test folders or files (default: tests)")
    parser.add_argument("--json", metavar="FILE", help="also write the score as JSON to FILE")
    parser.add_argument("--gradescope", metavar="FILE", help="also write Gradescope's results.json to FILE")
    parser.add_argument(
        "--jobs",
        "-j",
        type=int,
        default=1,
        help="worker processes (pytest-xdist, default 1: isolation at the least cost); 0 runs in this process",
    )
    parser.add_argument("--timeout", type=float, default=60.0, help="seconds per test (0: none); default 60")
    parser.add_argument(
        "--hard-timeout", type=float, default=None, help="seconds after which a worker stuck in one test is ended"
    )
    parser.add_argument(
        "--all-tests",
        action="store_true",
        help="also run the tests that carry no grade (by default only graded tests run: -m exercise)",
    )
    parser.add_argument(
        "--impl",
        action="append",
        default=[],
        metavar="STEP=PATH",
        help="grade the package at PATH as STEP's exercises (repeatable; sets GANDALF_IMPL)",
    )
    parser.add_argument(
        "--fail-under",
        type=float,
        default=None,
        metavar="PERCENT",
        help="exit with 1 when the score is below PERCENT (GitHub Classroom counts a test by its exit status)",
    )
    args, extra = parser.parse_known_args(argv)
    problem = argument_problem(args.tests, args.impl)
    if problem is not None:
        print(f"python -m gandalf_tools.grading: {problem}; nothing was graded.", file=sys.stderr)
        return 2
    if args.impl:
        os.environ["GANDALF_IMPL"] = os.pathsep.join(
            [*args.impl, *([os.environ["GANDALF_IMPL"]] if os.environ.get("GANDALF_IMPL") else [])]
        )
    json_path = args.json
    cleanup = None
    if args.fail_under is not None and not json_path:
        import tempfile

        fd, json_path = tempfile.mkstemp(suffix=".json", prefix="gandalf-grade-")
        os.close(fd)
        cleanup = json_path
    options = pytest_options(
        jobs=args.jobs,
        timeout=args.timeout,
        hard_timeout=args.hard_timeout,
        json_path=json_path,
        gradescope=args.gradescope,
    )
    if not args.all_tests and not any(a == "-m" or a.startswith("-m") and len(a) > 2 for a in extra):
        options += ["-m", "exercise"]  # only graded tests count: the others (studies, engine checks) cost time
    use_bytecode_cache()  # compiled once per machine, outside the checkout (GANDALF_PYCACHE=off: not at all)
    code = pytest.main(options + extra + args.tests)
    # 1 = some tests failed: that's a grade, not an error of the grader.
    status = 0 if code in (pytest.ExitCode.OK, pytest.ExitCode.TESTS_FAILED) else int(code)
    collect_only = any(a in ("--collect-only", "--co") for a in extra)
    if status == 0 and args.fail_under is not None and not collect_only:
        import json

        try:
            score = 100.0 * json.loads(open(json_path).read())["score"]
        except (OSError, ValueError, KeyError):
            score = 0.0
        if score + 1e-9 < args.fail_under:
            print(f"score {score:.1f}% is below {args.fail_under:g}%")
            status = 1
    if cleanup:
        os.unlink(cleanup)
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
