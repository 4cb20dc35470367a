"""Tests for gandalf_core.math: quaternions, affine transforms, look-at and projections.

Every comparison states its tolerance; most are a small multiple of float64 rounding (eps ~ 2.2e-16).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import gandalf_core.math as gm
from gandalf_core.math import (
    DepthRange,
    decompose_trs,
    depth_range,
    invert_affine,
    look_at,
    look_at_rotation,
    normal_matrix,
    normal_matrix_batch,
    orthographic,
    perspective,
    rotation,
    scaling,
    translation,
    trs,
    trs_batch,
)

FAST = settings(max_examples=60, deadline=None)

unit = st.floats(-1.0, 1.0)
quaternions = (
    st.tuples(unit, unit, unit, unit)
    .filter(lambda c: sum(v * v for v in c) > 1e-4)
    .map(lambda c: gm.quat_normalize(np.array(c)))
)
vectors = st.tuples(*(st.floats(-1e3, 1e3),) * 3).map(np.array)
magnitudes = st.floats(0.1, 10.0)
scales = st.tuples(magnitudes, magnitudes, magnitudes).map(np.array)


def rot_x(deg: float) -> np.ndarray:
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])


def rot_y(deg: float) -> np.ndarray:
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])


def rot_z(deg: float) -> np.ndarray:
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def angle_of(q: np.ndarray) -> float:
    """Rotation angle of a unit quaternion in [0, pi], accurate for small angles."""
    return 2.0 * math.atan2(np.linalg.norm(q[1:]), abs(q[0]))


def ndc(m: np.ndarray, points: np.ndarray) -> np.ndarray:
    """Project eye-space points (N, 3) by `m` and divide by w."""
    clip = np.c_[points, np.ones(len(points))] @ m.T
    return clip[:, :3] / clip[:, 3:]


# --- quaternions -------------------------------------------------------------------------------------------


def test_identity_and_axis_angle_match_hand_built_matrices():
    assert np.array_equal(gm.quat_to_matrix3(gm.quat_identity()), np.eye(3))
    # 1e-15: a handful of roundings of entries of size <= 1.
    np.testing.assert_allclose(gm.quat_to_matrix3(gm.quat_from_axis_angle([0, 0, 2], math.pi / 2)), rot_z(90),
                               atol=1e-15)
    np.testing.assert_allclose(gm.quat_to_matrix3(gm.quat_from_axis_angle([3, 0, 0], 0.7)), rot_x(math.degrees(0.7)),
                               atol=1e-15)


def test_euler_convention_is_rz_ry_rx():
    q = gm.quat_from_euler([30.0, -50.0, 110.0])
    np.testing.assert_allclose(gm.quat_to_matrix3(q), rot_z(110) @ rot_y(-50) @ rot_x(30), atol=1e-15)


@FAST
@given(quaternions, quaternions)
def test_quat_mul_applies_b_first_then_a(a, b):
    # Tolerance 1e-14: products of a few unit-size matrices.
    np.testing.assert_allclose(gm.quat_to_matrix3(gm.quat_mul(a, b)), gm.quat_to_matrix3(a) @ gm.quat_to_matrix3(b),
                               atol=1e-14)
    v = np.array([0.3, -1.2, 2.0])
    np.testing.assert_allclose(gm.quat_rotate(gm.quat_mul(a, b), v), gm.quat_rotate(a, gm.quat_rotate(b, v)),
                               atol=1e-14)


def test_batch_forms_equal_single_forms():
    rng = np.random.default_rng(1)
    a = gm.quat_normalize(rng.normal(size=(50, 4)))
    b = gm.quat_normalize(rng.normal(size=(50, 4)))
    v = rng.normal(size=(50, 3))
    batch_mul = gm.quat_mul(a, b)
    batch_mat = gm.quat_to_matrix3(a)
    batch_rot = gm.quat_rotate(a, v)
    for i in range(50):
        # Same arithmetic in the same order: equal to the last bit, 0 tolerance apart from 1e-16 slack.
        np.testing.assert_allclose(batch_mul[i], gm.quat_mul(a[i], b[i]), atol=1e-16)
        np.testing.assert_allclose(batch_mat[i], gm.quat_to_matrix3(a[i]), atol=1e-16)
        np.testing.assert_allclose(batch_rot[i], gm.quat_rotate(a[i], v[i]), atol=1e-15)


@FAST
@given(quaternions)
def test_inverse_and_conjugate_undo_the_rotation(q):
    np.testing.assert_allclose(gm.quat_mul(q, gm.quat_inverse(q)), gm.quat_identity(), atol=1e-15)
    np.testing.assert_allclose(gm.quat_inverse(2.0 * q), gm.quat_conjugate(q) / 2.0, atol=1e-15)
    v = np.array([1.0, 2.0, 3.0])
    np.testing.assert_allclose(gm.quat_rotate(gm.quat_conjugate(q), gm.quat_rotate(q, v)), v, atol=1e-14)


@FAST
@given(quaternions)
def test_quaternion_matrix_round_trip(q):
    m = gm.quat_to_matrix3(q)
    # A rotation: orthonormal with determinant +1 (tolerance 1e-14).
    np.testing.assert_allclose(m @ m.T, np.eye(3), atol=1e-14)
    assert abs(np.linalg.det(m) - 1.0) < 1e-14
    back = gm.quat_from_matrix3(m)
    # q and -q are the same rotation; the result is returned with w >= 0. Tolerance 1e-14.
    assert back[0] >= 0.0
    assert min(np.abs(back - q).max(), np.abs(back + q).max()) < 1e-14


@pytest.mark.parametrize("axis", [(1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 1), (-2, 0.5, 3)])
@pytest.mark.parametrize("angle", [0.0, 1e-9, math.pi - 1e-9, math.pi])
def test_matrix_to_quaternion_is_stable_near_zero_and_half_turns(axis, angle):
    # Shepperd's method keeps full precision where the trace is -1 (half turns) or 3 (no turn).
    q = gm.quat_from_axis_angle(axis, angle)
    back = gm.quat_from_matrix3(gm.quat_to_matrix3(q))
    assert abs(np.linalg.norm(back) - 1.0) < 1e-15
    np.testing.assert_allclose(gm.quat_to_matrix3(back), gm.quat_to_matrix3(q), atol=1e-14)


@FAST
@given(st.floats(-179.0, 179.0), st.floats(-89.0, 89.0), st.floats(-179.0, 179.0))
def test_euler_round_trip_away_from_gimbal_lock(x, y, z):
    # Within 1 degree of gimbal lock the roll/yaw split loses ~eps/cos(pitch) ~ 1e-14 relative: bound 1e-9 deg.
    np.testing.assert_allclose(gm.quat_to_euler(gm.quat_from_euler([x, y, z])), [x, y, z], atol=1e-9)


@pytest.mark.parametrize("pitch", [90.0, -90.0, 90.0 - 1e-7, -90.0 + 1e-9, 90.0 - 1e-3])
def test_euler_at_gimbal_lock_has_no_nan_and_keeps_the_rotation(pitch):
    q = gm.quat_from_euler([25.0, pitch, -40.0])
    angles = gm.quat_to_euler(q)
    assert np.all(np.isfinite(angles))
    assert abs(abs(angles[1]) - abs(pitch)) < 1e-6
    # Reported angles must give back the same rotation; bound 1e-7 covers dropping cos(pitch) < 1.5e-8.
    np.testing.assert_allclose(gm.quat_to_matrix3(gm.quat_from_euler(angles)), gm.quat_to_matrix3(q), atol=1e-7)


def test_euler_batch_has_no_nan_even_with_unnormalised_input():
    q = gm.quat_from_euler(np.array([[0.0, 90.0, 0.0], [10.0, -90.0, 5.0], [1.0, 2.0, 3.0]])) * 1.0000001
    assert np.all(np.isfinite(gm.quat_to_euler(q)))


@FAST
@given(quaternions, quaternions)
def test_slerp_endpoints_unit_length_and_constant_speed(a, b):
    np.testing.assert_allclose(gm.quat_to_matrix3(gm.quat_slerp(a, b, 0.0)), gm.quat_to_matrix3(a), atol=1e-14)
    np.testing.assert_allclose(gm.quat_to_matrix3(gm.quat_slerp(a, b, 1.0)), gm.quat_to_matrix3(b), atol=1e-14)
    ts = np.linspace(0.0, 1.0, 11)
    path = gm.quat_slerp(a, b, ts)
    np.testing.assert_allclose(np.linalg.norm(path, axis=1), 1.0, atol=1e-15)
    # Shortest path at constant angular speed: angle(a -> slerp(t)) = t * angle(a -> b), within 1e-7 rad
    # (angle_of loses precision only through its atan2 of rounded components).
    total = angle_of(gm.quat_mul(gm.quat_conjugate(a), b))
    assert total <= math.pi + 1e-12
    for t, q in zip(ts, path):
        assert abs(angle_of(gm.quat_mul(gm.quat_conjugate(a), q)) - t * total) < 1e-7


def test_slerp_takes_the_short_way_and_handles_nearly_equal_inputs():
    a = gm.quat_from_axis_angle([0, 1, 0], 0.1)
    b = -gm.quat_from_axis_angle([0, 1, 0], 0.3)  # same rotation as +q; must not go the long way round
    np.testing.assert_allclose(gm.quat_to_matrix3(gm.quat_slerp(a, b, 0.5)),
                               gm.quat_to_matrix3(gm.quat_from_axis_angle([0, 1, 0], 0.2)), atol=1e-15)
    c = gm.quat_from_axis_angle([0, 1, 0], 0.1 + 1e-12)
    mid = gm.quat_slerp(a, c, 0.5)
    assert np.all(np.isfinite(mid)) and abs(np.linalg.norm(mid) - 1.0) < 1e-15
    np.testing.assert_allclose(mid, gm.quat_from_axis_angle([0, 1, 0], 0.1 + 5e-13), atol=1e-15)
    with pytest.raises(ValueError, match="t"):
        gm.quat_slerp(a, c, 1.5)


def test_a_million_small_rotations_stay_unit_and_add_up():
    # 1e6 rotations of 1e-6 rad about one axis must add up to 1 rad. Vectorised: 1000 chains of 1000 steps
    # each advance together (1000 batched quat_mul calls), then the 1000 chain results are composed one after
    # the other, so every one of the 1e6 steps goes through quat_mul and the sequential depth is 2000.
    axis = np.array([1.0, 2.0, 3.0]) / math.sqrt(14.0)
    step = gm.quat_from_axis_angle(axis, 1e-6)
    chains = np.tile(gm.quat_identity(), (1000, 1))
    for _ in range(1000):
        chains = gm.quat_mul(step, chains)
    total = gm.quat_identity()
    for q in chains:
        total = gm.quat_mul(q, total)
    assert abs(np.linalg.norm(total) - 1.0) < 1e-12
    # Per-step angle rounding (~1e-22 rad) and 2000 sequential roundings of ~1e-16: bound 1e-12 rad.
    assert abs(angle_of(total) - 1.0) < 1e-12
    np.testing.assert_allclose(total[1:] / np.linalg.norm(total[1:]), axis, atol=1e-12)


def test_quaternion_errors_name_the_parameter():
    with pytest.raises(ValueError, match="axis"):
        gm.quat_from_axis_angle([0, 0, 0], 1.0)
    with pytest.raises(ValueError, match="radians"):
        gm.quat_from_axis_angle([0, 1, 0], math.nan)
    with pytest.raises(ValueError, match="q"):
        gm.quat_normalize([0, 0, 0, 0])
    with pytest.raises(ValueError, match="q"):
        gm.quat_normalize([1, math.inf, 0, 0])
    with pytest.raises(ValueError, match="q"):
        gm.quat_to_matrix3([0, 0, 0, 0])


# --- transforms --------------------------------------------------------------------------------------------


def test_trs_is_t_times_r_times_s():
    q = gm.quat_from_euler([10.0, 20.0, 30.0])
    expected = translation([1, 2, 3]) @ rotation(q) @ scaling([2, 3, 4])
    np.testing.assert_allclose(trs([1, 2, 3], q, [2, 3, 4]), expected, atol=1e-15)
    np.testing.assert_allclose(scaling(2.0), np.diag([2.0, 2.0, 2.0, 1.0]))


@FAST
@given(vectors, quaternions, scales, st.sampled_from([(1, 1, 1), (-1, 1, 1), (1, -1, 1), (-1, -1, -1)]))
def test_trs_decompose_round_trip(t, q, s, signs):
    s = s * np.array(signs)
    m = trs(t, q, s)
    t2, q2, s2 = decompose_trs(m)
    # Rebuilding gives the same matrix, relative error 1e-14 of its largest entry.
    np.testing.assert_allclose(trs(t2, q2, s2), m, atol=1e-14 * np.abs(m).max())
    np.testing.assert_allclose(np.abs(s2), np.abs(s), rtol=1e-14)
    assert abs(np.linalg.norm(q2) - 1.0) < 1e-15
    if min(signs) > 0:
        # Without mirroring the parts themselves come back (q up to sign).
        np.testing.assert_allclose(gm.quat_to_matrix3(q2), gm.quat_to_matrix3(q), atol=1e-14)


@pytest.mark.parametrize("s", [(0, 2, 3), (2, 0, 3), (2, 3, 0), (0, 0, 3), (0, 2, 0), (0, 0, 0), (0, -2, 3)])
def test_decompose_zero_scale_gives_unit_rotation_without_nan(s):
    q = gm.quat_from_euler([15.0, 40.0, -70.0])
    m = trs([1, 2, 3], q, s)
    t2, q2, s2 = decompose_trs(m)
    assert np.all(np.isfinite(q2)) and abs(np.linalg.norm(q2) - 1.0) < 1e-15
    np.testing.assert_allclose(trs(t2, q2, s2), m, atol=1e-14)
    if s == (0, 0, 0):
        np.testing.assert_allclose(q2, gm.quat_identity())


def test_trs_batch_equals_a_loop_of_trs():
    rng = np.random.default_rng(7)
    n = 257
    t = rng.normal(size=(n, 3)) * 100.0
    q = gm.quat_normalize(rng.normal(size=(n, 4)))
    s = rng.uniform(-3.0, 3.0, size=(n, 3))
    out = np.full((n, 4, 4), np.nan)
    batch = trs_batch(t, q, s, out=out)
    assert batch is out
    for i in range(n):
        # Same operations per entry: equal within 1e-15 relative.
        np.testing.assert_allclose(batch[i], trs(t[i], q[i], s[i]), rtol=1e-15, atol=1e-15)
    with pytest.raises(ValueError, match="s"):
        trs_batch(t, q, s[:-1])


@pytest.mark.parametrize("s", [(1e-6, 1e-6, 1e-6), (1e6, 1e6, 1e6), (1e-6, 1e6, 1.0), (1e6, -1e-6, 3.0)])
def test_extreme_scales_stay_finite_and_accurate(s):
    s = np.array(s)
    q = gm.quat_from_euler([33.0, -12.0, 71.0])
    t = np.array([5.0, -7.0, 11.0])
    r = gm.quat_to_matrix3(q)
    m = trs(t, q, s)
    assert np.all(np.isfinite(m))
    np.testing.assert_allclose(m[:3, :3], r * s, rtol=1e-15)

    # The exact inverse is diag(1/s) @ R^T and -that @ t; each row has its own scale 1/s_i, so compare
    # row by row relative to the row's size: 1e-14.
    inv = invert_affine(m)
    exact = (r / s).T
    for i in range(3):
        np.testing.assert_allclose(inv[i, :3], exact[i], atol=1e-14 / abs(s[i]))
    np.testing.assert_allclose(inv[:3, 3], -exact @ t, rtol=1e-13)

    # Normals transform by the inverse-transpose R @ diag(1/s); the normal matrix must give the same unit
    # directions within 1e-12, even where the components differ by a factor 1e12.
    nm = normal_matrix(m)
    assert np.all(np.isfinite(nm)) and abs(np.abs(nm).max() - 1.0) < 1e-15
    rng = np.random.default_rng(3)
    for n in rng.normal(size=(20, 3)):
        got = nm @ n
        want = (r / s) @ n
        np.testing.assert_allclose(got / np.linalg.norm(got), want / np.linalg.norm(want), atol=1e-12)


def test_normal_matrix_batch_equals_single():
    rng = np.random.default_rng(5)
    ms = trs_batch(rng.normal(size=(40, 3)), gm.quat_normalize(rng.normal(size=(40, 4))),
                   rng.uniform(-2.0, 2.0, size=(40, 3)))
    batch = normal_matrix_batch(ms)
    for i in range(40):
        np.testing.assert_allclose(batch[i], normal_matrix(ms[i]), atol=1e-16)


def test_normal_matrix_keeps_outward_normals_under_mirroring():
    # Mirror in x: the +x face moves to -x and its outward normal must point to -x (as the inverse-transpose).
    nm = normal_matrix(scaling([-2.0, 1.0, 1.0]))
    got = nm @ np.array([1.0, 0.0, 0.0])
    np.testing.assert_allclose(got / np.linalg.norm(got), [-1.0, 0.0, 0.0], atol=1e-15)


@pytest.mark.parametrize("s", [(0, 1, 1), (0, 0, 1), (0, 0, 0), (0, 2e6, 1e-6)])
def test_zero_scale_normal_matrix_is_finite_and_invert_raises(s):
    q = gm.quat_from_euler([10.0, 20.0, 30.0])
    m = trs([1, 2, 3], q, s)
    nm = normal_matrix(m)
    assert np.all(np.isfinite(nm))
    if s == (0, 1, 1):
        # A surface flattened onto the plane x = 0 (object space) faces along the rotated x axis.
        got = nm @ np.array([0.3, 0.2, 0.1])
        np.testing.assert_allclose(got / np.linalg.norm(got), gm.quat_to_matrix3(q)[:, 0], atol=1e-15)
    with pytest.raises(ValueError, match="singular") as err:
        invert_affine(m)
    assert "m " in str(err.value)


def test_invert_affine_round_trip_and_rejects_projective():
    m = trs([1, -2, 3], gm.quat_from_euler([5.0, 60.0, -20.0]), [2.0, 0.5, -3.0])
    np.testing.assert_allclose(invert_affine(m) @ m, np.eye(4), atol=1e-15)
    with pytest.raises(ValueError, match="affine"):
        invert_affine(perspective(60.0, 1.0, 0.1, 10.0))


def _assert_camera_rotation(view: np.ndarray) -> None:
    r = view[:3, :3]
    assert np.all(np.isfinite(view))
    # Orthonormal, right-handed: 1e-15.
    np.testing.assert_allclose(r @ r.T, np.eye(3), atol=1e-15)
    assert abs(np.linalg.det(r) - 1.0) < 1e-15


@FAST
@given(vectors, vectors)
def test_look_at_puts_target_on_the_minus_z_axis(eye, target):
    distance = np.linalg.norm(target - eye)
    if distance < 1e-3:
        return
    view = look_at(eye, target)
    _assert_camera_rotation(view)
    # Eye goes to the origin, target to (0, 0, -distance); error relative to the coordinates, 1e-13.
    size = 1.0 + np.abs(eye).max() + np.abs(target).max()
    np.testing.assert_allclose(view @ np.r_[eye, 1.0], [0, 0, 0, 1], atol=1e-13 * size)
    np.testing.assert_allclose(view @ np.r_[target, 1.0], [0, 0, -distance, 1], atol=1e-13 * size)
    # The camera quaternion is the inverse of the view rotation.
    q = look_at_rotation(eye, target)
    np.testing.assert_allclose(gm.quat_to_matrix3(q), view[:3, :3].T, atol=1e-14)


@pytest.mark.parametrize("direction", [(0.0, -1.0, 0.0), (0.0, 1.0, 0.0), (0.0, -1.0, 1e-9), (1e-8, 1.0, 0.0)])
def test_look_at_with_up_parallel_to_forward_is_finite_and_deterministic(direction):
    eye = np.array([1.0, 2.0, 3.0])
    target = eye + 5.0 * np.array(direction)
    view = look_at(eye, target, up=(0.0, 1.0, 0.0))
    _assert_camera_rotation(view)
    np.testing.assert_allclose(view @ np.r_[target, 1.0], [0, 0, -5.0, 1], atol=1e-14)
    # Looking straight down the top of the picture is world -Z, looking straight up it is +Z (1e-8).
    expected_up = np.sign(direction[1]) * np.array([0.0, 0.0, 1.0])
    np.testing.assert_allclose(view[1, :3], expected_up, atol=1e-8)
    assert np.array_equal(view, look_at(eye, target, up=(0.0, 1.0, 0.0)))
    assert np.all(np.isfinite(look_at_rotation(eye, target, up=(0.0, 1.0, 0.0))))


def test_look_at_errors_name_the_parameter():
    with pytest.raises(ValueError, match="target"):
        look_at([1, 2, 3], [1, 2, 3])
    with pytest.raises(ValueError, match="target"):
        look_at_rotation([0, 0, 0], [0, 0, 0], (0, 1, 0))
    with pytest.raises(ValueError, match="up"):
        look_at([0, 0, 0], [0, 0, -1], up=(0, 0, 0))
    with pytest.raises(ValueError, match="eye"):
        look_at([0, math.nan, 0], [0, 0, -1])


# --- projections -------------------------------------------------------------------------------------------

DEPTH_CASES = [("opengl", False), ("webgpu", False), ("opengl", True), ("webgpu", True)]


def test_depth_range_names_and_tuples():
    assert depth_range("opengl") == DepthRange(-1.0, 1.0)
    assert depth_range("WebGPU") == (0.0, 1.0)
    assert depth_range((0.25, 0.75)) == (0.25, 0.75)
    for bad in ("directx", (1.0, 0.0), (0.0, math.inf), (1.0,)):
        with pytest.raises(ValueError, match="depth_range"):
            depth_range(bad)


@pytest.mark.parametrize(("name", "reverse"), DEPTH_CASES)
def test_perspective_maps_near_and_far_to_the_depth_range_ends(name, reverse):
    near, far = 1e-4, 1e7
    lo, hi = depth_range(name)
    d_near, d_far = (hi, lo) if reverse else (lo, hi)
    m = perspective(60.0, 16.0 / 9.0, near, far, depth_range=name, reverse_z=reverse)
    z = ndc(m, np.array([[0.0, 0.0, -near], [0.0, 0.0, -far]]))[:, 2]
    # float64 with 1e11 between near and far: ends within 1e-12 (a few eps of the range size 1 or 2).
    assert abs(z[0] - d_near) < 1e-12
    assert abs(z[1] - d_far) < 1e-12
    # Depth is strictly monotonic over 2000 log-spaced distances from near to far, all inside the range.
    depths = ndc(m, np.c_[np.zeros((2000, 2)), -np.geomspace(near, far, 2000)])[:, 2]
    assert np.all(np.isfinite(depths))
    steps = np.diff(depths) * (-1.0 if reverse else 1.0)
    assert np.all(steps > 0.0)
    assert np.all((depths >= lo - 1e-12) & (depths <= hi + 1e-12))
    # The frustum edges map to x, y = +-1: a point on the top edge at distance 10 has y_ndc = 1 (1e-14).
    top = 10.0 * math.tan(math.radians(30.0))
    right = top * 16.0 / 9.0
    xy = ndc(m, np.array([[right, top, -10.0]]))[0, :2]
    np.testing.assert_allclose(xy, [1.0, 1.0], atol=1e-14)


@pytest.mark.parametrize(("name", "reverse"), DEPTH_CASES)
def test_perspective_with_infinite_far_plane(name, reverse):
    near = 1e-4
    lo, hi = depth_range(name)
    d_near, d_far = (hi, lo) if reverse else (lo, hi)
    m = perspective(45.0, 1.0, near, math.inf, depth_range=name, reverse_z=reverse)
    assert np.all(np.isfinite(m))
    distances = np.geomspace(near, 1e300, 500)
    depths = ndc(m, np.c_[np.zeros((500, 2)), -distances])[:, 2]
    assert np.all(np.isfinite(depths))
    assert abs(depths[0] - d_near) < 1e-12
    # Approaches the far end as 1/distance: within 1e-12 at 1e300 (only rounding left).
    assert abs(depths[-1] - d_far) < 1e-12
    assert np.all(np.diff(depths) * (-1.0 if reverse else 1.0) >= 0.0)


def test_reverse_z_infinite_far_keeps_float32_depth_strictly_monotonic():
    # The GPU computes clip coordinates in float32; with reverse-Z and an infinite far plane z_ndc = near / d,
    # which float32 resolves for every one of these 1000 distances from 1e-4 to 1e7.
    m = perspective(60.0, 1.0, 1e-4, math.inf, depth_range="webgpu", reverse_z=True).astype(np.float32)
    d = np.geomspace(1e-4, 1e7, 1000).astype(np.float32)
    points = np.c_[np.zeros((1000, 2), np.float32), -d, np.ones(1000, np.float32)]
    clip = points @ m.T
    depth = (clip[:, 2] / clip[:, 3]).astype(np.float32)
    assert depth.dtype == np.float32
    assert np.all(np.diff(depth) < 0.0)
    assert abs(depth[0] - 1.0) < 1e-6  # float32 rounding


@pytest.mark.parametrize(
    ("kwargs", "name"),
    [
        ({"fovy_degrees": 0.0}, "fovy_degrees"),
        ({"fovy_degrees": 180.0}, "fovy_degrees"),
        ({"fovy_degrees": -30.0}, "fovy_degrees"),
        ({"fovy_degrees": math.nan}, "fovy_degrees"),
        ({"aspect": 0.0}, "aspect"),
        ({"aspect": -1.5}, "aspect"),
        ({"aspect": math.inf}, "aspect"),
        ({"aspect": math.nan}, "aspect"),
        ({"near": 0.0}, "near"),
        ({"near": -0.1}, "near"),
        ({"near": math.inf}, "near"),
        ({"far": 0.1}, "far"),
        ({"far": 0.05}, "far"),
        ({"far": math.nan}, "far"),
        ({"depth_range": "vulkan"}, "depth_range"),
    ],
)
def test_degenerate_perspective_parameters_raise_naming_them(kwargs, name):
    args = {"fovy_degrees": 60.0, "aspect": 1.5, "near": 0.1, "far": 100.0} | kwargs
    with pytest.raises(ValueError, match=name):
        perspective(**args)


@pytest.mark.parametrize(
    ("kwargs", "name"),
    [
        ({"right": -1.0}, "right"),
        ({"top": -2.0}, "top"),
        ({"far": 0.5}, "far"),
        ({"left": math.inf}, "left"),
        ({"near": math.nan}, "near"),
    ],
)
def test_degenerate_orthographic_parameters_raise_naming_them(kwargs, name):
    args = {"left": -1.0, "right": 1.0, "bottom": -2.0, "top": 2.0, "near": 0.5, "far": 50.0} | kwargs
    with pytest.raises(ValueError, match=name):
        orthographic(**args)


@pytest.mark.parametrize(("name", "reverse"), DEPTH_CASES)
def test_orthographic_maps_box_corners_to_the_ndc_box(name, reverse):
    left, right, bottom, top, near, far = -3.0, 5.0, -1.0, 2.5, 0.25, 1e4
    lo, hi = depth_range(name)
    d_near, d_far = (hi, lo) if reverse else (lo, hi)
    m = orthographic(left, right, bottom, top, near, far, depth_range=name, reverse_z=reverse)
    corners = np.array([[x, y, -z] for x in (left, right) for y in (bottom, top) for z in (near, far)])
    expected = np.array([[x, y, z] for x in (-1.0, 1.0) for y in (-1.0, 1.0) for z in (d_near, d_far)])
    # Affine with entries ~1e-4..1e4: 1e-12 absolute.
    np.testing.assert_allclose(ndc(m, corners), expected, atol=1e-12)


@pytest.mark.parametrize("n", [1, 3, 8, 9, 40])
def test_trs_batch_gives_the_same_matrices_for_few_and_many_entities(n):
    """Up to 8 matrices TRSBatch computes in plain floats, above that in numpy: both give the same bits as
    building the matrices one by one (non-unit quaternions, mirrored and tiny/huge scales included)."""
    from gandalf_core.math import TRSBatch, trs

    rng = np.random.default_rng(n)
    t = rng.normal(size=(n, 3)) * 1e3
    q = rng.normal(size=(n, 4)) * 3.0
    s = rng.normal(size=(n, 3)) * np.array([1e-6, 1.0, 1e6])
    batched = TRSBatch()(t, q, s, out=np.empty((n, 4, 4)))
    one_by_one = np.array([trs(t[i], q[i] / np.linalg.norm(q[i]), s[i]) for i in range(n)])
    np.testing.assert_allclose(batched, one_by_one, rtol=1e-12, atol=1e-12 * np.abs(one_by_one).max())
    np.testing.assert_array_equal(batched, TRSBatch()(t, q, s))  # the general numpy path, bit for bit


def test_trs_batch_refuses_a_zero_quaternion_among_few():
    from gandalf_core.math import TRSBatch

    q = np.array([[1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 0.0]])
    with pytest.raises(ValueError, match="zero quaternion"):
        TRSBatch()(np.zeros((2, 3)), q, np.ones((2, 3)), out=np.empty((2, 4, 4)))
