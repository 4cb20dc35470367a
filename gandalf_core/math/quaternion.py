"""Unit quaternions for rotations, stored as float64 numpy arrays in (w, x, y, z) order.

Conventions: right-handed axes, column vectors, angles in radians except the Euler helpers, which speak
degrees and build R = Rz @ Ry @ Rx (rotate about X first, then Y, then Z). Functions that say so accept
batches: arrays of shape (N, 4) (or (N, 3) for vectors and Euler angles), computed without Python loops.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike

# Below this |cos(pitch)| the Euler decomposition treats the pitch as exactly +-90 degrees. sqrt(machine
# epsilon) balances the two errors: ignoring a tiny cos(pitch) versus dividing rounding noise by it.
_GIMBAL_COS = 1.5e-8
# Below this angle between two quaternions slerp and nlerp differ by less than angle**3 ~ 1e-18.
_SLERP_MIN_ANGLE = 1e-6


# Fast paths for ONE quaternion or 3-vector (the per-entity teaching code): when the input is already a float64
# array of the right shape (or a tuple/list of plain numbers), its components are read as Python floats and the
# result is computed with the math module, without numpy's per-call overhead (~1 us instead of ~20 us). Finiteness
# and zero-length checks then cost nothing: NaN and inf propagate into the result, whose length is checked anyway;
# anything unusual (non-finite, zero, huge or tiny lengths) falls back to the general numpy path, which raises the
# documented errors or handles the extremes exactly as before.
_ND = np.ndarray
_F64 = np.dtype(np.float64)
_S4 = (4,)
_NUMBER = (float, int, np.float64)
_FLOAT = (float, np.float64)
_array = np.array
# Between these squared lengths the plain sum of squares neither overflows nor loses precision to underflow.
_SAFE_MIN_SQ = 1e-280
_SAFE_MAX_SQ = 1e280


def _floats(value: object, n: int) -> list[float] | None:
    """``value``'s components as ``n`` Python floats when it is a float64 array of shape (n,) or a tuple/list of
    ``n`` plain numbers; None otherwise (the caller then takes the general path)."""
    t = type(value)
    if t is _ND:
        if value.dtype is _F64 and value.shape == (n,):  # type: ignore[union-attr]
            return value.tolist()  # type: ignore[union-attr]
        return None
    if (t is tuple or t is list) and len(value) == n:  # type: ignore[arg-type]
        for c in value:  # type: ignore[union-attr]
            if type(c) not in _NUMBER:
                return None
        try:
            return [float(c) for c in value]  # type: ignore[union-attr]
        except OverflowError:  # an int beyond float range: the general path says so
            return None
    return None


def _checked(value: ArrayLike, name: str, tail: tuple[int, ...]) -> np.ndarray:
    """Return `value` as a finite float64 array whose trailing shape is `tail` (leading batch axes allowed)."""
    arr = np.asarray(value, dtype=np.float64)
    if arr.shape[arr.ndim - len(tail):] != tail or arr.ndim > len(tail) + 1:
        raise ValueError(f"{name} must have shape {tail} or (N, {', '.join(map(str, tail))}), got {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"{name} must be finite, got {value!r}")
    return arr


def _norm_sq(q: np.ndarray, name: str) -> np.ndarray:
    """Squared length of each quaternion in `q`; raise if any is zero."""
    n2 = np.einsum("...i,...i->...", q, q)
    if np.any(n2 == 0.0):
        raise ValueError(f"{name} is a zero quaternion, which has no rotation")
    return n2


def quat_identity() -> np.ndarray:
    """The identity rotation (1, 0, 0, 0)."""
    return np.array([1.0, 0.0, 0.0, 0.0])


def quat_normalize(q: ArrayLike) -> np.ndarray:
    """Scale `q` (shape (4,) or (N, 4)) to unit length; raise ValueError for zero or non-finite input."""
    c = _floats(q, 4)
    if c is not None:
        w, x, y, z = c
        n2 = w * w + x * x + y * y + z * z
        if _SAFE_MIN_SQ < n2 < _SAFE_MAX_SQ:  # False for NaN and inf
            n = math.sqrt(n2)
            return _array([w / n, x / n, y / n, z / n])
    arr = _checked(q, "q", (4,))
    # Dividing by the largest component first keeps the squared norm from overflowing or underflowing.
    peak = np.max(np.abs(arr), axis=-1, keepdims=True)
    if np.any(peak == 0.0):
        raise ValueError("q is a zero quaternion and cannot be normalized")
    arr = arr / peak
    return arr / np.linalg.norm(arr, axis=-1, keepdims=True)


def quat_conjugate(q: ArrayLike) -> np.ndarray:
    """The conjugate (w, -x, -y, -z); for a unit quaternion this is the inverse rotation."""
    c = _floats(q, 4)
    if c is not None and math.isfinite(c[0] + c[1] + c[2] + c[3]):
        return _array([c[0], -c[1], -c[2], -c[3]])
    return _checked(q, "q", (4,)) * np.array([1.0, -1.0, -1.0, -1.0])


def quat_inverse(q: ArrayLike) -> np.ndarray:
    """The multiplicative inverse conj(q) / |q|^2 (valid for non-unit quaternions too)."""
    arr = _checked(q, "q", (4,))
    return quat_conjugate(arr) / _norm_sq(arr, "q")[..., None]


def quat_mul(a: ArrayLike, b: ArrayLike) -> np.ndarray:
    """Compose rotations: the Hamilton product a * b, renormalised; shapes (4,) or (N, 4), broadcast.

    As a rotation, `quat_mul(a, b)` applies `b` first and then `a` (like the matrix product Ra @ Rb).
    The exact product of unit quaternions has unit length; renormalising removes the rounding, which
    would otherwise compound: a unit quaternion stored in float64 is off by up to ~1e-16, and a million
    compositions (frames of a spinning object) would drift by ~1e-10.
    """
    # The usual case (two float64 arrays of shape (4,)) is tested inline; _floats handles the rest.
    if type(a) is _ND and type(b) is _ND and a.dtype is _F64 and b.dtype is _F64 and a.shape == _S4 == b.shape:
        ca, cb = a.tolist(), b.tolist()  # type: ignore[union-attr]
    else:
        ca, cb = _floats(a, 4), _floats(b, 4)
    if ca is not None and cb is not None:
        aw, ax, ay, az = ca
        bw, bx, by, bz = cb
        w = aw * bw - ax * bx - ay * by - az * bz
        x = aw * bx + ax * bw + ay * bz - az * by
        y = aw * by - ax * bz + ay * bw + az * bx
        z = aw * bz + ax * by - ay * bx + az * bw
        n2 = w * w + x * x + y * y + z * z
        if _SAFE_MIN_SQ < n2 < _SAFE_MAX_SQ:  # False for NaN and inf: the general path raises
            n = math.sqrt(n2)
            return _array([w / n, x / n, y / n, z / n])
    qa = _checked(a, "a", (4,))
    qb = _checked(b, "b", (4,))
    aw, ax, ay, az = np.moveaxis(qa, -1, 0)
    bw, bx, by, bz = np.moveaxis(qb, -1, 0)
    out = np.stack(
        [
            aw * bw - ax * bx - ay * by - az * bz,
            aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw,
        ],
        axis=-1,
    )
    n2 = np.einsum("...i,...i->...", out, out)
    if np.any(n2 == 0.0):
        raise ValueError("a and b must be non-zero quaternions; their product is zero")
    return out / np.sqrt(n2)[..., None]


def quat_from_axis_angle(axis: ArrayLike, radians: float) -> np.ndarray:
    """Rotation by `radians` about `axis` (any non-zero length; right-hand rule)."""
    c = _floats(axis, 3)
    if c is not None and type(radians) in _FLOAT:
        x, y, z = c
        n2 = x * x + y * y + z * z
        half = 0.5 * radians
        if _SAFE_MIN_SQ < n2 < _SAFE_MAX_SQ and -1e300 < half < 1e300:  # False for NaN and inf
            s = math.sin(half) / math.sqrt(n2)
            return _array([math.cos(half), s * x, s * y, s * z])
    ax = _checked(axis, "axis", (3,))
    if ax.ndim != 1:
        raise ValueError(f"axis must have shape (3,), got {ax.shape}")
    angle = float(radians)
    if not np.isfinite(angle):
        raise ValueError(f"radians must be finite, got {radians!r}")
    peak = np.max(np.abs(ax))
    if peak == 0.0:
        raise ValueError("axis must be a non-zero vector, got (0, 0, 0)")
    ax = ax / peak
    ax = ax / np.linalg.norm(ax)
    half = 0.5 * angle
    return np.concatenate([[np.cos(half)], np.sin(half) * ax])


def quat_from_euler(degrees_xyz: ArrayLike) -> np.ndarray:
    """Quaternion for Euler angles in degrees (shape (3,) or (N, 3)), with R = Rz @ Ry @ Rx."""
    half = np.radians(_checked(degrees_xyz, "degrees_xyz", (3,))) * 0.5
    cx, cy, cz = np.moveaxis(np.cos(half), -1, 0)
    sx, sy, sz = np.moveaxis(np.sin(half), -1, 0)
    # Expanded product qz * qy * qx.
    return np.stack(
        [
            cz * cy * cx + sz * sy * sx,
            cz * cy * sx - sz * sy * cx,
            cz * sy * cx + sz * cy * sx,
            sz * cy * cx - cz * sy * sx,
        ],
        axis=-1,
    )


def quat_to_euler(q: ArrayLike) -> np.ndarray:
    """Euler angles in degrees (x, y, z) with R = Rz @ Ry @ Rx; shape (4,) -> (3,), (N, 4) -> (N, 3).

    Pitch (y) lies in [-90, 90]. At gimbal lock (|pitch| = 90 degrees) the x and z rotations share one axis;
    the whole turn is then reported in z and x is 0. Never returns NaN.
    """
    m = quat_to_matrix3(q)
    r00, r10, r20 = m[..., 0, 0], m[..., 1, 0], m[..., 2, 0]
    cos_pitch = np.hypot(r00, r10)
    # atan2 with hypot instead of asin(-r20): accurate near +-90 degrees and no domain error (NaN) when
    # rounding pushes |r20| just above 1.
    pitch = np.arctan2(-r20, cos_pitch)
    locked = cos_pitch < _GIMBAL_COS
    roll = np.where(locked, 0.0, np.arctan2(m[..., 2, 1], m[..., 2, 2]))
    yaw = np.where(locked, np.arctan2(-m[..., 0, 1], m[..., 1, 1]), np.arctan2(r10, r00))
    return np.degrees(np.stack([roll, pitch, yaw], axis=-1))


def quat_rotate(q: ArrayLike, v: ArrayLike) -> np.ndarray:
    """Rotate vectors `v` (shape (3,) or (N, 3)) by unit quaternion(s) `q` ((4,) or (N, 4))."""
    cq = _floats(q, 4)
    if cq is not None:
        cv = _floats(v, 3)
        if cv is not None:
            w, ux, uy, uz = cq
            vx, vy, vz = cv
            tx = 2.0 * (uy * vz - uz * vy)
            ty = 2.0 * (uz * vx - ux * vz)
            tz = 2.0 * (ux * vy - uy * vx)
            rx = vx + w * tx + (uy * tz - uz * ty)
            ry = vy + w * ty + (uz * tx - ux * tz)
            rz = vz + w * tz + (ux * ty - uy * tx)
            if math.isfinite(rx + ry + rz):  # non-finite input always gives a non-finite result
                return _array([rx, ry, rz])
    qq = _checked(q, "q", (4,))
    vv = _checked(v, "v", (3,))
    w = qq[..., :1]
    u = qq[..., 1:]
    # v' = v + w t + u x t with t = 2 u x v: two cross products, cheaper than building the matrix.
    t = 2.0 * np.cross(u, vv)
    return vv + w * t + np.cross(u, t)


def quat_slerp(a: ArrayLike, b: ArrayLike, t: ArrayLike) -> np.ndarray:
    """Spherical linear interpolation from `a` (t = 0) to `b` (t = 1) along the shorter arc.

    `a`, `b` have shape (4,) or (N, 4); `t` is a scalar or an array broadcasting against the batch axis,
    each value in [0, 1]. The result has unit length. Nearly equal rotations use normalised lerp, where
    slerp's sin(angle) denominator would lose precision.
    """
    qa = quat_normalize(a)
    qb = quat_normalize(b)
    tt = np.asarray(t, dtype=np.float64)
    if not np.all(np.isfinite(tt)) or np.any(tt < 0.0) or np.any(tt > 1.0):
        raise ValueError(f"t must lie in [0, 1], got {t!r}")
    # q and -q are the same rotation; flip b onto a's hemisphere to take the short way round.
    sign = np.where(np.einsum("...i,...i->...", qa, qb) < 0.0, -1.0, 1.0)
    qb = qb * sign[..., None]
    # Half the 4D angle between a and b; atan2 of chord lengths is accurate for tiny and large angles,
    # unlike arccos(dot).
    theta = 2.0 * np.arctan2(np.linalg.norm(qa - qb, axis=-1), np.linalg.norm(qa + qb, axis=-1))
    tiny = theta < _SLERP_MIN_ANGLE
    safe_theta = np.where(tiny, 1.0, theta)
    sin_theta = np.sin(safe_theta)
    wa = np.where(tiny, 1.0 - tt, np.sin((1.0 - tt) * safe_theta) / sin_theta)
    wb = np.where(tiny, tt, np.sin(tt * safe_theta) / sin_theta)
    out = wa[..., None] * qa + wb[..., None] * qb
    return out / np.linalg.norm(out, axis=-1, keepdims=True)


def quat_to_matrix3(q: ArrayLike) -> np.ndarray:
    """Rotation matrix of `q`: shape (4,) -> (3, 3), (N, 4) -> (N, 3, 3).

    Non-unit input is treated as its normalised rotation (the 2/|q|^2 factor), so small drift in
    stored quaternions never shears the result.
    """
    qq = _checked(q, "q", (4,))
    m = np.empty(qq.shape[:-1] + (3, 3))
    _write_rotation(qq, m)
    return m


def _write_rotation(q: np.ndarray, dst: np.ndarray) -> None:
    """Write the rotation matrices of checked quaternions `q` (..., 4) into `dst` (..., 3, 3).

    Every step works on whole 1D component arrays and writes straight into `dst`: numpy is slow at
    broadcasting over tiny trailing axes. (Per-frame model matrices of many entities: ``TRSBatch``.)
    """
    k = 2.0 / _norm_sq(q, "q")
    w, x, y, z = np.moveaxis(q, -1, 0)
    xk, yk, zk = x * k, y * k, z * k
    wx, wy, wz = w * xk, w * yk, w * zk
    xx, xy, xz = x * xk, x * yk, x * zk
    yy, yz, zz = y * yk, y * zk, z * zk
    entries = (
        (1.0 - (yy + zz), xy - wz, xz + wy),
        (xy + wz, 1.0 - (xx + zz), yz - wx),
        (xz - wy, yz + wx, 1.0 - (xx + yy)),
    )
    for i, row in enumerate(entries):
        for j, value in enumerate(row):
            dst[..., i, j] = value


def quat_from_matrix3(m: ArrayLike) -> np.ndarray:
    """Unit quaternion (with w >= 0) of a rotation matrix; shape (3, 3) -> (4,), (N, 3, 3) -> (N, 4).

    Shepperd's method: of the four ways to recover the quaternion, use the one whose square root argument
    (1 + trace, or 1 + 2*m_ii - trace) is largest, so no step divides by a small number.
    """
    mm = _checked(m, "m", (3, 3))
    m00, m11, m22 = mm[..., 0, 0], mm[..., 1, 1], mm[..., 2, 2]
    trace = m00 + m11 + m22
    d21 = mm[..., 2, 1] - mm[..., 1, 2]
    d02 = mm[..., 0, 2] - mm[..., 2, 0]
    d10 = mm[..., 1, 0] - mm[..., 0, 1]
    s01 = mm[..., 0, 1] + mm[..., 1, 0]
    s02 = mm[..., 0, 2] + mm[..., 2, 0]
    s12 = mm[..., 1, 2] + mm[..., 2, 1]
    # Each candidate is 4 * q_k * q (unnormalised); row k of `cand` has diagonal term 4 * q_k^2.
    cand = np.stack(
        [
            np.stack([1.0 + trace, d21, d02, d10], axis=-1),
            np.stack([d21, 1.0 + 2.0 * m00 - trace, s01, s02], axis=-1),
            np.stack([d02, s01, 1.0 + 2.0 * m11 - trace, s12], axis=-1),
            np.stack([d10, s02, s12, 1.0 + 2.0 * m22 - trace], axis=-1),
        ],
        axis=-2,
    )
    pivots = np.stack([trace, m00, m11, m22], axis=-1)
    best = np.argmax(pivots, axis=-1)
    q = np.take_along_axis(cand, best[..., None, None], axis=-2)[..., 0, :]
    q = q / np.linalg.norm(q, axis=-1, keepdims=True)
    return q * np.where(q[..., :1] < 0.0, -1.0, 1.0)
