"""The component of step 03: a constant spin that makes the textured cube show all its faces."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from gandalf_core import Component


class SpinComponent(Component):
    """Rotate the entity about a world ``axis`` at ``speed`` degrees per second (right-hand rule)."""

    def __init__(self, axis: Sequence[float] = (0.0, 1.0, 0.0), speed: float = 30.0) -> None:
        a = np.asarray(axis, dtype=np.float64)
        if a.shape != (3,) or not np.all(np.isfinite(a)) or np.linalg.norm(a) <= 1e-12:
            raise ValueError(f"SpinComponent.axis must be a non-zero finite 3-vector, got {axis!r}")
        if not np.isfinite(speed):
            raise ValueError(f"SpinComponent.speed must be finite, got {speed!r}")
        self.axis = a / np.linalg.norm(a)
        self.speed = float(speed)
