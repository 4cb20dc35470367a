"""Reference solution: UVs for a box that map its faces into the cross-shaped atlas."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from ..atlas import CROSS_CELLS, CROSS_GRID, FACE_FRAMES


def _rows(name: str, value: ArrayLike) -> np.ndarray:
    a = np.asarray(value, dtype=np.float64)
    if a.ndim != 2 or a.shape[1] != 3 or a.shape[0] == 0:
        raise ValueError(f"cube_cross_uvs: {name} must have shape (N, 3) with N > 0, got {a.shape}")
    if not np.all(np.isfinite(a)):
        raise ValueError(f"cube_cross_uvs: {name} contains NaN or Inf")
    return a


def cube_cross_uvs(positions: ArrayLike, normals: ArrayLike) -> np.ndarray:
    """UVs (N, 2) placing each face of an axis-aligned box in its square of the cross atlas."""
    p, n = _rows("positions", positions), _rows("normals", normals)
    if p.shape != n.shape:
        raise ValueError(f"cube_cross_uvs: positions {p.shape} and normals {n.shape} differ in length")
    lo, hi = p.min(axis=0), p.max(axis=0)
    size = hi - lo
    if np.any(size <= 0.0):
        raise ValueError(f"cube_cross_uvs: the positions span no volume (box size {size.tolist()})")
    if np.any(np.abs(n).max(axis=1) <= 0.0):
        raise ValueError("cube_cross_uvs: a normal is zero, so its face is unknown")
    centred = (p - (lo + hi) / 2.0) / size  # in [-0.5, 0.5] on every axis
    axis = np.argmax(np.abs(n), axis=1)
    positive = n[np.arange(len(n)), axis] > 0.0
    uv = np.empty((len(p), 2))
    cols, rows = CROSS_GRID
    for face, (normal, right, up) in FACE_FRAMES.items():
        k = int(np.flatnonzero(normal)[0])
        mask = (axis == k) & (positive == (normal[k] > 0))
        s = 0.5 + centred[mask] @ np.array(right, float)  # 0 at the face's left edge, 1 at its right
        t = 0.5 - centred[mask] @ np.array(up, float)  # 0 at its top edge (v grows down the image)
        col, row = CROSS_CELLS[face]
        uv[mask] = np.stack([(col + s) / cols, (row + t) / rows], axis=1)
    return uv
