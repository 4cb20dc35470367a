"""Perspective and orthographic projection matrices with an explicit NDC depth range.

OpenGL clips depth to z_ndc in [-1, 1], WebGPU to [0, 1]; the projection says which, so one camera gives the
same picture in both APIs. Reverse-Z swaps the ends (near -> hi, far -> lo): with a [0, 1] float depth buffer
it spreads precision evenly over huge depth ranges, and it allows an infinite far plane.
Cameras look down -Z in eye space; matrices are float64, row-major, acting on column vectors.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np


class DepthRange(NamedTuple):
    """The NDC depth interval [lo, hi] that clipping keeps; near maps to lo (to hi with reverse-Z)."""

    lo: float
    hi: float


_NAMED_RANGES = {"opengl": DepthRange(-1.0, 1.0), "webgpu": DepthRange(0.0, 1.0)}
#: What a ``depth_range`` argument may be: a name of :data:`_NAMED_RANGES` or a (lo, hi) pair.
DepthRangeLike = str | tuple[float, float]


def depth_range(value: DepthRangeLike) -> DepthRange:
    """Resolve "opengl" ([-1, 1]), "webgpu" ([0, 1]) or a (lo, hi) tuple with lo < hi to a DepthRange."""
    if isinstance(value, str):
        try:
            return _NAMED_RANGES[value.lower()]
        except KeyError:
            raise ValueError(
                f"depth_range must be one of {sorted(_NAMED_RANGES)} or a (lo, hi) tuple, got {value!r}"
            ) from None
    try:
        lo, hi = (float(v) for v in value)
    except (TypeError, ValueError):
        raise ValueError(f"depth_range must be a name or a (lo, hi) pair of numbers, got {value!r}") from None
    if not (math.isfinite(lo) and math.isfinite(hi) and lo < hi):
        raise ValueError(f"depth_range needs finite lo < hi, got {value!r}")
    return DepthRange(lo, hi)


def perspective(fovy_degrees: float, aspect: float, near: float, far: float, depth_range: DepthRangeLike = "opengl",
                reverse_z: bool = False) -> np.ndarray:
    """Perspective projection (4x4) with vertical field of view `fovy_degrees` and `aspect` = width / height.

    A point at eye-space distance `near` in front of the camera lands on the depth range's near end, one at
    `far` on its far end. `far` may be `math.inf` (infinite far plane; best paired with `reverse_z`).
    """
    fov_ok = math.isfinite(fovy_degrees) and 0.0 < fovy_degrees < 180.0
    _require(fov_ok, "fovy_degrees", "lie in (0, 180)", fovy_degrees)
    _require(math.isfinite(aspect) and aspect > 0.0, "aspect", "be finite and > 0", aspect)
    _require(math.isfinite(near) and near > 0.0, "near", "be finite and > 0", near)
    _require(far > near, "far", f"be greater than near ({near!r}); math.inf is allowed", far)
    d_near, d_far = _depth_ends(depth_range, reverse_z)
    focal = 1.0 / math.tan(math.radians(fovy_degrees) * 0.5)
    # z_ndc = -a + b / distance must give d_near at `near` and d_far at `far`. Written with r = near / far
    # so that far = inf is the plain limit r = 0, and without the cancellation of (far + near) / (far - near).
    r = near / far
    k = 1.0 / (1.0 - r)
    a = -d_far - (d_far - d_near) * r * k
    b = (d_near - d_far) * near * k
    m = np.zeros((4, 4))
    m[0, 0] = focal / aspect
    m[1, 1] = focal
    m[2, 2] = a
    m[2, 3] = b
    m[3, 2] = -1.0
    _require_finite(m, f"fovy_degrees={fovy_degrees!r}, aspect={aspect!r}, near={near!r}, far={far!r}")
    return m


def orthographic(left: float, right: float, bottom: float, top: float, near: float, far: float,
                 depth_range: DepthRangeLike = "opengl", reverse_z: bool = False) -> np.ndarray:
    """Orthographic projection (4x4) of the eye-space box [left, right] x [bottom, top] x [-far, -near]."""
    bounds = {"left": left, "right": right, "bottom": bottom, "top": top, "near": near, "far": far}
    for name, value in bounds.items():
        _require(math.isfinite(value), name, "be finite", value)
    _require(right != left, "right", f"differ from left ({left!r})", right)
    _require(top != bottom, "top", f"differ from bottom ({bottom!r})", top)
    _require(far != near, "far", f"differ from near ({near!r})", far)
    d_near, d_far = _depth_ends(depth_range, reverse_z)
    m = np.zeros((4, 4))
    m[0, 0] = 2.0 / (right - left)
    m[0, 3] = -(right + left) / (right - left)
    m[1, 1] = 2.0 / (top - bottom)
    m[1, 3] = -(top + bottom) / (top - bottom)
    # z_ndc = a * z_eye + b with z_eye = -near -> d_near and z_eye = -far -> d_far.
    m[2, 2] = (d_near - d_far) / (far - near)
    m[2, 3] = (d_near * far - d_far * near) / (far - near)
    m[3, 3] = 1.0
    _require_finite(m, ", ".join(f"{k}={v!r}" for k, v in bounds.items()))
    return m


def _depth_ends(value: DepthRangeLike, reverse_z: bool) -> tuple[float, float]:
    """NDC depth of the near and the far plane for this range and direction."""
    lo, hi = depth_range(value)
    return (hi, lo) if reverse_z else (lo, hi)


def _require(ok: bool, name: str, rule: str, value: float) -> None:
    """Raise a ValueError naming the camera parameter `name` unless `ok`."""
    if not ok:
        raise ValueError(f"{name} must {rule}, got {value!r}")


def _require_finite(m: np.ndarray, given: str) -> None:
    """Extreme but valid inputs (a field of view of 1e-310 degrees, an aspect of 1e-320) can overflow: refuse a
    projection that is not finite rather than hand the GPU infinities."""
    if not np.isfinite(m).all():
        raise ValueError(f"the projection is not finite for {given}: the values are too extreme to represent")
