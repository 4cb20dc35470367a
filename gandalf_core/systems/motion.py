"""What a system hands the render system for entities whose motion the GPU evaluates (``SpinSystem(path="gpu")``):
their transform rows and, per row, a world axis, a speed and the time their Transform's pose was theirs. The
render system (``render/gpu_motion.py``) turns it into the compute pass's per-instance rows."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass
class GpuMotion:
    """Per-entity spins a system asks the GPU to evaluate: transform ``rows`` and, per row, ``axes`` (world,
    unit), ``speeds`` (rad/s) and ``joined`` (app seconds when the Transform's pose was the entity's)."""

    rows: np.ndarray
    axes: np.ndarray
    speeds: np.ndarray
    joined: np.ndarray
