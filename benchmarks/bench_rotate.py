"""The rotation the benchmark scenes spin their models with, in its teaching form: a component with an axis and a
speed, and a system that turns each entity in one Python call per frame. It imports the engine, so a script
imports it where the engine is wanted (in its child process), by name like ``bench_common``."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from gandalf_core import Component, System, TransformComponent
from gandalf_core.math import quat_from_axis_angle, quat_mul, quat_normalize


class RotateComponent(Component):
    """Spin about ``axis`` at ``speed`` degrees per second."""

    def __init__(self, axis: tuple[float, float, float], speed: float) -> None:
        self.axis = np.asarray(axis, dtype=np.float64)
        self.speed = float(speed)


class RotateEntitySystem(System):
    """The teaching form: one Python call per entity per frame (``normalize``: renormalise each quaternion)."""

    def __init__(self, normalize: bool = False) -> None:
        super().__init__([TransformComponent, RotateComponent])
        self.normalize = normalize

    def on_update_entity(self, ts: float, entity: Any, components: tuple[Any, ...]) -> None:
        transform, rotate = components
        q = quat_mul(quat_from_axis_angle(rotate.axis, math.radians(rotate.speed) * ts), transform.quaternion)
        transform.quaternion = quat_normalize(q) if self.normalize else q
