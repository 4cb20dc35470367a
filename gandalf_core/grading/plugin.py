"""The course autograder, as a pytest plugin.

* ``pytest tests/step01_window`` grades the reference ``solutions`` (CI stays green).
* ``pytest --student tests/step01_window`` grades the student's ``exercises`` instead, prints a score
  per exercise, and ``--grade-json result.json`` writes it for course platforms.

A graded test carries ``@pytest.mark.exercise("name", points=1)`` and receives the implementation
under test through the ``impl`` fixture, which a step's ``conftest.py`` creates with
:func:`impl_fixture`.
"""

from __future__ import annotations

import importlib
import json
from collections import defaultdict
from pathlib import Path
from types import ModuleType
from typing import Any

import pytest

_results: dict[str, dict[str, Any]] = {}


def pytest_addoption(parser: pytest.Parser) -> None:
    group = parser.getgroup("gandalf grading")
    group.addoption("--student", action="store_true", help="grade the exercises/ stubs instead of solutions/")
    group.addoption("--grade-json", metavar="PATH", help="write the per-exercise score as JSON to PATH")


def pytest_configure(config: pytest.Config) -> None:
    config.addinivalue_line("markers", "exercise(name, points=1): a graded test of exercise `name`")
    _results.clear()


# --8<-- [start:impl_fixture]
def impl_fixture(step_package: str) -> Any:
    """Create the ``impl`` fixture of a step: its ``exercises`` or ``solutions`` package."""

    @pytest.fixture
    def impl(request: pytest.FixtureRequest) -> ModuleType:
        which = "exercises" if request.config.getoption("--student") else "solutions"
        return importlib.import_module(f"{step_package}.{which}")

    return impl
# --8<-- [end:impl_fixture]


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item: pytest.Item, call: pytest.CallInfo[Any]) -> Any:
    outcome = yield
    report = outcome.get_result()
    marker = item.get_closest_marker("exercise")
    if marker is None:
        return
    name = marker.args[0] if marker.args else marker.kwargs["name"]
    points = float(marker.kwargs.get("points", 1))
    step = Path(str(item.path)).parent.name
    key = item.nodeid
    entry = _results.setdefault(key, {"step": step, "exercise": name, "points": points, "passed": True})
    if report.failed or (report.when == "call" and report.skipped):
        entry["passed"] = False
    if report.when == "setup" and report.skipped:
        entry["passed"] = False


def summary() -> dict[str, Any]:
    """Scores per step and exercise from the graded tests that ran."""
    # An exercise is worth its `points` (default 1) however many tests check it; the share of its
    # tests that pass earns that share of the points.
    by_exercise: dict[tuple[str, str], dict[str, float]] = defaultdict(
        lambda: {"possible": 0.0, "tests": 0, "passed": 0}
    )
    for entry in _results.values():
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
        "graded_tests": len(_results),
        "graded_tests_passed": sum(1 for e in _results.values() if e["passed"]),
        "exercises": exercises,
        "tests": [{"test": k, **v} for k, v in sorted(_results.items())],
    }


def pytest_terminal_summary(terminalreporter: Any, exitstatus: int, config: pytest.Config) -> None:
    if not _results:
        return
    result = summary()
    which = "exercises (student)" if config.getoption("--student") else "solutions (reference)"
    tr = terminalreporter
    tr.section(f"gandalf grade — {which}")
    for x in result["exercises"]:
        tr.write_line(
            f"{x['step']:<22} {x['exercise']:<28} {x['earned']:>5.1f} / {x['possible']:<5.1f}"
            f" ({int(x['passed'])}/{int(x['tests'])} tests)"
        )
    tr.write_line(f"{'TOTAL':<51} {result['earned']:>5.1f} / {result['possible']:<5.1f} ({result['score']:.0%})")
    path = config.getoption("--grade-json")
    if path:
        Path(path).write_text(json.dumps({"mode": which, **result}, indent=2))
        tr.write_line(f"grade written to {path}")
