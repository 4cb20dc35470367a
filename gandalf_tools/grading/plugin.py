"""The course autograder, as a pytest plugin.

* ``pytest tests/step01_window`` grades the reference ``solutions`` (CI stays green); in a student's release,
  which has no ``solutions/``, it grades the ``exercises``.
* ``pytest --student tests/step01_window`` grades the student's ``exercises`` instead, prints a score
  per exercise, and ``--grade-json result.json`` writes it for course platforms (``--gradescope
  results.json`` writes Gradescope's format).

A graded test carries ``@pytest.mark.exercise("name", points=1)`` and receives the implementation
under test through the ``impl`` fixture, which a step's ``conftest.py`` creates with
:func:`impl_fixture`.

The grade is the same with and without pytest-xdist (``-n 2``): every graded test's result travels in its
report's ``user_properties`` (xdist ships them from the worker to the controller), the controller adds
them up, and the list of graded tests comes from collection (each worker writes it to a folder the
controller gave it), so a test whose worker crashed (``os._exit``, a segfault, a hard timeout) counts as
failed instead of vanishing from the grade.

``GANDALF_IMPL="step01_window=/path/to/package"`` (several joined by ``os.pathsep``) grades the package at
that path as the step's ``exercises``: the batch grader overlays a submission's folders with it and the mutation
check its mutants.

A student's package (``--student`` or ``GANDALF_IMPL``) never runs in this process: it runs in a sandboxed
process (:mod:`.sandbox`) and the ``impl`` fixture gives its stand-in (:mod:`.remote`), put in ``sys.modules`` as
``<step>.exercises`` so that ``load_impl(step, student=True)`` finds it too; only plain data comes back, and the
results and grade files are written here. ``--grade-in-process`` imports the package here instead, for the course's
own code only (the mutation check's mutants).
"""

from __future__ import annotations

import importlib
import importlib.util
import inspect
import json
import linecache
import os
import sys
import tempfile
import threading
import time
import traceback
from collections import defaultdict
from pathlib import Path
from types import ModuleType
from typing import Any

import pytest

from . import feedback, remote, sandbox, shader_box, watchdog

IMPL_ENV = "GANDALF_IMPL"
_PROPERTY = "gandalf_grade"
_NOT_HERE = "gandalf_not_here"  # set by tests/conftest.py on a test this machine cannot run (a missing capability)
_FEEDBACK = "gandalf_feedback"  # a failed graded test's sentence for the student (built where the exception is)
_TRACE = "gandalf_trace"  # its full traceback, for the grade's log file
_MESSAGE_LIMIT = 4000

# nodeid -> {"step", "exercise", "points"} for every graded test collected in this run.
_graded: dict[str, dict[str, Any]] = {}
# nodeid -> {"passed_call": bool, "failed": bool, "message": str, "duration": float}
_outcomes: dict[str, dict[str, Any]] = {}
_overlays: dict[str, ModuleType] = {}
_collected_steps: set[str] = set()  # the steps whose graded tests this process runs
# step package -> (its sandbox, the stand-in of the student's package) for this run.
_sandboxes: dict[str, tuple[Any, ModuleType]] = {}
# The full report of each failed graded test in the student's view (written to the grade's log file).
_log: list[str] = []
_config: list[pytest.Config] = []  # this run's config (the report hooks are not given it)
# Test modules that failed to import (a course bug: their graded tests are missing from the grade), nodeid -> message.
_collection_errors: dict[str, str] = {}


def pytest_addoption(parser: pytest.Parser) -> None:
    group = parser.getgroup("gandalf grading")
    group.addoption("--student", action="store_true", help="grade the exercises/ stubs instead of solutions/")
    group.addoption("--grade-json", metavar="PATH", help="write the per-exercise score as JSON to PATH")
    group.addoption("--gradescope", metavar="PATH", help="write Gradescope's results.json format to PATH")
    group.addoption(
        "--grade-only",
        action="append",
        default=[],
        metavar="EXERCISE",
        help="run only the graded tests of this exercise (repeatable; the mutation check uses it)",
    )
    group.addoption(
        "--grade-call-budget",
        type=float,
        default=watchdog.DEFAULT_BUDGET,
        metavar="SECONDS",
        help=f"with --student: seconds one call of the student's function may take; a function that runs past it "
        f"fails that test and every later call at once, saying so (default {watchdog.DEFAULT_BUDGET:g}; 0: none)",
    )
    group.addoption(
        "--grade-shader-budget",
        type=float,
        default=shader_box.SHADER_BUDGET,
        metavar="SECONDS",
        help=f"with --student: seconds one run of the student's shaders may take in the shader process (default "
        f"{shader_box.SHADER_BUDGET:g}); past it that call fails, and the same call later fails at once",
    )
    group.addoption(
        "--grade-log",
        metavar="PATH",
        help="with --student: write the full traceback of each failed graded test to PATH (default: beside "
        "--grade-json or --gradescope, else in the temporary folder); the student's view holds one line per test",
    )
    group.addoption(
        "--grade-in-process",
        action="store_true",
        help="import the graded package into the test process instead of a sandboxed process (only for the "
        "course's own code: the mutation check's mutants)",
    )
    group.addoption(
        "--grade-hard-timeout",
        type=float,
        default=0.0,
        metavar="SECONDS",
        help="in an xdist worker, end the worker when one test runs this long (a hang in native code that "
        "pytest-timeout's signal cannot interrupt); the test counts as failed and the worker restarts",
    )


# ---------------------------------------------------------------------------------------------------
# The implementation under test
# ---------------------------------------------------------------------------------------------------


def parse_impl_env(value: str | None) -> dict[str, Path]:
    """``GANDALF_IMPL``'s entries: step package -> folder of the package graded as its ``exercises``."""
    overlays: dict[str, Path] = {}
    for entry in (value or "").split(os.pathsep):
        if not entry.strip():
            continue
        step, sep, path = entry.partition("=")
        if not sep or not step.strip() or not path.strip():
            raise pytest.UsageError(f"{IMPL_ENV}: expected 'step_package=/path/to/package', got {entry!r}")
        folder = Path(path.strip()).expanduser().resolve()
        if not (folder / "__init__.py").is_file():
            raise pytest.UsageError(f"{IMPL_ENV}: {folder} (for {step.strip()}) has no __init__.py")
        overlays[step.strip()] = folder
    return overlays


def load_overlay(step_package: str, folder: Path) -> ModuleType:
    """Import the package in ``folder`` as ``<step_package>.exercises`` (replacing the step's own)."""
    name = f"{step_package}.exercises"
    parent = importlib.import_module(step_package)
    spec = importlib.util.spec_from_file_location(
        name, folder / "__init__.py", submodule_search_locations=[str(folder)]
    )
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    for key in [k for k in sys.modules if k == name or k.startswith(name + ".")]:
        del sys.modules[key]
    sys.modules[name] = module
    parent.exercises = module  # type: ignore[attr-defined]
    spec.loader.exec_module(module)
    return module


def _overlay(step_package: str) -> ModuleType | None:
    if step_package in _overlays:
        return _overlays[step_package]
    folder = parse_impl_env(os.environ.get(IMPL_ENV)).get(step_package)
    if folder is None:
        return None
    _overlays[step_package] = load_overlay(step_package, folder)
    return _overlays[step_package]


def _has_solutions(step_package: str) -> bool:
    """Whether the step holds its reference ``solutions`` (a student's release does not: it grades ``exercises``);
    ``gandalf_core.app.cli.has_solutions`` without importing the engine's app layer into every pytest start."""
    try:
        return importlib.util.find_spec(f"{step_package}.solutions") is not None
    except ModuleNotFoundError:  # not a step package
        return False


def _sandboxed(config: pytest.Config, step_package: str, folder: Path) -> ModuleType:
    """The stand-in of the student's package ``folder``, whose code runs in the run's sandbox (one process for every
    step graded, started once)."""
    if step_package not in _sandboxes:
        boxes = {box for box, _ in _sandboxes.values()}
        if boxes:
            box = boxes.pop()
            box.add(step_package, folder)
        else:
            outputs = [str(Path(p).resolve().parent) for p in (config.getoption("--grade-json"),
                                                               config.getoption("--gradescope")) if p]
            # Every package the run may grade goes into the first layout: one process start for the whole run.
            wanted = {p.parent.parent.name: p.parent for p in sandbox.ROOT.glob("step*/exercises/__init__.py")
                      } if config.getoption("--student") else {}
            wanted.update(parse_impl_env(os.environ.get(IMPL_ENV)))
            wanted[step_package] = folder
            box = sandbox.Sandbox(step_package, folder, hide=tuple(outputs))
            for step, other in wanted.items():
                box.add(step, other)
            # The shader process gets the same folders; it starts now where the run grades a step with shader files.
            shader_steps = [step for step in _collected_steps if step in wanted
                            and (any(Path(wanted[step]).glob("*.glsl")) or any(Path(wanted[step]).glob("*.wgsl")))]
            shader_box.plan({Path(f).resolve(): s for s, f in wanted.items()}, tuple(outputs), bool(shader_steps))
        budget = float(config.getoption("--grade-call-budget"))
        _sandboxes[step_package] = (box, remote.install(step_package, folder, box, budget))
    return _sandboxes[step_package][1]


# --8<-- [start:impl_fixture]
def impl_fixture(step_package: str) -> Any:
    """Create the ``impl`` fixture of a step: its ``exercises`` or ``solutions`` package.

    A student's package (``--student``, ``GANDALF_IMPL``) runs in a sandboxed process (:mod:`.sandbox`); the
    fixture gives its stand-in (:mod:`.remote`). ``--grade-in-process`` imports it here instead (the mutation
    check's mutants: the course's own code)."""

    @pytest.fixture
    def impl(request: pytest.FixtureRequest) -> ModuleType:
        config = request.config
        folder = parse_impl_env(os.environ.get(IMPL_ENV)).get(step_package)  # a submission's or a mutant's package
        student = config.getoption("--student") or not _has_solutions(step_package)  # a student's release: exercises
        if folder is None and not student:
            return importlib.import_module(f"{step_package}.solutions")
        if not config.getoption("--grade-in-process"):
            if folder is None:  # the step's own exercises (found without importing them)
                folder = Path(importlib.import_module(step_package).__file__ or "").resolve().parent / "exercises"
            return _sandboxed(config, step_package, folder)
        budget = float(config.getoption("--grade-call-budget"))
        overlay = _overlay(step_package)
        if overlay is not None:
            return watchdog.guard(overlay, budget)
        return watchdog.guard(importlib.import_module(f"{step_package}.exercises"), budget)

    return impl


# --8<-- [end:impl_fixture]


# ---------------------------------------------------------------------------------------------------
# Collecting results (the same with and without xdist)
# ---------------------------------------------------------------------------------------------------


def _is_worker(config: pytest.Config) -> bool:
    return hasattr(config, "workerinput")


def pytest_configure(config: pytest.Config) -> None:
    config.addinivalue_line("markers", "exercise(name, points=1): a graded test of exercise `name`")
    _graded.clear()
    _outcomes.clear()
    _collection_errors.clear()
    _log.clear()
    _config[:] = [config]
    if _student_view(config) and getattr(config.option, "tbstyle", None) == "auto":
        config.option.tbstyle = "line"  # the student's view: one line per failed test (--tb=long shows more)
    watchdog.reset()
    shader_box.budget[0] = float(config.getoption("--grade-shader-budget"))
    config._gandalf_collect_dir = None  # type: ignore[attr-defined]
    if not _is_worker(config) and config.pluginmanager.hasplugin("xdist"):
        config._gandalf_collect_dir = tempfile.mkdtemp(prefix="gandalf-grade-")  # type: ignore[attr-defined]


@pytest.hookimpl(optionalhook=True)
def pytest_configure_node(node: Any) -> None:
    """xdist (controller): tell each worker where to write its list of graded tests."""
    folder = getattr(node.config, "_gandalf_collect_dir", None)
    if folder:
        node.workerinput["gandalf_collect_dir"] = folder


def _exercise_of(item: pytest.Item) -> dict[str, Any] | None:
    marker = item.get_closest_marker("exercise")
    if marker is None:
        return None
    name = marker.args[0] if marker.args else marker.kwargs["name"]
    return {
        "step": Path(str(item.path)).parent.name,
        "exercise": str(name),
        "points": float(marker.kwargs.get("points", 1)),
    }


def pytest_collection_modifyitems(session: pytest.Session, config: pytest.Config, items: list[pytest.Item]) -> None:
    only = set(config.getoption("--grade-only") or ())
    if not only:
        return
    keep, drop = [], []
    for item in items:
        info = _exercise_of(item)
        (keep if info is not None and info["exercise"] in only else drop).append(item)
    if drop:
        config.hook.pytest_deselected(items=drop)
        items[:] = keep


def pytest_collection_finish(session: pytest.Session) -> None:
    graded = {item.nodeid: info for item in session.items if (info := _exercise_of(item)) is not None}
    _collected_steps.clear()
    _collected_steps.update(info["step"] for info in graded.values())
    config = session.config
    if _is_worker(config):
        folder = config.workerinput.get("gandalf_collect_dir")  # type: ignore[attr-defined]
        if folder:
            worker = config.workerinput.get("workerid", "gw")  # type: ignore[attr-defined]
            fd, tmp = tempfile.mkstemp(dir=folder, suffix=".tmp")
            with os.fdopen(fd, "w") as f:
                json.dump(graded, f)
            os.replace(tmp, Path(folder) / f"{worker}-{os.getpid()}.json")
    else:
        _graded.update(graded)


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item: pytest.Item, call: pytest.CallInfo[Any]) -> Any:
    if call.when == "setup":
        feedback.reset_calls()
        remote.forget_calls()
    outcome = yield
    report = outcome.get_result()
    info = _exercise_of(item)
    if info is not None:
        report.user_properties.append((_PROPERTY, info))
        if report.failed and call.excinfo is not None:
            report.user_properties.append((_FEEDBACK, _sentence(item, info, call.excinfo)))
            if _student_view(item.config):  # the whole traceback, for the log file (the student sees one line)
                report.user_properties.append((_TRACE, _log_traceback(item, call.excinfo)[-20000:]))


def _log_traceback(item: pytest.Item, excinfo: pytest.ExceptionInfo[BaseException]) -> str:
    """A failed test's traceback for the grade's log, drawn as ``--tb=short`` draws it: the frames from the test's own
    on, without the frames that hide themselves (the grader's relay, pytest's), each with its line, then the error
    and what caused it. Each line is read with :mod:`linecache`: pytest's drawing parses every frame's whole file
    again for every failed test (~10 ms a failure: seconds for a class's untouched stubs)."""
    try:
        entries = item._traceback_filter(excinfo)  # type: ignore[attr-defined]  # pytest's pruning (pytest >= 8.0)
    except Exception:  # noqa: BLE001 - another pytest: only the frames that hide themselves go
        entries = excinfo.traceback.filter(excinfo)
    root = Path(str(item.config.rootpath))
    frames = []
    for entry in entries:
        path = Path(str(entry.path))
        shown = path.relative_to(root) if path.is_relative_to(root) else path
        frames.append(traceback.FrameSummary(str(shown), entry.lineno + 1, entry.name,
                                             line=linecache.getline(str(path), entry.lineno + 1)))
    lines = [*traceback.StackSummary.from_list(frames).format()]
    lines += [f"E   {line}\n" for line in "".join(traceback.format_exception_only(excinfo.value)).splitlines()]
    cause = excinfo.value.__cause__ or (None if excinfo.value.__suppress_context__ else excinfo.value.__context__)
    if cause is not None:
        lines += ["\nwhich came from:\n", *traceback.format_exception(cause)]
    return "".join(lines).rstrip("\n")


def _sentence(item: pytest.Item, info: dict[str, Any], excinfo: pytest.ExceptionInfo[BaseException]) -> str:
    """The student's one line for a failed graded test (:mod:`.feedback`), naming the exercise's file."""
    marker = item.get_closest_marker("exercise")
    hint = str(marker.kwargs.get("hint", "")) if marker is not None else ""
    params = getattr(getattr(item, "callspec", None), "params", {})
    backend = str(params.get("backend", "")) if isinstance(params.get("backend", ""), str) else ""
    step = Path(str(item.path)).parent.name
    name, error = str(info["exercise"]), excinfo.value
    remote.flush_calls()  # the student's newest calls, worded now that a sentence needs them
    try:
        file = feedback.exercise_file(step, name, backend)
        return feedback.sentence(error, exercise=name, file=file, hint=hint, values=_assert_values(item, excinfo),
                                 expected_raise=_expected_raise(item, excinfo))
    except Exception as exc:  # noqa: BLE001 - the feedback must never hide the failure itself
        return feedback.cap(f"{name}: {type(error).__name__}: {error} (feedback failed: {exc!r})")


def _config_of(report: pytest.TestReport) -> pytest.Config:
    return _config[0]


def _assert_values(item: pytest.Item, excinfo: pytest.ExceptionInfo[BaseException]) -> str:
    """For a bare ``assert`` in a test file: where its got and expected differ (:func:`.feedback.values_sentence`)."""
    if not isinstance(excinfo.value, AssertionError):
        return ""
    tests = Path(str(item.path)).parent.parent
    for entry in reversed(excinfo.traceback):
        if Path(str(entry.path)).is_relative_to(tests):
            try:
                statement = str(entry.statement)
            except Exception:  # noqa: BLE001 - no source: no values
                return ""
            return feedback.values_sentence(statement, entry.frame.f_globals, entry.frame.f_locals) or ""
    return ""


def _expected_raise(item: pytest.Item, excinfo: pytest.ExceptionInfo[BaseException]) -> str:
    """The error a ``pytest.raises`` block around the test's failing line waits for (:func:`.feedback.raises_expected`),
    for an error that escaped it or a call that did not raise."""
    if isinstance(excinfo.value, AssertionError):
        return ""
    for entry in reversed(excinfo.traceback):
        if Path(str(entry.path)) == Path(str(item.path)):  # the test's own file (a mutant's code may lie in tests/)
            try:
                code = entry.frame.code.raw
                source = inspect.getsource(code)
            except Exception:  # noqa: BLE001 - no source: no words
                return ""
            line = entry.lineno + 1 - code.co_firstlineno + 1  # entry.lineno counts from 0
            return feedback.raises_expected(source, line, entry.frame.f_globals, entry.frame.f_locals)
    return ""


def _student_view(config: pytest.Config) -> bool:
    """Whether this run grades a student's code (one line per failed graded test instead of tracebacks)."""
    return bool(config.getoption("--student") or os.environ.get(IMPL_ENV))


class _Crash:
    """A failed test's one line where pytest looks for the crash (``-rf`` summary, ``--tb=line``, JUnit XML)."""

    def __init__(self, test: str, message: str) -> None:
        self.test, self.message = test, message

    def __str__(self) -> str:
        return f"{self.test}: {self.message}"


class _Sentence:
    """A report's ``longrepr`` in the student's view: the one line, and nothing of the traceback."""

    def __init__(self, test: str, message: str, style: str) -> None:
        self.reprcrash, self.message, self.style = _Crash(test, message), message, style

    def toterminal(self, out: Any) -> None:
        if self.style != "line":  # --tb=line prints the crash line itself
            out.line(self.message, red=True)

    def __str__(self) -> str:
        return self.message


def _to_student_view(config: pytest.Config, report: pytest.TestReport, message: str) -> None:
    """Keep the full report for the log; show the student one line (no worker line, no traceback)."""
    trace = next((v for k, v in report.user_properties if k == _TRACE), None) or report.longreprtext
    _log.append(f"=== {report.nodeid} ({report.when})\n{message}\n\n{trace}\n")
    short, style = report.nodeid.split("::", 1)[-1], str(config.getoption("tbstyle", "auto"))
    if style in ("line", "auto", "no"):  # the student's view; an explicit --tb=long/short/native keeps the traceback
        report.longrepr = _Sentence(short, message, style)  # type: ignore[assignment]
    report.sections = [(name, text) for name, text in report.sections if "teardown" not in name]
    if hasattr(report, "node"):
        del report.node  # xdist's "[gw0] linux -- Python ..." line


def _message(report: pytest.TestReport) -> str:
    longrepr = report.longrepr
    if longrepr is None:
        return ""
    crash = getattr(longrepr, "reprcrash", None)
    if crash is not None and getattr(crash, "message", None):
        text = str(crash.message)
    elif isinstance(longrepr, tuple) and len(longrepr) == 3:  # a skip: (path, line, reason)
        text = str(longrepr[2])
    else:
        text = str(longrepr).strip().splitlines()[-1] if str(longrepr).strip() else ""
    text = text.removeprefix(f"{watchdog.__name__}.{watchdog.ExerciseTimeout.__name__}: ")
    return text if len(text) <= _MESSAGE_LIMIT else text[: _MESSAGE_LIMIT - 1] + "…"


def pytest_collectreport(report: pytest.CollectReport) -> None:
    """A test module that fails to import: its graded tests cannot be counted, so the grade says so."""
    if report.failed:
        text = str(report.longrepr).strip().splitlines()
        _collection_errors[report.nodeid] = (text[-1] if text else "failed to collect")[:_MESSAGE_LIMIT]


def pytest_runtest_logreport(report: pytest.TestReport) -> None:
    """Runs where the reports end up: in the one process, or in xdist's controller."""
    info = next((value for key, value in report.user_properties if key == _PROPERTY), None)
    if info is None and report.nodeid not in _outcomes and report.nodeid not in _graded:
        return  # not a graded test (a crash report of a graded test has no properties but a known id)
    if info is not None:
        _graded.setdefault(report.nodeid, dict(info))
    entry = _outcomes.setdefault(report.nodeid, {"passed_call": False, "failed": False, "message": "", "duration": 0.0})
    entry["duration"] += float(getattr(report, "duration", 0.0) or 0.0)
    entry["not_here"] = entry.get("not_here") or next((v for k, v in report.user_properties if k == _NOT_HERE), "")
    if report.when == "call" and report.passed:
        entry["passed_call"] = True
    elif report.failed or report.skipped:
        entry["failed"] = True
        if not entry["message"]:
            prefix = {"setup": "error in setup: ", "teardown": "error in teardown: "}.get(report.when, "")
            if report.skipped:
                prefix = "skipped: "
            elif report.when not in ("setup", "call", "teardown"):
                prefix = "the test process crashed (os._exit, a segfault or a hard timeout): "
            sentence = next((v for k, v in report.user_properties if k == _FEEDBACK), None)
            entry["message"] = (prefix + sentence) if sentence and not report.skipped else prefix + _message(report)
    if report.failed and _config and _student_view(_config_of(report)):
        text = feedback.cap(entry["message"] or "failed") if entry["message"] else "failed"
        entry["message"] = text
        _to_student_view(_config_of(report), report, text)


@pytest.hookimpl(optionalhook=True)
def pytest_handlecrashitem(crashitem: str, report: Any, sched: Any) -> None:
    """xdist (controller): a worker died in ``crashitem``; it is failed below (pytest_runtest_logreport)."""
    _outcomes.setdefault(crashitem, {"passed_call": False, "failed": True, "message": "", "duration": 0.0})


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_protocol(item: pytest.Item, nextitem: pytest.Item | None) -> Any:
    """In an xdist worker, ``--grade-hard-timeout`` ends the worker when one test hangs in native code."""
    limit = float(item.config.getoption("--grade-hard-timeout") or 0.0)
    timer = None
    if limit > 0 and _is_worker(item.config):

        def _die() -> None:
            sys.stderr.write(f"\ngandalf grading: {item.nodeid} ran over {limit:g} s; ending this worker\n")
            sys.stderr.flush()
            os._exit(70)

        timer = threading.Timer(limit, _die)
        timer.daemon = True
        timer.start()
    try:
        yield
    finally:
        if timer is not None:
            timer.cancel()


def _merge_worker_lists(config: pytest.Config) -> None:
    folder = getattr(config, "_gandalf_collect_dir", None)
    if not folder or not Path(folder).is_dir():
        return
    for path in sorted(Path(folder).glob("*.json")):
        try:
            for nodeid, info in json.loads(path.read_text()).items():
                _graded.setdefault(nodeid, info)
        except (OSError, ValueError):
            continue


# ---------------------------------------------------------------------------------------------------
# The grade
# ---------------------------------------------------------------------------------------------------


def _test_results() -> list[dict[str, Any]]:
    results = []
    for nodeid in sorted(_graded):
        info = _graded[nodeid]
        outcome = _outcomes.get(nodeid)
        if outcome is not None and outcome.get("not_here"):
            continue  # this machine lacks what the test's part needs (tests/conftest.py): not graded here
        if outcome is None:
            passed, message = False, "not run (the run stopped or its worker crashed before this test)"
        else:
            passed = outcome["passed_call"] and not outcome["failed"]
            message = "" if passed else (outcome["message"] or "failed")
        results.append(
            {
                "test": nodeid,
                "step": info["step"],
                "exercise": info["exercise"],
                "points": float(info["points"]),
                "passed": passed,
                "message": message,
            }
        )
    return results


def summary() -> dict[str, Any]:
    """Scores per step and exercise from the graded tests of the run."""
    tests = _test_results()
    # An exercise is worth its `points` (default 1) however many tests check it; the share of its
    # tests that pass earns that share of the points.
    by_exercise: dict[tuple[str, str], dict[str, float]] = defaultdict(
        lambda: {"possible": 0.0, "tests": 0, "passed": 0}
    )
    for entry in tests:
        agg = by_exercise[(entry["step"], entry["exercise"])]
        agg["possible"] = max(agg["possible"], entry["points"])
        agg["tests"] += 1
        agg["passed"] += int(entry["passed"])
    exercises = [
        {"step": s, "exercise": e, "earned": v["possible"] * v["passed"] / v["tests"], **v}
        for (s, e), v in sorted(by_exercise.items())
    ]
    earned = sum(x["earned"] for x in exercises)
    possible = sum(x["possible"] for x in exercises)
    return {
        "earned": earned,
        "possible": possible,
        "score": (earned / possible) if possible else 0.0,
        "graded_tests": len(tests),
        "graded_tests_passed": sum(1 for e in tests if e["passed"]),
        "collection_errors": dict(sorted(_collection_errors.items())),
        "exercises": exercises,
        "tests": tests,
    }


def gradescope_results(result: dict[str, Any], execution_time: float | None = None) -> dict[str, Any]:
    """Gradescope's ``results.json``: one entry per graded test, each exercise's points spread evenly
    over its tests, the failure message as the test's output."""
    exercises = {(x["step"], x["exercise"]): x for x in result["exercises"]}
    durations = {nodeid: o.get("duration", 0.0) for nodeid, o in _outcomes.items()}
    tests = []
    for entry in result["tests"]:
        x = exercises[(entry["step"], entry["exercise"])]
        share = x["possible"] / x["tests"]
        short = entry["test"].split("::", 1)[-1]
        tests.append(
            {
                "name": f"{entry['step']} · {entry['exercise']} · {short}",
                "score": share if entry["passed"] else 0.0,
                "max_score": share,
                "status": "passed" if entry["passed"] else "failed",
                "output": entry["message"] if not entry["passed"] else "",
                "tags": [entry["step"], entry["exercise"]],
                "visibility": "visible",
                "extra_data": {"nodeid": entry["test"], "duration_s": round(durations.get(entry["test"], 0.0), 4)},
            }
        )
    lines = [
        f"{x['step']} {x['exercise']}: {x['earned']:.2f} / {x['possible']:.2f} ({int(x['passed'])}/{int(x['tests'])})"
        for x in result["exercises"]
    ]
    warning = result.get("isolation_warning")
    out: dict[str, Any] = {
        "score": result["earned"],
        "output": "\n".join(([warning] if warning else []) + lines
                            + [f"TOTAL {result['earned']:.2f} / {result['possible']:.2f}"]),
        "visibility": "visible",
        "stdout_visibility": "hidden",
        "tests": tests,
    }
    if "isolation" in result:  # for the instructor: how the student's code was kept from the grader
        out["extra_data"] = {"isolation": result["isolation"], **({"isolation_warning": warning} if warning else {})}
    if execution_time is not None:
        out["execution_time"] = round(float(execution_time), 3)
    return out


def pytest_sessionstart(session: pytest.Session) -> None:
    session.config._gandalf_start = time.perf_counter()  # type: ignore[attr-defined]


def _log_path(config: pytest.Config) -> Path:
    """Where the full tracebacks go: ``--grade-log``, else beside the grade file, else the temporary folder."""
    chosen = config.getoption("--grade-log")
    if chosen:
        return Path(chosen)
    for option in ("--grade-json", "--gradescope"):
        if config.getoption(option):
            return Path(config.getoption(option)).with_suffix(".tracebacks.log")
    # A fresh, unpredictable file (O_EXCL): a name fixed in the shared temporary folder could be a planted link.
    fd, path = tempfile.mkstemp(prefix="gandalf-grade-", suffix=".tracebacks.log")
    os.close(fd)
    return Path(path)


def pytest_terminal_summary(terminalreporter: Any, exitstatus: int, config: pytest.Config) -> None:
    if _is_worker(config) or config.getoption("collectonly"):
        return
    _merge_worker_lists(config)
    if not _graded:
        return
    result = summary()
    student = bool(config.getoption("--student") or os.environ.get(IMPL_ENV)
                   or not all(_has_solutions(info["step"]) for info in _graded.values()))
    warning = None
    if student and not config.getoption("--grade-in-process"):  # how the student's code was kept from the checkout
        result["isolation"] = sandbox.isolation()
        warning = sandbox.isolation_warning(result["isolation"])
        if warning:
            result["isolation_warning"] = warning
    which = "exercises (student)" if student else "solutions (reference)"
    tr = terminalreporter
    tr.section(f"gandalf grade — {which}")
    if warning:  # loud, first and last: a grade that may be forged must not pass unnoticed
        tr.write_line(warning, red=True, bold=True)
    for x in result["exercises"]:
        tr.write_line(
            f"{x['step']:<22} {x['exercise']:<28} {x['earned']:>5.1f} / {x['possible']:<5.1f}"
            f" ({int(x['passed'])}/{int(x['tests'])} tests)"
        )
    tr.write_line(f"{'TOTAL':<51} {result['earned']:>5.1f} / {result['possible']:<5.1f} ({result['score']:.0%})")
    for nodeid, entry in sorted(_outcomes.items()):
        if entry.get("not_here") and nodeid in _graded:
            tr.write_line(f"NOT GRADED HERE: {nodeid}: {entry['not_here']}")
    for nodeid, message in result["collection_errors"].items():
        tr.write_line(f"NOT GRADED: {nodeid} failed to import, its tests are missing from the total ({message})")
    if _log:
        log = _log_path(config)
        log.parent.mkdir(parents=True, exist_ok=True)
        log.write_text("\n".join(_log))
        tr.write_line(f"full tracebacks of the failed tests: {log}")
    if warning:
        tr.write_line(warning, red=True, bold=True)
    path = config.getoption("--grade-json")
    if path:
        Path(path).write_text(json.dumps({"mode": which, **result}, indent=2))
        tr.write_line(f"grade written to {path}")
    gradescope = config.getoption("--gradescope")
    if gradescope:
        start = getattr(config, "_gandalf_start", None)
        elapsed = (time.perf_counter() - start) if start is not None else None
        Path(gradescope).parent.mkdir(parents=True, exist_ok=True)
        Path(gradescope).write_text(json.dumps(gradescope_results(result, elapsed), indent=2))
        tr.write_line(f"Gradescope results written to {gradescope}")


def pytest_unconfigure(config: pytest.Config) -> None:
    for box in {box for box, _package in _sandboxes.values()}:
        box.stop()
    _sandboxes.clear()
    shader_box.stop()
    remote.uninstall()
    folder = getattr(config, "_gandalf_collect_dir", None)
    if folder and Path(folder).is_dir():
        for path in Path(folder).iterdir():
            path.unlink(missing_ok=True)
        Path(folder).rmdir()
