"""GPU-driven motion, the part both backends share: what the system hands the renderer for entities whose motion
the GPU evaluates, and the per-instance rows the compute pass reads.

The :class:`~.system.GpuSpinSystem` leaves its entities' Transforms at the pose they had when they joined (so the
CPU neither recomputes nor uploads them: they are static there) and hands the render system, through its
``instance_pass`` hook, a pass over the instance rows: per entity a world axis, a speed (rad/s) and the time it
joined (:class:`GpuMotion`), turned into :data:`MOTION_FLOATS` float32 per instance, in instance order. Each frame
the renderer runs one compute pass (``shaders/motion_spin.comp`` / ``.wgsl``, :mod:`.motion_gl` /
:mod:`.motion_wgpu`) that turns every instance's rows by ``R(axis, speed · t + phase)``; the draws read the
result. An instance with speed 0 and phase 0 is copied.

**Time in float32.** The kernel gets ``t`` = seconds since an *epoch* (:data:`MOTION_EPOCH` wide), and every
instance a phase ``speed · (epoch − joined)`` wrapped to [0, 2π) in float64. So the angle it forms,
``speed · t + phase``, has ``t < 1024`` s whatever the run time: its float32 error stays under
``|speed| · 1024 · 2⁻²⁴ ≈ 6e-5 · |speed|`` rad plus a few ulp of 2π. When the clock passes the epoch's end the
system starts a new epoch and writes the phases again (once every 17 minutes, O(N) then).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from gandalf_core.resources.layout import BlockLayout

#: float32 per instance in the motion buffer: (axis x, y, z, speed rad/s), (phase rad, 0, 0, 0).
MOTION_FLOATS = 8
#: Seconds an epoch lasts (as the frame block's ``time.x`` wrap): float32 steps 1.2e-4 s at its end.
MOTION_EPOCH = 1024.0
#: The kernel's workgroup size (``local_size_x`` / ``@workgroup_size``).
WORKGROUP = 64
#: The kernel's file stem in this technique's ``shaders`` (``.comp`` for GLSL 4.30, ``.wgsl``).
KERNEL = "motion_spin"
#: Where the kernels lie.
SHADER_DIR = Path(__file__).resolve().parent / "shaders"
#: The kernel's uniform block, declared once: the time since the epoch and the number of instances.
PARAMS_LAYOUT = BlockLayout("MotionParams", [("time", "float"), ("count", "uint")])
#: Its GL binding point (0 and 1 are the engine's Frame and Lights); WGSL: @group(0) @binding(0).
PARAMS_BINDING = 4
#: The block as the kernels include it (``#include "motion_params.glsl"`` / ``"motion_params.wgsl"``).
PARAMS_INCLUDES = {
    "motion_params.glsl": PARAMS_LAYOUT.glsl(None, {"time": "u_time", "count": "u_count"}, binding=PARAMS_BINDING),
    "motion_params.wgsl": PARAMS_LAYOUT.wgsl("params", 0, 0),
}


@dataclass
class GpuMotion:
    """Per-entity spins a system asks the GPU to evaluate: transform ``rows`` and, per row, ``axes`` (world,
    unit), ``speeds`` (rad/s) and ``joined`` (app seconds when the Transform's pose was the entity's)."""

    rows: np.ndarray
    axes: np.ndarray
    speeds: np.ndarray
    joined: np.ndarray


@dataclass
class MotionFrame:
    """What a frame's motion pass reads: the motion rows (instance order), their version (uploaded again only when
    it changes) and the kernel's time since the epoch."""

    rows: np.ndarray  # (instances, MOTION_FLOATS) float32
    version: tuple[object, int]
    time: float


def motion_rows(count: int, instance_of_row: np.ndarray, motions: list[GpuMotion], epoch: float) -> np.ndarray:
    """The motion buffer's rows for ``count`` instances (``instance_of_row``: transform row -> instance, -1 when not
    drawn): zeros (no motion) except where a motion names a drawn row. Phases in float64, wrapped to one turn."""
    out = np.zeros((count, MOTION_FLOATS), dtype=np.float32)
    for motion in motions:
        known = np.flatnonzero(motion.rows < len(instance_of_row))
        at = instance_of_row[motion.rows[known]]
        known, at = known[at >= 0], at[at >= 0]
        out[at, 0:3] = motion.axes[known]
        out[at, 3] = motion.speeds[known]
        out[at, 4] = np.mod(motion.speeds[known] * (epoch - motion.joined[known]), 2.0 * math.pi)
    return out


def epoch_of(time: float) -> float:
    """The start of the epoch ``time`` falls in (a whole number of :data:`MOTION_EPOCH`)."""
    return math.floor(time / MOTION_EPOCH) * MOTION_EPOCH


def spin_rows_np(rows: np.ndarray, axes: np.ndarray, angles: np.ndarray) -> np.ndarray:
    """The kernel in float64: instance ``rows`` (n, 12) turned about ``axes`` (n, 3) by ``angles`` (n,) — the
    reference the tests compare the GPU's result with."""
    m = np.asarray(rows, np.float64).reshape(-1, 3, 4)
    a = np.asarray(axes, np.float64)
    c, s = np.cos(angles), np.sin(angles)
    k = 1.0 - c
    x, y, z = a[:, 0], a[:, 1], a[:, 2]
    r = np.empty((len(m), 3, 3))
    r[:, 0] = np.stack([c + k * x * x, k * x * y - s * z, k * x * z + s * y], 1)
    r[:, 1] = np.stack([k * y * x + s * z, c + k * y * y, k * y * z - s * x], 1)
    r[:, 2] = np.stack([k * z * x - s * y, k * z * y + s * x, c + k * z * z], 1)
    out = m.copy()
    out[:, :, :3] = r @ m[:, :, :3]
    return out.reshape(-1, 12)
