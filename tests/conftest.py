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
