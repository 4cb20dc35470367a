"""Step 07's small helper for the demo: a steady spin about an axis (the parallax-mapped cube turns with it)."""

from __future__ import annotations

import uuid
from collections.abc import Sequence
from typing import Any

import numpy as np

from gandalf_core import TransformComponent
from gandalf_core.ecs import Component, System
from gandalf_core.math import quat_from_axis_angle, quat_mul, quat_normalize


class SpinComponent(Component):
    """Turn about the unit ``axis`` (world space) at ``degrees_per_second``."""

    def __init__(self, axis: Sequence[float] = (0.0, 1.0, 0.0), degrees_per_second: float = 20.0) -> None:
        a = np.asarray(axis, dtype=np.float64)
        length = float(np.linalg.norm(a)) if a.shape == (3,) and np.all(np.isfinite(a)) else 0.0
        if length <= 1e-12:
            raise ValueError(f"SpinComponent.axis must be a non-zero finite 3-vector, got {axis!r}")
        self.axis = a / length
        self.degrees_per_second = float(degrees_per_second)


class SpinSystem(System):
    """Adds ``degrees_per_second · ts`` of rotation about the spin axis every frame (pre-multiplied: world axis)."""

    def __init__(self) -> None:
        super().__init__((SpinComponent, TransformComponent))

    def on_update_entity(self, ts: float, entity: uuid.UUID, components: tuple[Any, ...]) -> None:
        spin, transform = components
        step = quat_from_axis_angle(spin.axis, np.radians(spin.degrees_per_second * ts))
        transform.quaternion = quat_normalize(quat_mul(step, transform.quaternion))
