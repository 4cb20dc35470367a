"""Reference solution: the orbit camera system."""

from __future__ import annotations

import math

import numpy as np

from gandalf_core import System, TransformComponent
from gandalf_core.math import look_at_rotation

from ..components import OrbitCameraComponent

LEFT_BUTTON = 0


class OrbitCameraSystem(System):
    """Left-drag turns the orbit, scrolling zooms; the camera always looks at its target."""

    def __init__(self) -> None:
        super().__init__([OrbitCameraComponent, TransformComponent])

    def on_update_system(self, ts: float) -> None:
        app = self.scene.app
        dx = dy = scroll = 0.0
        if app is not None:
            if LEFT_BUTTON in app.input.buttons_down:
                dx, dy = app.input.mouse_delta()
            scroll = app.input.scroll_delta()
        for orbit, transform in self.components:
            orbit.yaw -= dx * orbit.sensitivity
            orbit.pitch = float(np.clip(orbit.pitch + dy * orbit.sensitivity, orbit.min_pitch, orbit.max_pitch))
            orbit.distance = float(
                np.clip(orbit.distance * orbit.zoom_factor**scroll, orbit.min_distance, orbit.max_distance)
            )
            yaw, pitch = math.radians(orbit.yaw), math.radians(orbit.pitch)
            direction = np.array([math.cos(pitch) * math.sin(yaw), math.sin(pitch), math.cos(pitch) * math.cos(yaw)])
            eye = orbit.target + orbit.distance * direction
            transform.translation = eye
            transform.quaternion = look_at_rotation(eye, orbit.target)
