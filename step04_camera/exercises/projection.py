"""Exercise: the two matrices of a camera.

1. ``perspective``: the projection matrix (camera space -> clip space) for a given NDC depth range.
2. ``look_at``: the view matrix (world space -> camera space) of a camera at ``eye`` looking at ``target``.

Conventions: right-handed, +Y up, the camera looks down its -Z axis; 4x4 float64 numpy arrays acting on
column vectors (p_clip = P @ V @ p_world).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike


def perspective(
    fovy_deg: float, aspect: float, near: float, far: float, depth_range: str | tuple[float, float] = "opengl"
) -> np.ndarray:
    """Perspective projection with vertical field of view ``fovy_deg`` (degrees) and ``aspect`` = width / height.

    ``depth_range`` is "opengl" (z_ndc in [-1, 1]), "webgpu" ([0, 1]) or a (lo, hi) tuple;
    ``gandalf_core.math.depth_range(depth_range)`` turns any of them into (lo, hi). A point at distance
    ``near`` in front of the camera must land on z_ndc = lo after the divide by w, one at ``far`` on hi.

    Raise ValueError whose message names the bad parameter ("fovy_deg", "aspect", "near", "far") when
    fovy_deg is not in (0, 180), aspect <= 0, near <= 0, far <= near, or any value is not finite.

    Hint: row 3 is (0, 0, -1, 0) so that w_clip = distance; row 2 is (0, 0, A, B) with A and B solved from
    the two conditions z_ndc(near) = lo and z_ndc(far) = hi where z_ndc = (A * z + B) / -z.
    """
    raise NotImplementedError("exercise: perspective")


def look_at(eye: ArrayLike, target: ArrayLike, up: ArrayLike = (0.0, 1.0, 0.0)) -> np.ndarray:
    """View matrix of a camera at ``eye`` looking at ``target``, with its top towards ``up``.

    Raise ValueError naming "target" when target == eye and naming "up" when up is zero or parallel to
    the view direction.

    Hint: forward f = normalize(target - eye), right r = normalize(f x up), true up u = r x f. The camera's
    rotation has columns (r, u, -f); the view matrix is its inverse: rows r, u, -f and a translation that
    brings ``eye`` to the origin.
    """
    raise NotImplementedError("exercise: look_at")
