"""Exercise: an orbit camera driven by the mouse.

Every frame, for each entity with an OrbitCameraComponent and a TransformComponent:

1. Read ``self.scene.app.input`` (skip the input part when ``self.scene.app`` is None).
2. While the left mouse button (0) is down (``0 in input.buttons_down``), turn by this frame's mouse
   movement ``dx, dy = input.mouse_delta()``: ``yaw -= dx * sensitivity`` and ``pitch += dy * sensitivity``;
   clamp pitch to [min_pitch, max_pitch].
3. Zoom with the scroll wheel: ``distance *= zoom_factor ** input.scroll_delta()``, clamped to
   [min_distance, max_distance].
4. Place the camera: eye = target + distance * (cos(pitch) sin(yaw), sin(pitch), cos(pitch) cos(yaw))
   (angles in degrees!), and turn it to look at the target: write ``transform.translation`` and
   ``transform.quaternion`` (``gandalf_core.math.look_at_rotation`` or ``quat_from_euler`` help).
"""

from __future__ import annotations

from gandalf_core import System, TransformComponent

from ..components import OrbitCameraComponent


class OrbitCameraSystem(System):
    """Places orbit cameras from their yaw, pitch and distance, and lets the mouse change them."""

    def __init__(self) -> None:
        super().__init__([OrbitCameraComponent, TransformComponent])

    def on_update_system(self, ts: float) -> None:
        # The matching entities' components, in the order given to __init__:
        #     for orbit, transform in self.components: ...
        raise NotImplementedError("exercise: OrbitCameraSystem.on_update_system")
