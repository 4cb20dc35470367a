"""Shared helpers of the step 04 tests: headless apps of the step's scene and the camera they render with."""

from __future__ import annotations

from pathlib import Path
from types import SimpleNamespace

import numpy as np

from gandalf_core import Application
from gandalf_core.app.cli import load_impl
from gandalf_core.render import RenderSystem
from step04_camera.scene import build_scene, register_shaders

REFERENCES = Path(__file__).resolve().parent / "references"
SIZE = (128, 96)


def make_app(backend: str, impl: object, size: tuple[int, int] = SIZE) -> Application:
    """A headless app of the step's scene with ``impl`` providing look_at and OrbitCameraSystem."""
    app = Application(backend, *size, headless=True, fixed_dt=1 / 60)
    register_shaders(app)
    app.add_scene(build_scene(impl))
    return app


def only(**parts: object) -> SimpleNamespace:
    """An implementation taking ``parts`` from the code under test and the rest from the reference
    solutions, so that each exercise is graded on its own (in a student's release, which has no solutions, the rest
    is the student's too)."""
    reference = load_impl("step04_camera")
    return SimpleNamespace(**{"look_at": reference.look_at, "OrbitCameraSystem": reference.OrbitCameraSystem, **parts})


def rendered_camera(app: Application) -> tuple[np.ndarray, np.ndarray]:
    """(view, projection) the render system used for the last frame's primary camera."""
    view, projection = app.scene.get_system(RenderSystem).camera()[:2]
    return view, projection
