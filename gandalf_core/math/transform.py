"""Affine 4x4 transforms: build (T @ R @ S), take apart, invert, derive normal and view matrices.

Matrices are row-major float64 numpy arrays acting on column vectors (p' = M @ p); the world is right-handed
with +Y up and a camera looks down its -Z axis. Batch forms take (N, ...) arrays and loop in numpy only.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike

from .quaternion import _checked, quat_from_matrix3, quat_to_matrix3

# |forward x up| below this (both unit vectors) counts as "up is parallel to the view direction".
_PARALLEL_UP = 1e-6
# |det| below this fraction of the product of column lengths counts as singular: the fraction is
# scale-invariant, so uniformly tiny (1e-6) or huge (1e6) scales still invert.
_SINGULAR_RATIO = 1e-12


def translation(t: ArrayLike) -> np.ndarray:
    """4x4 matrix translating by the 3-vector `t`."""
    m = np.eye(4)
    m[:3, 3] = _vec3(t, "t")
    return m


def scaling(s: ArrayLike) -> np.ndarray:
    """4x4 matrix scaling by `s`: a scalar (uniform) or a 3-vector (per axis)."""
    m = np.eye(4)
    m[:3, :3] = np.diag(_scale3(s))
    return m


def rotation(q: ArrayLike) -> np.ndarray:
    """4x4 matrix rotating by the quaternion `q` (w, x, y, z)."""
    m = np.eye(4)
    m[:3, :3] = quat_to_matrix3(_quat(q))
    return m


def trs(t: ArrayLike, q: ArrayLike, s: ArrayLike) -> np.ndarray:
    """The model matrix T @ R @ S: scale by `s`, then rotate by `q`, then translate by `t`."""
    m = np.eye(4)
    # R @ diag(s) scales the columns of R; no need for two matrix products.
    m[:3, :3] = quat_to_matrix3(_quat(q)) * _scale3(s)
    m[:3, 3] = _vec3(t, "t")
    return m


def trs_batch(t: ArrayLike, q: ArrayLike, s: ArrayLike, out: np.ndarray | None = None) -> np.ndarray:
    """Model matrices T @ R @ S for N entities at once: t (N, 3), q (N, 4), s (N, 3) -> (N, 4, 4).

    Pass a float64 (N, 4, 4) array as `out` to reuse it from frame to frame instead of allocating; a
    :class:`TRSBatch` also keeps its scratch memory between calls.
    """
    return TRSBatch()(t, q, s, out)


#: Up to this many matrices, :class:`TRSBatch` computes in plain floats: three dozen numpy calls on arrays of a few
#: elements cost more than the arithmetic (a scene with one camera and one model, every frame).
_FEW = 8


def _few_trs(t: ArrayLike, q: ArrayLike, s: ArrayLike, out: np.ndarray) -> bool:
    """T @ R(q/|q|) @ S into ``out`` for a few float64 (n, 3)/(n, 4) arrays of matching length; False (nothing
    written) for anything else, including non-finite or zero quaternions, so the general path raises its errors."""
    if not all(isinstance(a, np.ndarray) and a.dtype == np.float64 for a in (t, q, s)) or out.dtype != np.float64:
        return False
    n = len(out)
    if t.shape != (n, 3) or q.shape != (n, 4) or s.shape != (n, 3) or out.shape != (n, 4, 4):
        return False
    rows = []
    for (tx, ty, tz), (w, x, y, z), (sx, sy, sz) in zip(t.tolist(), q.tolist(), s.tolist()):
        k = w * w + x * x + y * y + z * z
        if not (k > 0.0 and math.isfinite(k + tx + ty + tz + sx + sy + sz)):
            return False
        k = 2.0 / k
        xk, yk, zk = x * k, y * k, z * k
        rows.append(((1.0 - (y * yk + z * zk)) * sx, (x * yk - w * zk) * sy, (x * zk + w * yk) * sz, tx,
                     (x * yk + w * zk) * sx, (1.0 - (x * xk + z * zk)) * sy, (y * zk - w * xk) * sz, ty,
                     (x * zk - w * yk) * sx, (y * zk + w * xk) * sy, (1.0 - (x * xk + y * yk)) * sz, tz,
                     0.0, 0.0, 0.0, 1.0))
    out[...] = np.array(rows).reshape(n, 4, 4)
    return True


class TRSBatch:
    """Builds T @ R @ S for N entities per call, keeping its scratch arrays between calls.

    Per-frame work on 100k entities is dominated by memory traffic: fresh temporaries of N floats cost
    page faults on every call, so this keeps them (the TransformSystem owns one). Every step works on
    whole contiguous component arrays with ``out=`` and writes the result with one transposing copy.
    Quaternions need not be unit length (the rotation of q/|q| is built), but must not be zero.
    """

    def __init__(self) -> None:
        self._n = -1

    def _allocate(self, n: int) -> None:
        self._q = np.empty((4, n))  # w, x, y, z rows
        self._s = np.empty((3, n))
        self._tmp = np.empty((7, n))
        self._rows = np.empty((3, 4, n))  # the top three rows of every matrix, component-major
        self._n = n

    def __call__(self, t: ArrayLike, q: ArrayLike, s: ArrayLike, out: np.ndarray | None = None) -> np.ndarray:
        if out is not None and len(out) <= _FEW and _few_trs(t, q, s, out):
            return out
        qq = _checked(q, "q", (4,)).reshape(-1, 4)
        n = qq.shape[0]
        tt = _checked(t, "t", (3,))
        ss = _checked(s, "s", (3,))
        if tt.shape != (n, 3) or ss.shape != (n, 3):
            raise ValueError(f"t and s must have shape ({n}, 3) to match q {qq.shape}, got {tt.shape} and {ss.shape}")
        if out is None:
            out = np.empty((n, 4, 4))
        elif out.shape != (n, 4, 4) or out.dtype != np.float64:
            raise ValueError(f"out must be a float64 array of shape ({n}, 4, 4), got {out.dtype} {out.shape}")
        if n != self._n:
            self._allocate(n)
        c, sc, tmp, rows = self._q, self._s, self._tmp, self._rows
        c[:] = qq.T
        sc[:] = ss.T
        w, x, y, z = c
        k, xk, yk, zk, a, b, d = tmp
        np.einsum("ij,ij->j", c, c, out=k)
        if not k.all():
            raise ValueError("q is a zero quaternion, which has no rotation")
        np.divide(2.0, k, out=k)
        np.multiply(x, k, out=xk)
        np.multiply(y, k, out=yk)
        np.multiply(z, k, out=zk)
        # Diagonal: 1 - (yy + zz), 1 - (xx + zz), 1 - (xx + yy), each times its column's scale.
        for i, (p, pk, r, rk) in enumerate(((y, yk, z, zk), (x, xk, z, zk), (x, xk, y, yk))):
            np.multiply(p, pk, out=a)
            np.multiply(r, rk, out=b)
            a += b
            np.subtract(1.0, a, out=a)
            np.multiply(a, sc[i], out=rows[i, i])
        # Off-diagonal pairs (i, j) and (j, i) share two products: u ± v.
        for (i, j), (p, pk), (r, rk) in (((0, 1), (x, yk), (w, zk)), ((0, 2), (x, zk), (w, yk)),
                                         ((1, 2), (y, zk), (w, xk))):
            np.multiply(p, pk, out=a)
            np.multiply(r, rk, out=b)
            sign = -1.0 if (i, j) != (0, 2) else 1.0  # r01 = xy - wz, r02 = xz + wy, r12 = yz - wx
            np.multiply(b, sign, out=b)
            np.add(a, b, out=d)
            np.multiply(d, sc[j], out=rows[i, j])
            np.subtract(a, b, out=d)
            np.multiply(d, sc[i], out=rows[j, i])
        rows[:, 3] = tt.T
        out[:, :3, :] = rows.transpose(2, 0, 1)
        out[:, 3, :3] = 0.0
        out[:, 3, 3] = 1.0
        return out


def decompose_trs(m: ArrayLike) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Split an affine matrix without shear into (t, q, s) with `trs(t, q, s)` equal to `m`.

    A mirroring matrix (negative determinant) comes back with the x scale negative. A zero scale axis
    carries no rotation information: that part of the rotation is filled in from the identity, so the
    result is still a unit quaternion (never NaN).
    """
    mm = _affine(m, "m")
    a = mm[:3, :3]
    s = np.linalg.norm(a, axis=0)
    valid = s > 0.0
    cols = np.zeros((3, 3))
    cols[:, valid] = a[:, valid] / s[valid]
    if not np.all(valid):
        _complete_basis(cols, valid)
    if np.linalg.det(cols) < 0.0:
        # Mirror: flip one axis of the rotation and its scale. Prefer a zero-scale axis, whose sign is
        # free, so the scale signs stay as they were.
        if np.all(valid):
            cols[:, 0] = -cols[:, 0]
            s[0] = -s[0]
        else:
            axis = np.flatnonzero(~valid)[-1]
            cols[:, axis] = -cols[:, axis]
    return mm[:3, 3].copy(), quat_from_matrix3(cols), s


def cross3(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Cross product of 3-vectors along the last axis (one pair or batches): ``np.cross`` without its axis
    handling, which costs more than the arithmetic for the small arrays a frame uses."""
    a0, a1, a2 = a[..., 0], a[..., 1], a[..., 2]
    b0, b1, b2 = b[..., 0], b[..., 1], b[..., 2]
    return np.stack([a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0], axis=-1)


def invert_affine(m: ArrayLike) -> np.ndarray:
    """Inverse of an affine 4x4 matrix (last row 0, 0, 0, 1); ValueError if it is singular (a zero scale).

    The inverse of the 3x3 part is built from cross products of its columns (adjugate / determinant),
    which keeps full relative precision for scales far from 1 (1e-6, 1e6) where elimination would not.
    """
    mm = _affine(m, "m")
    # Plain floats: one 4x4 costs more in numpy call overhead than in arithmetic (the camera's view, every frame).
    (a00, a01, a02, t0), (a10, a11, a12, t1), (a20, a21, a22, t2), _ = mm.tolist()
    # Rows of the adjugate: the cross products of the columns c1 x c2, c2 x c0, c0 x c1.
    r0 = (a11 * a22 - a21 * a12, a21 * a02 - a01 * a22, a01 * a12 - a11 * a02)
    r1 = (a12 * a20 - a22 * a10, a22 * a00 - a02 * a20, a02 * a10 - a12 * a00)
    r2 = (a10 * a21 - a20 * a11, a20 * a01 - a00 * a21, a00 * a11 - a10 * a01)
    det = a00 * r0[0] + a10 * r0[1] + a20 * r0[2]
    lengths = math.hypot(a00, a10, a20) * math.hypot(a01, a11, a21) * math.hypot(a02, a12, a22)
    if not math.isfinite(det) or lengths == 0.0 or abs(det) <= _SINGULAR_RATIO * lengths:
        raise ValueError(f"m is singular (a zero scale or collapsed axis, determinant {det:g}); it has no inverse")
    inv = np.eye(4)
    inv[:3, :3] = np.array((r0, r1, r2)) / det
    inv[:3, 3] = -(inv[:3, :3] @ (t0, t1, t2))
    return inv


def normal_matrix(m: ArrayLike) -> np.ndarray:
    """3x3 matrix that transforms surface normals under `m` (renormalise the result per normal).

    It is the cofactor matrix of the upper 3x3 (det * inverse-transpose), scaled so its largest entry
    has magnitude 1 and signed like the determinant: the same directions as the inverse-transpose,
    but finite for zero or extreme scales. A fully collapsed matrix gives zeros, never NaN or Inf.
    """
    return normal_matrix_batch(_mat4(m, "m")[None])[0]


def normal_matrix_batch(ms: ArrayLike) -> np.ndarray:
    """`normal_matrix` for a stack of matrices: (N, 4, 4) -> (N, 3, 3)."""
    mm = _checked(ms, "ms", (4, 4)).reshape(-1, 4, 4)
    a = mm[:, :3, :3]
    # Scale each matrix to entries <= 1 first so the cross products cannot overflow or underflow.
    peak = np.max(np.abs(a), axis=(1, 2), keepdims=True)
    a = a / np.where(peak > 0.0, peak, 1.0)
    c0, c1, c2 = a[:, :, 0], a[:, :, 1], a[:, :, 2]
    cof = np.stack([cross3(c1, c2), cross3(c2, c0), cross3(c0, c1)], axis=-1)
    det = np.einsum("ni,ni->n", c0, cof[:, :, 0])
    cof_peak = np.max(np.abs(cof), axis=(1, 2))
    scale = np.where(det < 0.0, -1.0, 1.0) / np.where(cof_peak > 0.0, cof_peak, 1.0)
    return cof * scale[:, None, None]


def look_at(eye: ArrayLike, target: ArrayLike, up: ArrayLike = (0.0, 1.0, 0.0)) -> np.ndarray:
    """View matrix (world -> camera) of a camera at `eye` looking at `target`, its top towards `up`.

    If `up` is (nearly) parallel to the view direction, a fixed fallback is used instead: for the usual
    +Y up, a camera looking straight down gets -Z as its top and one looking straight up gets +Z, the
    orientation it would reach by pitching there from the default view.
    """
    e = _vec3(eye, "eye")
    right, true_up, forward = _camera_basis(e, _vec3(target, "target"), _vec3(up, "up"))
    view = np.eye(4)
    view[0, :3], view[1, :3], view[2, :3] = right, true_up, -forward
    view[:3, 3] = -view[:3, :3] @ e
    return view


def look_at_rotation(eye: ArrayLike, target: ArrayLike, up: ArrayLike = (0.0, 1.0, 0.0)) -> np.ndarray:
    """Quaternion that orients a camera (looking down its local -Z, +Y up) from `eye` towards `target`.

    It is the rotation part of the camera's world transform, i.e. the inverse of `look_at`'s rotation.
    """
    right, true_up, forward = _camera_basis(_vec3(eye, "eye"), _vec3(target, "target"), _vec3(up, "up"))
    return quat_from_matrix3(np.stack([right, true_up, -forward], axis=1))


def _vec3(value: ArrayLike, name: str) -> np.ndarray:
    """`value` as a finite float64 3-vector."""
    arr = _checked(value, name, (3,))
    if arr.ndim != 1:
        raise ValueError(f"{name} must have shape (3,), got {arr.shape}")
    return arr


def _scale3(s: ArrayLike) -> np.ndarray:
    """A scale given as a scalar or a 3-vector, as a finite 3-vector."""
    arr = np.asarray(s, dtype=np.float64)
    return _vec3(np.full(3, arr) if arr.ndim == 0 else arr, "s")


def _quat(q: ArrayLike) -> np.ndarray:
    """`q` as a finite float64 quaternion of shape (4,)."""
    arr = _checked(q, "q", (4,))
    if arr.ndim != 1:
        raise ValueError(f"q must have shape (4,), got {arr.shape}")
    return arr


def _mat4(m: ArrayLike, name: str) -> np.ndarray:
    """`m` as a finite float64 matrix of shape (4, 4)."""
    mm = _checked(m, name, (4, 4))
    if mm.ndim != 2:
        raise ValueError(f"{name} must have shape (4, 4), got {mm.shape}")
    return mm


def _affine(m: ArrayLike, name: str) -> np.ndarray:
    """`m` as a finite 4x4 matrix whose last row is (0, 0, 0, 1)."""
    mm = _mat4(m, name)
    if not np.array_equal(mm[3], [0.0, 0.0, 0.0, 1.0]):
        raise ValueError(f"{name} is not affine: its last row is {mm[3]}, expected (0, 0, 0, 1)")
    return mm


def _complete_basis(cols: np.ndarray, valid: np.ndarray) -> None:
    """Fill the columns of `cols` not marked `valid` so that all three are orthonormal (in place).

    Missing columns start from the matching identity axis (then the others, in order) and are
    Gram-Schmidt-orthogonalised against the columns already there; handedness is fixed by the caller.
    """
    done = [int(i) for i in np.flatnonzero(valid)]
    for i in np.flatnonzero(~valid):
        for k in (i, (i + 1) % 3, (i + 2) % 3):
            v = np.eye(3)[k]
            for j in done:
                v = v - np.dot(cols[:, j], v) * cols[:, j]
            length = np.linalg.norm(v)
            # Any identity axis not within ~35 degrees of the span so far gives a well-conditioned column.
            if length > 0.5:
                cols[:, i] = v / length
                done.append(int(i))
                break


def _camera_basis(eye: np.ndarray, target: np.ndarray, up: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Orthonormal (right, up, forward) of a camera at `eye` looking at `target`."""
    d = target - eye
    d_peak = np.max(np.abs(d))
    if d_peak == 0.0:
        raise ValueError(f"target must differ from eye, both are {tuple(eye.tolist())}")
    # Normalise after dividing by the largest component so huge or tiny distances neither overflow nor underflow.
    forward = d / d_peak
    forward /= np.linalg.norm(forward)
    up_peak = np.max(np.abs(up))
    if up_peak == 0.0:
        raise ValueError("up must be a non-zero vector, got (0, 0, 0)")
    up_dir = up / up_peak
    up_dir /= np.linalg.norm(up_dir)
    right = np.cross(forward, up_dir)
    if np.linalg.norm(right) < _PARALLEL_UP:
        # Use the world axis most perpendicular to up (ties prefer Z, then X), signed so that looking
        # along +up or -up continues smoothly from pitching up or down towards it.
        k = (2, 0, 1)[int(np.argmin(np.abs(up_dir[[2, 0, 1]])))]
        helper = np.eye(3)[k] - up_dir[k] * up_dir
        helper /= np.linalg.norm(helper)
        right = np.cross(forward, np.sign(np.dot(forward, up_dir)) * helper)
    right /= np.linalg.norm(right)
    return right, np.cross(right, forward), forward
