"""The spin's GPU path: :class:`GpuSpinSystem` turns its entities in a compute pass, with no work on the CPU per
frame, and hands the render system that pass through the engine's hook (a system's ``instance_pass``).

Its entities' Transforms keep the pose they joined with (static for the CPU: never recomputed or uploaded again),
and every frame the renderer runs the pass (:class:`MotionPass`) that turns their instance rows by
``speed · (t − joined)`` about the world axis (a local axis is turned into the world's once:
``R0 · R(a, θ) = R(R0 a, θ) · R0``). Only for root entities without children (a child would not follow).
"""

from __future__ import annotations

import uuid
from dataclasses import dataclass
from typing import Any

import numpy as np

from gandalf_core.components import TransformComponent
from gandalf_core.ecs import LinkComponent
from gandalf_core.math import quat_rotate
from gandalf_core.systems.spin import SpinComponent, SpinSystem

from .motion import KERNEL, GpuMotion, MotionFrame, epoch_of, motion_rows


class GpuSpinSystem(SpinSystem):
    """Turns each ``SpinComponent``'s entity as :class:`~gandalf_core.systems.spin.SpinSystem` does, on the GPU
    (``path`` reads ``"gpu"``); see the module's docstring."""

    def __init__(self) -> None:
        super().__init__()
        self.path = "gpu"
        self._joined: dict[uuid.UUID, float] = {}  # app seconds when each entity's pose was its own
        self._motion: GpuMotion | None = None
        # The motion rows of the scene's GPU spins (made by the system the render system asks), and what from.
        self._motion_key: tuple | None = None
        self._motion_rows: np.ndarray | None = None
        self._motion_serial = 0

    # --8<-- [start:update]
    def on_update_system(self, ts: float) -> None:
        if self._plan_key != self._current_key():  # only new members cost anything, once
            now = (self.scene.app.clock.time if self.scene.app is not None else ts) - ts  # this frame's start
            joined = self._joined
            self._joined = {e: joined.get(e, now) for e in self.entities}
            self._motion = None
            self._plan_key = self._current_key()
    # --8<-- [end:update]

    @property
    def motion_version(self) -> tuple[int, int] | None:
        """Changes whenever :meth:`gpu_motion` would give something new."""
        return self._plan_key

    def gpu_motion(self) -> GpuMotion:
        """The entities the compute pass moves: their rows, world axes, speeds (rad/s) and join times."""
        if self._motion is None or self._plan_key != self._current_key():
            if self._plan_key != self._current_key():
                self.on_update_system(0.0)
            self._motion = self._build_motion()
        return self._motion

    # --8<-- [start:gpu_motion]
    def _build_motion(self) -> GpuMotion:
        scene = self.scene
        store = scene.store(TransformComponent)
        if scene.hierarchy_version:  # children would not follow a turn made on the GPU
            for entity in self.entities:
                link = scene.try_component(entity, LinkComponent)
                if link is not None and (link.parent is not None or link.children):
                    raise ValueError(f"{scene.describe(entity)}: GpuSpinSystem turns root entities without "
                                     "children only (the GPU turns its instance alone); use SpinSystem(path='batch')")
        spins = self.column(SpinComponent)
        rows = store.rows_of(self.column(TransformComponent))
        axes = np.array([s.axis for s in spins], dtype=np.float64).reshape(-1, 3)
        local = np.array([s.local for s in spins], dtype=bool)
        if local.any():  # R0 R(a, θ) = R(R0 a, θ) R0: a local axis is the world axis R0 a
            axes[local] = quat_rotate(store.columns["quaternion"][rows[local]], axes[local])
        return GpuMotion(rows=rows, axes=axes, speeds=np.radians([s.speed for s in spins]),
                         joined=np.array([self._joined.get(e, 0.0) for e in self.entities], dtype=np.float64))
    # --8<-- [end:gpu_motion]

    # --8<-- [start:instance_pass]
    def instance_pass(self, render_system: Any, time: float) -> MotionPass:
        """The engine's hook: this frame's compute pass over the instance rows, for every enabled GPU spin of the
        scene (the render system asks the first). Its motion rows are made again only when those systems, the
        instance order or the motion epoch change."""
        systems = [s for s in self.scene.systems if isinstance(s, GpuSpinSystem) and s.enabled]
        instance_of_row, count, order = render_system.instance_order()
        epoch = epoch_of(time)
        key = (order, epoch, tuple((id(s), s.motion_version) for s in systems))
        if key != self._motion_key or self._motion_rows is None or len(self._motion_rows) != count:
            motions = [s.gpu_motion() for s in systems]
            self._motion_rows = motion_rows(count, instance_of_row, motions, epoch)
            self._motion_key = (order, epoch, tuple((id(s), s.motion_version) for s in systems))
            self._motion_serial += 1
        return MotionPass(MotionFrame(self._motion_rows, (self, self._motion_serial), time - epoch))
    # --8<-- [end:instance_pass]


@dataclass
class MotionPass:
    """A frame's motion pass as the renderer runs it: :meth:`run` in OpenGL, :meth:`record` in WebGPU. The kernel's
    GPU objects are built on the first call and kept with the renderer (``renderer.attachments``, released with
    it)."""

    frame: MotionFrame

    def run(self, renderer: Any, instances: Any, count: int) -> Any:
        """OpenGL: move ``count`` rows of ``instances`` now; the buffer the draws read them from."""
        from .motion_gl import GLMotionPass

        return _attached(renderer, GLMotionPass, renderer.ctx).run(instances, count, self.frame)

    def record(self, renderer: Any, encoder: Any, instances: Any, count: int) -> Any:
        """WebGPU: record the pass into the frame's ``encoder``; the buffer the draws read the rows from."""
        from .motion_wgpu import WGPUMotionPass

        return _attached(renderer, WGPUMotionPass, renderer.device).record(encoder, instances, count, self.frame)


def _attached(renderer: Any, kind: type, context: Any) -> Any:
    """The renderer's motion pass (a ``kind`` on ``context``), built on first use and kept with the renderer."""
    found = renderer.attachments.get(KERNEL)
    if found is None:
        found = renderer.attachments[KERNEL] = kind(context, renderer.stats)
    return found
