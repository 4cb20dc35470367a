"""Exercise: a regular n-gon as an indexed triangle fan, and the system that builds it.

1. ``ngon_mesh(sides, radius)``: the mesh of a regular polygon in the z = 0 plane.
2. ``NGonSystem``: when an entity with an NGonComponent and a MeshComponent appears, register
   ``ngon_mesh(sides, radius)`` in the scene's assets under the MeshComponent's mesh name.
"""

from __future__ import annotations

from gandalf_core import System
from gandalf_core.components import MeshComponent
from gandalf_core.resources import MeshData

from ..components import NGonComponent


def ngon_mesh(sides: int, radius: float) -> MeshData:
    """A regular polygon with ``sides`` corners on a circle of ``radius`` around the origin, in the z = 0 plane.

    Build it as a triangle *fan*: one centre vertex plus one vertex per corner, and ``sides`` triangles
    (centre, corner k, corner k + 1), the last one closing back to corner 0. Give it an index buffer, and
    wind every triangle **counter-clockwise** seen from +Z (back-face culling drops the others). Give every
    vertex a colour (RGBA, alpha 1), e.g. a white centre and the corners around the colour wheel.
    Raise ValueError naming ``sides`` unless it is an integer >= 3, and naming ``radius`` unless it is a
    positive finite number.

    Hint: corner k is at angle ``2π k / sides``; ``MeshData(positions=..., colors=..., indices=...)``.
    """
    raise NotImplementedError("exercise: ngon_mesh")


class NGonSystem(System):
    """Runs over entities with an NGonComponent and a MeshComponent."""

    def __init__(self) -> None:
        super().__init__([NGonComponent, MeshComponent])

    def on_create_entity(self, entity, components) -> None:
        ngon, mesh = components
        raise NotImplementedError("exercise: NGonSystem.on_create_entity")
