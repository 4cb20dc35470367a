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


@pytest.fixture(scope="module")
def apps() -> Iterator[dict[str, Application]]:
    """Headless apps by backend, made on first use and shared by one module's cases (for tables parametrised with
    :func:`bad_input.catalogue.params_per_backend`): ``apps.get(backend)``."""
    made: dict[str, Application] = {}

    class Apps(dict):
        def __missing__(self, backend: str) -> Application:
            made[backend] = self[backend] = Application(backend, W, H, headless=True, fixed_dt=1 / 60)
            return made[backend]

    try:
        yield Apps()
    finally:
        for app in made.values():
            app.close()
