"""Exercise: texture coordinates that wrap one image, a cross-shaped atlas, around a box.

The atlas (see :mod:`step03_textures.atlas`) is a 4 x 3 grid; ``CROSS_CELLS[face]`` is the (column, row) of a
face's square, with row 0 at the top of the image (v = 0). ``FACE_FRAMES[face]`` gives the face's outward
normal and, seen from outside, the directions of image right (+u) and image up (-v).

``cube_cross_uvs(positions, normals)`` returns an (N, 2) float array with one (u, v) per vertex:

1. the box is the axis-aligned bounding box of ``positions`` (any size, anywhere, not only a unit cube);
2. a vertex belongs to the face whose normal axis is the largest component (by absolute value) of its normal,
   on the side of that component's sign;
3. inside its face the vertex has ``s`` in [0, 1] from the face's left edge to its right edge (along
   ``right``) and ``t`` in [0, 1] from its top edge to its bottom edge (against ``up``);
4. ``(u, v) = ((column + s) / 4, (row + t) / 3)``.

For ``primitives.cube()`` the per-face (s, t) are exactly the mesh's own UVs, so the whole image lands on
every face; with your UVs each face shows only its own square. Raise ValueError for arrays that are not
(N, 3) with N > 0, different lengths, NaN/Inf, a zero normal, or positions that span no volume.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike


def cube_cross_uvs(positions: ArrayLike, normals: ArrayLike) -> np.ndarray:
    """UVs (N, 2) placing each face of an axis-aligned box in its square of the cross atlas."""
    raise NotImplementedError("exercise: cube_cross_uvs")
