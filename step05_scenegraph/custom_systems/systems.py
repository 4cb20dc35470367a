"""The custom systems of step 05: a system that simulates on a fixed time step, and gravity done right.

The paper's gravity example moved the position by ``force * ts`` each frame, which is a constant speed, not
a fall. Here the fall is integrated exactly (``x += v dt - g dt² / 2`` with the old ``v``, then ``v -= g dt``:
constant acceleration has a closed form) on a fixed time step, so the path is the same at any ``dt`` and any
frame rate. :class:`FixedStepSystem` is the pattern
(the integrators' SpringSystem is one too): it runs whole fixed steps and shows the state interpolated to the
frame's time.
"""

from __future__ import annotations

import numpy as np

from gandalf_core import System, TransformComponent

from .components import GravityComponent
from .fixed_step import FixedStep

__all__ = ["FixedStepSystem", "GravitySystem"]


# --8<-- [start:fixed_step_system]
class FixedStepSystem(System):
    """A system that simulates at a fixed ``dt`` and shows the state interpolated to the frame time.

    Its entities have a body component (with ``position``, ``previous``) and a Transform; a
    subclass says what one step does to a body (:meth:`step`).
    """

    def __init__(self, component_types, dt: float) -> None:
        super().__init__(component_types)
        self.clock = FixedStep(dt)

    def on_update_system(self, ts: float) -> None:
        for _ in range(self.clock.advance(ts)):
            for body, _transform in self.components:
                body.previous = body.position.copy()
                self.step(body, self.clock.dt)
        alpha = self.clock.alpha
        for body, transform in self.components:
            transform.translation = body.previous + alpha * (body.position - body.previous)
# --8<-- [end:fixed_step_system]

    def on_create_entity(self, entity, components) -> None:
        body, transform = components
        body.position = np.array(transform.translation)
        body.previous = body.position.copy()

    def step(self, body, dt: float) -> None:
        raise NotImplementedError(f"{type(self).__name__}.step(body, dt): one fixed step of the simulation")


# --8<-- [start:gravity]
class GravitySystem(FixedStepSystem):
    """Falling bodies: the exact constant-gravity step and an optional bouncy floor."""

    def __init__(self, dt: float = 1.0 / 120.0) -> None:
        super().__init__([GravityComponent, TransformComponent], dt)

    def step(self, body: GravityComponent, dt: float) -> None:
        fall = np.array([0.0, 0.5 * body.gravity * dt * dt, 0.0])
        body.position = body.position + body.velocity * dt - fall
        body.velocity[1] -= body.gravity * dt
        if body.floor is not None and body.position[1] < body.floor:
            # Reflect the penetration and the velocity; restitution < 1 loses energy at each bounce.
            body.position[1] = body.floor + (body.floor - body.position[1]) * body.restitution
            body.velocity[1] = -body.velocity[1] * body.restitution
# --8<-- [end:gravity]

# Saved in USD scenes by name (the loader only builds classes registered like this).
