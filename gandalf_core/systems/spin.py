"""A constant spin: the course's one spin component and system (step 03's textured cube, step 05's planets with
``local=True``, step 07's demos all use it).

``SpinSystem`` turns each ``SpinComponent``'s entity by ``speed * ts`` degrees a frame, written per entity (the
teaching form of a system).
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from ..components import TransformComponent
from ..ecs import Component, System
from ..math import quat_from_axis_angle, quat_mul, quat_normalize


class SpinComponent(Component):
    """Rotate the entity about a world ``axis`` at ``speed`` degrees per second (right-hand rule).

    With ``local=True`` the axis is the entity's own (its local frame): a tilted planet spins about its tilted
    axis instead of precessing about the world's.
    """

    def __init__(self, axis: Sequence[float] = (0.0, 1.0, 0.0), speed: float = 30.0, local: bool = False) -> None:
        a = np.asarray(axis, dtype=np.float64)
        if a.shape != (3,) or not np.all(np.isfinite(a)) or np.linalg.norm(a) <= 1e-12:
            raise ValueError(f"SpinComponent.axis must be a non-zero finite 3-vector, got {axis!r}")
        if not np.isfinite(speed):
            raise ValueError(f"SpinComponent.speed must be finite, got {speed!r}")
        self.axis = a / np.linalg.norm(a)
        self.speed = float(speed)
        self.local = bool(local)


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
