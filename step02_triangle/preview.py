"""Render one mesh headless with the step's shader, in either API: for trying out your own meshes.

``render_mesh("webgpu", ngon_mesh(7, 0.8))`` returns the picture as a (height, width, 4) uint8 array.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from gandalf_core import Application, ClearColorComponent, Scene, TransformComponent
from gandalf_core.components import MaterialComponent, MeshComponent
from gandalf_core.resources import MaterialData, MeshData

from .scene import SHADER, register_shaders


def render_mesh(backend: str, mesh: MeshData, width: int = 96, height: int = 72, *,
                transform: TransformComponent | None = None, clear_color: Sequence[float] = (0.0, 0.0, 0.0),
                cull: str = "back") -> np.ndarray:
    """Draw ``mesh`` once (clip space, placed by ``transform``) on ``clear_color``; return the picture."""
    scene = Scene("preview")
    scene.assets.mesh("mesh", mesh)
    scene.assets.material("material", MaterialData(SHADER, cull=cull, name="material"))
    scene.create_entity(ClearColorComponent(tuple(clear_color)))
    scene.create_entity(transform or TransformComponent(), MeshComponent("mesh"), MaterialComponent("material"))
    with Application(backend, width, height, headless=True) as app:
        register_shaders(app)
        app.add_scene(scene)
        app.run(frames=1)
        return app.capture()
