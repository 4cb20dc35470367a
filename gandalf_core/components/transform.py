"""The Transform component: translation, rotation (unit quaternion) and scale, plus the world matrix.

Its fields live in scene-wide numpy columns (see :class:`~gandalf_core.ecs.ColumnarComponent`), so the
transform system computes every world matrix in a few vectorised numpy calls.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from ..ecs import ColumnarComponent
from ..math import quat_from_euler, quat_normalize, quat_to_euler


class TransformComponent(ColumnarComponent):
    """Local TRS relative to the parent (or the world for roots); ``world`` is written by the transform system.

    ``rotation`` takes Euler degrees (X, then Y, then Z) for convenience; the state is ``quaternion``
    (w, x, y, z).
    """

    columns = {
        "translation": ((3,), 0.0),
        "quaternion": ((4,), (1.0, 0.0, 0.0, 0.0)),
        "scale": ((3,), 1.0),
        "world": ((4, 4), np.eye(4)),
    }

    def __init__(
        self,
        translation: Sequence[float] = (0.0, 0.0, 0.0),
        rotation: Sequence[float] = (0.0, 0.0, 0.0),
        scale: float | Sequence[float] = (1.0, 1.0, 1.0),
        *,
        quaternion: Sequence[float] | None = None,
    ) -> None:
        super().__init__()
        self.translation = translation
        if quaternion is not None:
            self.quaternion = quat_normalize(quaternion)
        elif any(rotation):  # the default (no rotation) is already in place
            self.quaternion = quat_from_euler(rotation)
        self.scale = scale

    @property
    def rotation(self) -> np.ndarray:
        """The rotation as Euler degrees (X, Y, Z); assigning sets the quaternion."""
        return quat_to_euler(self.quaternion)

    @rotation.setter
    def rotation(self, degrees: Sequence[float]) -> None:
        self.quaternion = quat_from_euler(degrees)

    @property
    def world_position(self) -> np.ndarray:
        return np.array(self.world[:3, 3])
