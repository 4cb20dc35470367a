"""The system of step 06 that is not an exercise: it moves the orbiting lights."""

from __future__ import annotations

from gandalf_core import System, TransformComponent

from .components import OrbitComponent


class OrbitSystem(System):
    """Advances each OrbitComponent's angle by ``speed * ts`` and moves its entity onto the circle."""

    def __init__(self) -> None:
        super().__init__([OrbitComponent, TransformComponent])

    def on_update_entity(self, ts, entity, components) -> None:
        orbit, transform = components
        orbit.angle = (orbit.angle + orbit.speed * ts) % 360.0
        transform.translation = orbit.position()


