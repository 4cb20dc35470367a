"""The component of step 03: a constant spin that makes the textured cube show all its faces.

It is the course's one spin: step 05's planets (``local=True``) and step 07's demos import it from here.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from gandalf_core import Component
from gandalf_core.usd import register_component


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


register_component(SpinComponent, fields=["axis", "speed", "local"])  # saved in USD files
