"""What a frame hands a renderer: camera uniforms and instanced draw batches (written once for both APIs).

Per-instance data is the entity's world matrix as three float32 ``vec4`` rows (the affine part; the
last row is always 0 0 0 1): 48 bytes an instance, uploaded in one write per frame. Shaders rebuild
the model matrix from the rows and the normal matrix from cross products of its columns, so the CPU
never inverts a matrix per entity.

The frame uniform block is identical in GLSL (std140) and WGSL, because it holds only mat4/vec4::

    view: mat4, projection: mat4, camera_position: vec4, time: vec4 (x = seconds, y = frame time)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

INSTANCE_FLOATS = 12
FRAME_FLOATS = 16 + 16 + 4 + 4


@dataclass
class DrawBatch:
    """All entities that share a mesh and a material: drawn with one instanced call."""

    mesh: str
    material: str
    rows: np.ndarray  # rows of the TransformComponent store
    first_instance: int = 0

    @property
    def count(self) -> int:
        return len(self.rows)


def pack_frame(view: np.ndarray, projection: np.ndarray, camera_position: np.ndarray, time: float, dt: float) -> bytes:
    """The frame uniform block as bytes (matrices column-major, as both APIs expect)."""
    data = np.zeros(FRAME_FLOATS, dtype=np.float32)
    data[0:16] = view.T.ravel()
    data[16:32] = projection.T.ravel()
    data[32:35] = camera_position
    data[35] = 1.0
    data[36] = time
    data[37] = dt
    return data.tobytes()


def pack_instances(world: np.ndarray, rows: np.ndarray, out: np.ndarray | None = None) -> np.ndarray:
    """Gather the affine rows of ``world[rows]`` into a ``(len(rows), 12)`` float32 array."""
    if out is None or out.shape[0] != len(rows):
        out = np.empty((len(rows), INSTANCE_FLOATS), dtype=np.float32)
    out.reshape(-1, 3, 4)[:] = world[rows, :3, :]
    return out
