"""The component of step 02: the parameters of a regular polygon that a system turns into a mesh."""

from __future__ import annotations

from gandalf_core import Component


class NGonComponent(Component):
    """A regular polygon with ``sides`` corners on a circle of ``radius`` (model units) around the origin.

    The entity's MeshComponent names the mesh; the NGonSystem builds it under that name.
    """

    def __init__(self, sides: int = 6, radius: float = 0.5) -> None:
        self.sides = sides
        self.radius = radius


