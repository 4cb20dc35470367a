"""Reference solution: perspective projection for any depth range, and the look-at view matrix."""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike

from gandalf_core.math import depth_range as resolve_depth_range


def _check(ok: bool, name: str, rule: str, value: object) -> None:
    if not ok:
        raise ValueError(f"{name} must {rule}, got {value!r}")


def perspective(
    fovy_deg: float, aspect: float, near: float, far: float, depth_range: str | tuple[float, float] = "opengl"
) -> np.ndarray:
    """Perspective projection mapping distance ``near`` to the range's lo end and ``far`` to its hi end."""
    _check(math.isfinite(fovy_deg) and 0.0 < fovy_deg < 180.0, "fovy_deg", "lie in (0, 180)", fovy_deg)
    _check(math.isfinite(aspect) and aspect > 0.0, "aspect", "be finite and > 0", aspect)
    _check(math.isfinite(near) and near > 0.0, "near", "be finite and > 0", near)
    _check(math.isfinite(far) and far > near, "far", f"be finite and greater than near ({near!r})", far)
    lo, hi = resolve_depth_range(depth_range)
    focal = 1.0 / math.tan(math.radians(fovy_deg) / 2.0)
    # z_ndc = (A z + B) / -z. With z = -near -> lo and z = -far -> hi:
    #   A = -(hi * far - lo * near) / (far - near),  B = -(hi - lo) * far * near / (far - near).
    a = -(hi * far - lo * near) / (far - near)
    b = -(hi - lo) * far * near / (far - near)
    return np.array(
        [
            [focal / aspect, 0.0, 0.0, 0.0],
            [0.0, focal, 0.0, 0.0],
            [0.0, 0.0, a, b],
            [0.0, 0.0, -1.0, 0.0],
        ]
    )


def look_at(eye: ArrayLike, target: ArrayLike, up: ArrayLike = (0.0, 1.0, 0.0)) -> np.ndarray:
    """View matrix (world -> camera) of a camera at ``eye`` looking at ``target``."""
    e = np.asarray(eye, dtype=np.float64)
    d = np.asarray(target, dtype=np.float64) - e
    u = np.asarray(up, dtype=np.float64)
    length = np.linalg.norm(d)
    _check(length > 0.0, "target", "differ from eye", tuple(e))
    _check(np.linalg.norm(u) > 0.0, "up", "be a non-zero vector", tuple(u))
    forward = d / length
    right = np.cross(forward, u / np.linalg.norm(u))
    # |f x up| = sin(angle between them): near zero, "right" would be noise.
    _check(np.linalg.norm(right) > 1e-6, "up", "not be parallel to the view direction", tuple(u))
    right /= np.linalg.norm(right)
    true_up = np.cross(right, forward)
    view = np.eye(4)
    view[0, :3], view[1, :3], view[2, :3] = right, true_up, -forward
    view[:3, 3] = -view[:3, :3] @ e
    return view
