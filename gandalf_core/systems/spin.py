"""A constant spin: the course's one spin component and system (step 03's textured cube, step 05's planets with
``local=True``, step 07's demos all use it).

``SpinSystem`` turns each ``SpinComponent``'s entity by ``speed * ts`` degrees a frame. It says which path it
takes (``path``):

* ``"entity"`` (the default, the teaching form): ``on_update_entity`` once per entity;
* ``"batch"``: one vectorised quaternion product over the rows of all its entities, the rows named to the store
  (only they are recomputed and uploaded).

A third path, on the GPU (a compute pass turns the instance rows, no work on the CPU per frame), is step 07's
GPU-driven motion technique: ``step07_advanced.gpu_motion.system.GpuSpinSystem``, through the render system's
``instance_pass`` hook.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from ..components import TransformComponent
from ..ecs import Component, System
from ..math import quat_from_axis_angle, quat_mul, quat_normalize

#: The paths a SpinSystem can take.
PATHS = ("entity", "batch")


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
    """Turns each entity by ``speed * ts`` degrees about its spin axis: the world's, or with ``local`` its own.
    ``path`` says where: ``"entity"`` (per entity) or ``"batch"`` (vectorised)."""

    def __init__(self, path: str = "entity") -> None:
        super().__init__([SpinComponent, TransformComponent])
        if path not in PATHS:
            raise ValueError(f"SpinSystem: path must be one of {', '.join(PATHS)}, got {path!r}")
        self.path = path
        self._plan_key: tuple[int, int] | None = None

    # --8<-- [start:paths]
    def on_update_system(self, ts: float) -> None:
        if self.path == "entity":
            super().on_update_system(ts)
        else:
            self._update_batch(ts)
    # --8<-- [end:paths]

    def on_update_entity(self, ts, entity, components) -> None:
        spin, transform = components
        step = quat_from_axis_angle(spin.axis, math.radians(spin.speed * ts))
        # On the left the turn is about the *world* axis, whatever the entity's orientation; on the right it is
        # applied first, in the entity's own frame. Normalising keeps a long spin free of rounding drift.
        if spin.local:
            transform.quaternion = quat_normalize(quat_mul(transform.quaternion, step))
        else:
            transform.quaternion = quat_normalize(quat_mul(step, transform.quaternion))

    # --- batch -------------------------------------------------------------------------------------
    def _update_batch(self, ts: float) -> None:
        if self._plan_key != self._current_key():
            self._plan_batch()
        if not len(self._rows):
            return
        store = self.scene.store(TransformComponent)
        half = (0.5 * ts) * self._speeds
        step = self._step
        np.cos(half, out=step[:, 0])
        np.multiply(np.sin(half)[:, None], self._axes, out=step[:, 1:])
        q = store.columns["quaternion"]
        rows = self._target
        turned = quat_mul(step, q[rows])
        if self._local.any():
            turned[self._local] = quat_mul(q[self._rows[self._local]], step[self._local])
        # One Newton step towards unit length, |q|² = 1 + e -> 1 + O(e²): no drift over a long spin, at the cost
        # of one dot product (a full normalisation checks and divides).
        turned *= (1.5 - 0.5 * np.einsum("ij,ij->i", turned, turned))[:, None]
        q[rows] = turned
        store.touch(rows)

    def _plan_batch(self) -> None:
        store = self.scene.store(TransformComponent)
        spins = self.column(SpinComponent)
        self._rows = store.rows_of(self.column(TransformComponent))
        order = np.argsort(self._rows, kind="stable")
        self._rows = self._rows[order]  # rows in store order: consecutive ones are read as a slice, no gathering
        spins = [spins[i] for i in order]
        rows = self._rows
        consecutive = len(rows) and rows[-1] - rows[0] == len(rows) - 1
        self._target = slice(int(rows[0]), int(rows[-1]) + 1) if consecutive else rows
        self._axes = np.array([s.axis for s in spins], dtype=np.float64).reshape(-1, 3)
        self._speeds = np.radians([s.speed for s in spins])
        self._local = np.array([s.local for s in spins], dtype=bool)
        self._step = np.empty((len(spins), 4))
        self._plan_key = self._current_key()

    def _current_key(self) -> tuple[int, int]:
        return (self.version, self.scene.store(TransformComponent).layout_version)
