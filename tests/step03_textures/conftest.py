"""Step 03 tests get the implementation under test (solutions, or exercises with --student) as ``impl``,
and ``render_scene``: draw a scene with the step's textured shader, headless, in one backend."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest

from gandalf_core import Application, Scene
from gandalf_tools.grading.plugin import impl_fixture
from step03_textures.scene import SHADER

#: The step's shader folder.
SHADERS = Path(__file__).resolve().parents[2] / "step03_textures" / "shaders"

impl = impl_fixture("step03_textures")


def render(backend: str, scene: Scene, width: int, height: int, frames: int = 1) -> tuple[np.ndarray, dict]:
    """The last frame (top row first) and the renderer's stats after ``frames`` frames of ``scene``."""
    with Application(backend, width, height, headless=True, fixed_dt=1 / 60) as app:
        if backend == "opengl":
            app.renderer.shaders.build(SHADER, SHADERS / "textured.vert", SHADERS / "textured.frag")
        else:
            app.renderer.shaders.build(SHADER, SHADERS / "textured.wgsl")
        app.add_scene(scene)
        app.run(frames=frames)
        return app.capture(), dict(app.renderer.stats)


@pytest.fixture
def render_scene() -> Callable[..., tuple[np.ndarray, dict]]:
    """``render_scene(backend, scene, width, height, frames=1) -> (image, stats)``."""
    return render
