"""The core tests' own shaders (``tests/core/shaders/``), one call that builds them for either API, and a scene's
picture drawn with them."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from gandalf_core import Application, Scene

SHADERS = Path(__file__).resolve().parent / "shaders"
#: name -> (GLSL vertex, GLSL fragment, WGSL) file names in SHADERS.
FILES = {
    "unlit": ("unlit.vert", "unlit.frag", "unlit.wgsl"),
    "lit": ("lit.vert", "lit.frag", "lit.wgsl"),
    "flat": ("unlit.vert", "flat.frag", "flat.wgsl"),
}


def build_shaders(shaders: Any, backend: str, *names: str) -> None:
    """Build each of ``names`` (keys of :data:`FILES`) in a renderer's shader library ``shaders`` for ``backend``:
    GLSL has a file per stage, WGSL one module with both."""
    for name in names:
        vert, frag, wgsl = FILES[name]
        if backend == "opengl":
            shaders.build(name, SHADERS / vert, SHADERS / frag)
        else:
            shaders.build(name, SHADERS / wgsl)


def render_scene(backend: str, scene: Scene, size: tuple[int, int] = (96, 72),
                 shaders: tuple[str, ...] = ("unlit", "lit"),
                 frames: int = 2) -> np.ndarray:
    """``scene``'s picture after ``frames`` frames of a headless ``backend`` app of ``size`` with ``shaders`` built."""
    with Application(backend, *size, headless=True, fixed_dt=1 / 60) as app:
        build_shaders(app.renderer.shaders, backend, *shaders)
        app.add_scene(scene)
        app.run(frames=frames)
        return app.capture()
