"""One headless app per backend for a whole catalogue file (apps cost ~0.1-0.5 s each; cases share them)."""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from gandalf_core import Application

#: A tiny target: the catalogue checks errors and values, not pictures.
W, H = 16, 12


@pytest.fixture(scope="module", params=["opengl", "webgpu"])
def shared_app(request: pytest.FixtureRequest) -> Iterator[Application]:
    """A headless app of each backend, shared by the cases of one module (cases must leave it usable)."""
    app = Application(request.param, W, H, headless=True, fixed_dt=1 / 60)
    try:
        yield app
    finally:
        app.close()
