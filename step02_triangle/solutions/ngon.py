"""Reference solution: the regular n-gon as an indexed, counter-clockwise triangle fan, and its system."""

from __future__ import annotations

import colorsys
import math

import numpy as np

from gandalf_core import System
from gandalf_core.components import MeshComponent
from gandalf_core.resources import MeshData

from ..components import NGonComponent


def ngon_mesh(sides: int, radius: float) -> MeshData:
    """A regular ``sides``-gon of circumradius ``radius`` in the z = 0 plane, as an indexed triangle fan."""
    if isinstance(sides, bool) or not isinstance(sides, (int, np.integer)) or sides < 3:
        raise ValueError(f"sides: a polygon needs an integer >= 3 corners, got {sides!r}")
    if isinstance(radius, bool) or not isinstance(radius, (int, float, np.number)) or not (
        math.isfinite(radius) and radius > 0
    ):
        raise ValueError(f"radius: must be a positive finite number, got {radius!r}")
    n = int(sides)
    angles = 2.0 * np.pi * np.arange(n) / n
    corners = float(radius) * np.column_stack([np.cos(angles), np.sin(angles), np.zeros(n)])
    positions = np.vstack([np.zeros((1, 3)), corners])
    # White in the middle, the corners around the colour wheel (sRGB, like every colour).
    rim = [(*colorsys.hsv_to_rgb(k / n, 0.8, 1.0), 1.0) for k in range(n)]
    colors = np.vstack([np.ones((1, 4)), rim])
    k = np.arange(n)
    # Centre 0, corner k is vertex k + 1. Angles grow counter-clockwise, so (0, k, k + 1) winds CCW from +Z.
    indices = np.column_stack([np.zeros(n, dtype=np.int64), k + 1, (k + 1) % n + 1])
    return MeshData(positions=positions, colors=colors, indices=indices, name=f"ngon{n}")


class NGonSystem(System):
    """Registers each n-gon entity's mesh in the scene's assets, under its MeshComponent's name."""

    def __init__(self) -> None:
        super().__init__([NGonComponent, MeshComponent])

    def on_create_entity(self, entity, components) -> None:
        ngon, mesh = components
        self.scene.assets.mesh(mesh.mesh, ngon_mesh(ngon.sides, ngon.radius))
