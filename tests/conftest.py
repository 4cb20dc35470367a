"""Shared fixtures: headless apps for both backends and image comparison helpers."""

from __future__ import annotations

import os
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))
# Helpers every step's tests share (the shader harness) live in tests/ itself.
TESTS = Path(__file__).resolve().parent
if str(TESTS) not in sys.path:
    sys.path.append(str(TESTS))


@pytest.fixture
def one_window_at_a_time() -> Iterator[None]:
    """Hold the display for this test alone, across pytest-xdist's worker processes (a lock file): two windows
    made at once on one X display can crash Mesa's GLX, and an obscured window's pixels are undefined to a read of
    its framebuffer. Used by every test that opens real windows."""
    import fcntl
    import tempfile

    with open(Path(tempfile.gettempdir()) / f"gandalf-display-{os.environ.get('DISPLAY', 'none')}.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        try:
            yield
        finally:
            fcntl.flock(lock, fcntl.LOCK_UN)


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    """The in-process window tests (``tests/core/test_window.py``) first, so that a process opens its windows before
    any headless context: after headless EGL contexts in the same process Mesa's GLX refuses a window's context
    (``X_GLXMakeCurrent``: BadAccess) and Xlib ends the process. pytest-xdist hands tests out in this order (the
    first worker's share starts with them), so they run first in a worker's fresh process too."""
    first = [item for item in items if item.path.name == "test_window.py"]
    if first:
        items[:] = first + [item for item in items if item.path.name != "test_window.py"]


@pytest.fixture(params=["opengl", "webgpu"])
def backend(request: pytest.FixtureRequest) -> str:
    """Runs a test once per backend."""
    return request.param


@pytest.hookimpl(wrapper=True)
def pytest_runtest_makereport(item: pytest.Item, call: pytest.CallInfo[None]) -> pytest.TestReport:
    """Two failures that are no failure of the course are skipped, naming why:

    * a test without a grade that stops on an untouched exercise stub (the student's release runs the steps with
      the student's exercises), naming the exercise and its file; a graded test fails as it must;
    * a test this machine cannot run (a part's need it lacks): the grade leaves it out ("not graded here").
    """
    report = yield
    if report.failed and call.excinfo is not None and item.get_closest_marker("exercise") is None:
        from gandalf_core.app.cli import unfinished_exercise

        error, sentence = call.excinfo.value, None
        while error is not None and sentence is None:  # also behind pytest.raises/warns ("DID NOT WARN")
            sentence, error = unfinished_exercise(error), error.__cause__ or error.__context__
        if sentence is not None:
            report.outcome = "skipped"
            report.longrepr = (str(item.path), item.location[1] or 0, f"waits for your exercise: {sentence}")
    from capabilities_here import mark_not_here

    return mark_not_here(item, call, report)
