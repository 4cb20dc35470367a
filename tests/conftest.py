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


@pytest.hookimpl(wrapper=True)
def pytest_runtest_makereport(item: pytest.Item, call: pytest.CallInfo[None]) -> pytest.TestReport:
    """A test this machine cannot run (a part's need it lacks) is skipped, and the grade leaves it out."""
    from capabilities_here import mark_not_here

    return mark_not_here(item, call, (yield))
