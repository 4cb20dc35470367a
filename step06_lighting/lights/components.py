"""The component of step 06: a light that circles a vertical axis (the demo's ring of coloured lights)."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from gandalf_core import Component


class OrbitComponent(Component):
    """Circle of ``radius`` around ``center`` (at its height), at ``angle`` degrees, turning ``speed`` degrees/s."""

    def __init__(self, center: Sequence[float] = (0.0, 0.0, 0.0), radius: float = 1.0, angle: float = 0.0,
                 speed: float = 30.0) -> None:
        self.center = np.asarray(center, dtype=np.float64).reshape(3)
        self.radius = float(radius)
        self.angle = float(angle)
        self.speed = float(speed)

    def position(self) -> np.ndarray:
        """The point on the circle for the current angle (0° is +X, 90° is -Z: counter-clockwise from above)."""
        a = np.radians(self.angle)
        return self.center + self.radius * np.array([np.cos(a), 0.0, -np.sin(a)])


