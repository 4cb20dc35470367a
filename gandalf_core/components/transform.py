"""The Transform component: translation, rotation (unit quaternion) and scale, plus the world matrix.

Its fields live in scene-wide numpy columns (see :class:`~gandalf_core.ecs.ColumnarComponent`), so the
transform system computes every world matrix in a few vectorised numpy calls.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from numpy.typing import ArrayLike

from ..ecs import ColumnarComponent
from ..ecs.component import ColumnBatch
from ..math import quat_from_euler, quat_normalize, quat_to_euler

_ZERO3 = (0.0, 0.0, 0.0)
_ONE3 = (1.0, 1.0, 1.0)


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
        translation: Sequence[float] = _ZERO3,
        rotation: Sequence[float] = _ZERO3,
        scale: float | Sequence[float] = _ONE3,
        *,
        quaternion: Sequence[float] | None = None,
    ) -> None:
        super().__init__()
        if translation is not _ZERO3:  # the defaults are already in place
            self.translation = translation
        if quaternion is not None:
            self.quaternion = quat_normalize(quaternion)
        elif rotation is not _ZERO3 and any(rotation):
            self.quaternion = quat_from_euler(rotation)
        if scale is not _ONE3:
            self.scale = scale

    @classmethod
    def batch(  # type: ignore[override]
        cls,
        n: int | None = None,
        *,
        translations: ArrayLike | None = None,
        rotations: ArrayLike | None = None,
        scales: ArrayLike | None = None,
        quaternions: ArrayLike | None = None,
    ) -> ColumnBatch:
        """Transforms of ``n`` new entities for :meth:`Scene.create_entities`, without one object per entity.

        Each argument is one value for all (shape (3,), (4,) for quaternions, or a number for a uniform scale)
        or one row per entity: ``translations`` (n, 3); ``rotations`` Euler degrees (n, 3) or ``quaternions``
        (n, 4) (normalised; not both); ``scales`` (n, 3), or (n,) uniform. ``n`` may be left out when an
        argument has rows.
        """
        if rotations is not None and quaternions is not None:
            raise ValueError("TransformComponent.batch: give rotations (Euler degrees) or quaternions, not both")
        values: dict[str, np.ndarray] = {}
        if translations is not None:
            values["translation"] = translations
        if quaternions is not None:
            try:
                values["quaternion"] = quat_normalize(quaternions)
            except ValueError as exc:
                raise ValueError(f"TransformComponent.batch: quaternions: {exc}") from None
        elif rotations is not None:
            try:
                values["quaternion"] = quat_from_euler(rotations)
            except ValueError as exc:
                raise ValueError(f"TransformComponent.batch: rotations: {exc}") from None
        if scales is not None:
            arr = np.asarray(scales, dtype=np.float64)
            if arr.ndim == 0 or (arr.ndim == 1 and arr.shape != (3,)):  # uniform: one number, or one per entity
                arr = np.repeat(arr[..., None], 3, axis=-1)
            values["scale"] = arr
        return ColumnBatch(cls, n, values)

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
