"""Shared fixtures: headless apps for both backends and image comparison helpers."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))
# Helpers every step's tests share (the shader harness) live in tests/ itself.
TESTS = Path(__file__).resolve().parent
if str(TESTS) not in sys.path:
    sys.path.append(str(TESTS))


@pytest.fixture(params=["opengl", "webgpu"])
def backend(request: pytest.FixtureRequest) -> str:
    """Runs a test once per backend."""
    return request.param


# --- capabilities: a part this machine cannot run is skipped, "not graded here" -----------------------------------
#: The report property that tells the grade a test was not graded here (and why).
NOT_HERE = "gandalf_not_here"


def not_here(excinfo: pytest.ExceptionInfo[BaseException]) -> str:
    """The reason a test cannot run on this machine, or "" for a real failure.

    Only a :class:`~gandalf_core.render.capabilities.CapabilityError` counts, and only when the machine really
    lacks what it names (probed again here) and no exercise code raised it (an exercise cannot skip its test).
    """
    from gandalf_core.render.capabilities import CapabilityError, offer_here

    exc = excinfo.value
    if not isinstance(exc, CapabilityError):
        return ""
    tb = excinfo.tb
    while tb is not None:
        if str(tb.tb_frame.f_globals.get("__name__", "")).split(".")[1:2] == ["exercises"]:
            return ""
        tb = tb.tb_next
    return str(exc) if exc.needs.missing(offer_here(exc.offer.api)) else ""


@pytest.hookimpl(wrapper=True)
def pytest_runtest_makereport(item: pytest.Item, call: pytest.CallInfo[None]) -> pytest.TestReport:
    report = yield
    reason = not_here(call.excinfo) if call.excinfo is not None and report.failed else ""
    if reason:
        report.outcome = "skipped"
        report.longrepr = (str(item.path), item.location[1] or 0, f"Skipped: not graded here: {reason}")
        report.user_properties.append((NOT_HERE, reason))
    return report


def skip_unless_here(part: str, api: str) -> None:
    """Skip the test, not graded here, when this machine cannot run ``part`` (``step07_advanced.filter``) in
    ``api``: for tests that use a part's pieces without its launcher (the hook above turns the error into the
    skip)."""
    import importlib

    from gandalf_core.render.capabilities import check, offer_here

    check(importlib.import_module(f"{part}.scene").PART.needs, offer_here(api), part)
