"""The step's own (non-exercise) systems: a camera placed from a view matrix, and camera switching with C."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from gandalf_core import System, TransformComponent
from gandalf_core.components import CameraComponent
from gandalf_core.math import decompose_trs, invert_affine

from .components import LookAtComponent

#: The key that makes the next camera the primary one.
SWITCH_KEY = "C"


class LookAtSystem(System):
    """Sets each LookAt camera's transform from a view matrix made by ``look_at(eye, target, up)``.

    The render system computes view = inverse(camera world) every frame, so the camera's world
    transform must be inverse(view): we invert the look-at matrix and split it into translation and
    rotation. ``look_at`` is the student's function in the demo (``impl.look_at``).
    """

    def __init__(self, look_at: Callable[..., np.ndarray]) -> None:
        super().__init__([LookAtComponent, TransformComponent])
        self.look_at = look_at

    def on_update_entity(self, ts, entity, components) -> None:
        placement, transform = components
        view = np.asarray(self.look_at(placement.eye, placement.target, placement.up), dtype=np.float64)
        translation, quaternion, _scale = decompose_trs(invert_affine(view))
        transform.translation = translation
        transform.quaternion = quaternion


class CameraSwitchSystem(System):
    """When C is pressed, the next camera (in creation order) becomes the only primary one."""

    def __init__(self) -> None:
        super().__init__([CameraComponent])

    def on_update_system(self, ts: float) -> None:
        app = self.scene.app
        if app is None or not app.input.pressed(SWITCH_KEY):
            return
        cameras = self.column(CameraComponent)
        current = next((i for i, c in enumerate(cameras) if c.primary), -1)
        for i, camera in enumerate(cameras):
            camera.primary = i == (current + 1) % len(cameras)
