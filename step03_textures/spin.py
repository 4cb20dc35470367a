"""The spin system of step 03 (not an exercise): turns every SpinComponent's entity a little each frame."""

from __future__ import annotations

import math

from gandalf_core import System, TransformComponent
from gandalf_core.math import quat_from_axis_angle, quat_mul

from .components import SpinComponent


class SpinSystem(System):
    """Pre-multiplies each entity's rotation by ``speed * ts`` degrees about its world axis."""

    def __init__(self) -> None:
        super().__init__([SpinComponent, TransformComponent])

    def on_update_entity(self, ts, entity, components) -> None:
        spin, transform = components
        step = quat_from_axis_angle(spin.axis, math.radians(spin.speed * ts))
        # Multiplying on the left turns about the *world* axis, whatever the entity's current orientation.
        transform.quaternion = quat_mul(step, transform.quaternion)
