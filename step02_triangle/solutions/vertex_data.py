"""Reference solution: interleaved position + colour vertex data and its layout."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from gandalf_core.resources import VertexAttribute, VertexLayout

FLOAT_BYTES = 4


def _rows(name: str, value: ArrayLike, components: int) -> np.ndarray:
    a = np.asarray(value, dtype=np.float64)
    if a.ndim != 2 or a.shape[1] != components:
        raise ValueError(f"{name}: expected shape (N, {components}), got {a.shape}")
    return a


def interleave(positions: ArrayLike, colors: ArrayLike) -> tuple[np.ndarray, VertexLayout]:
    """Interleave (N, 3) positions and (N, 4) colours into float32 (N, 7) plus their layout."""
    p = _rows("positions", positions, 3)
    c = _rows("colors", colors, 4)
    if p.shape[0] != c.shape[0]:
        raise ValueError(f"colors: has {c.shape[0]} rows but positions has {p.shape[0]}")
    data = np.empty((p.shape[0], 7), dtype=np.float32)
    data[:, 0:3] = p
    data[:, 3:7] = c
    layout = VertexLayout(
        attributes=(
            VertexAttribute("position", 0, 3, 0),
            VertexAttribute("color", 4, 4, 3 * FLOAT_BYTES),
        ),
        stride=7 * FLOAT_BYTES,
    )
    return data, layout
