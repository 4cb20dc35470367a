"""Step 03 reference solutions (same API as ``exercises``)."""

from .bricks import brick_texture
from .uvs import cube_cross_uvs

__all__ = ["brick_texture", "cube_cross_uvs"]
