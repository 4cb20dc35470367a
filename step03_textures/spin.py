"""The spin system of step 03 (not an exercise): turns every SpinComponent's entity a little each frame."""

from __future__ import annotations

import math

from gandalf_core import System, TransformComponent
from gandalf_core.math import quat_from_axis_angle, quat_mul, quat_normalize
from gandalf_core.usd import register_system

from .components import SpinComponent


class SpinSystem(System):
    """Turns each entity by ``speed * ts`` degrees about its spin axis: the world's, or with ``local`` its own."""

    def __init__(self) -> None:
        super().__init__([SpinComponent, TransformComponent])

    def on_update_entity(self, ts, entity, components) -> None:
        spin, transform = components
        step = quat_from_axis_angle(spin.axis, math.radians(spin.speed * ts))
        # On the left the turn is about the *world* axis, whatever the entity's orientation; on the right it is
        # applied first, in the entity's own frame. Normalising keeps a long spin free of rounding drift.
        if spin.local:
            transform.quaternion = quat_normalize(quat_mul(transform.quaternion, step))
        else:
            transform.quaternion = quat_normalize(quat_mul(step, transform.quaternion))


register_system(SpinSystem)  # allowed in saved scenes (gandalf_core.usd)
