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
from .fields import FieldError, Vector, as_floats

_ZERO3 = (0.0, 0.0, 0.0)
_ONE3 = (1.0, 1.0, 1.0)
_ROTATION = "3 finite numbers (Euler degrees about X, then Y, then Z)"


class TransformComponent(ColumnarComponent):
    """Local TRS relative to the parent (or the world for roots); ``world`` is written by the transform system.

    ``rotation`` takes Euler degrees (X, then Y, then Z) for convenience; the state is ``quaternion``
    (w, x, y, z). Every field is checked whenever it is set (a :class:`~gandalf_core.components.fields.FieldError`
    names the field): ``translation`` 3 finite numbers; ``quaternion`` 4 finite numbers scaled to unit length
    (all zero reads as no rotation); ``scale`` 3 finite numbers or one for all three (0 and negative scales are
    allowed: a collapsed or mirrored object); ``world`` a 4x4 matrix of finite numbers.
    """

    translation = Vector(3, 0.0, expected="x, y, z")
    quaternion = Vector(4, (1.0, 0.0, 0.0, 0.0), unit=True,
                        expected="w, x, y, z; scaled to unit length, all zero reads as no rotation")
    scale = Vector(3, 1.0, uniform=True, expected="x, y, z, or one number for all three")
    world = Vector((4, 4), np.eye(4), expected="a 4x4 matrix")
    #: The transform system computes ``world`` from the others: reading it marks nothing as changed.
    derived = frozenset({"world"})

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
            if rotation is not _ZERO3:
                raise FieldError("TransformComponent: give rotation (Euler degrees) or quaternion, not both; got "
                                 f"rotation={rotation!r}, quaternion={quaternion!r}")
            self.quaternion = quaternion  # checked (a bad one names the field) and scaled to unit length
        elif rotation is not _ZERO3 and not ((type(rotation) is tuple or type(rotation) is list)
                                             and tuple(rotation) == _ZERO3):
            self.rotation = rotation
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
            arr = np.asarray(scales) if not isinstance(scales, (str, bytes)) else np.asarray(None)
            if arr.dtype.kind not in "iuf":
                raise ValueError(f"TransformComponent.batch: scales must be numbers: (n, 3), (n,) uniform, (3,) or one "
                                 f"number for all, got {scales!r:.80}")
            arr = arr.astype(np.float64, copy=False)
            if arr.ndim == 0 or (arr.ndim == 1 and arr.shape != (3,)):  # uniform: one number, or one per entity
                arr = np.repeat(arr[..., None], 3, axis=-1)
            values["scale"] = arr
        return ColumnBatch(cls, n, values)

    @property
    def rotation(self) -> np.ndarray:
        """The rotation as Euler degrees (X, Y, Z); assigning sets the quaternion. An all-zero quaternion reads as
        no rotation (0, 0, 0), as everywhere else."""
        q = self.quaternion
        if not np.any(q):
            return np.zeros(3)
        return quat_to_euler(q)

    @rotation.setter
    def rotation(self, degrees: Sequence[float]) -> None:
        angles = as_floats(degrees, (3,))
        if angles is None:
            raise FieldError(f"TransformComponent.rotation must be {_ROTATION}, got {degrees!r}")
        self.quaternion = quat_from_euler(angles)

    @property
    def world_position(self) -> np.ndarray:
        return np.array(self.world[:3, 3])
