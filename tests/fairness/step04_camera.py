"""Correct alternatives of step 04: the projection from the frustum's bounds, the view matrix as the inverse of
the camera's placement, the orbit direction from a rotation matrix."""

from __future__ import annotations

import math

import numpy as np

from gandalf_tools.grading.fairness import alternative
from gandalf_tools.grading.mutants import Mutant, patch

STEP = "step04_camera"
ALTERNATIVES: list[Mutant] = []


@alternative(ALTERNATIVES, STEP, "perspective", "from-frustum-bounds",
             "top = near tan(fov / 2), right = top aspect, then the frustum matrix; the depth row by solving the 2x2 "
             "system")
def _(pkg):
    from gandalf_core.math import depth_range as resolve

    def perspective(fovy_deg, aspect, near, far, depth_range="opengl"):
        for name, value in (("fovy_deg", fovy_deg), ("aspect", aspect), ("near", near), ("far", far)):
            if not math.isfinite(value):
                raise ValueError(f"{name} is not finite: {value!r}")
        if not 0.0 < fovy_deg < 180.0:
            raise ValueError(f"fovy_deg must be in (0, 180), got {fovy_deg}")
        if aspect <= 0.0:
            raise ValueError(f"aspect must be > 0, got {aspect}")
        if near <= 0.0:
            raise ValueError(f"near must be > 0, got {near}")
        if far <= near:
            raise ValueError(f"far must exceed near, got {far}")
        lo, hi = resolve(depth_range)
        top = near * math.tan(math.radians(fovy_deg) / 2.0)
        right = top * aspect
        # z_ndc = (A z + B) / -z: A (-near) + B = lo near and A (-far) + B = hi far
        a, b = np.linalg.solve([[-near, 1.0], [-far, 1.0]], [lo * near, hi * far])
        return np.array([[near / right, 0, 0, 0], [0, near / top, 0, 0], [0, 0, a, b], [0, 0, -1, 0]], dtype=float)

    patch(pkg, "projection.perspective", perspective)


@alternative(ALTERNATIVES, STEP, "look_at", "inverse-of-placement",
             "builds the camera's placement (columns r, u, -f, eye) and inverts it with numpy")
def _(pkg):
    def look_at(eye, target, up=(0.0, 1.0, 0.0)):
        e, t, u = (np.asarray(x, dtype=float) for x in (eye, target, up))
        if np.allclose(t, e, rtol=0.0, atol=0.0):
            raise ValueError("target equals eye")
        f = (t - e) / np.linalg.norm(t - e)
        if np.linalg.norm(u) == 0.0:
            raise ValueError("up is zero")
        r = np.cross(f, u / np.linalg.norm(u))
        if np.linalg.norm(r) < 1e-6:
            raise ValueError("up is parallel to the view direction")
        r /= np.linalg.norm(r)
        placement = np.eye(4)
        placement[:3, 0], placement[:3, 1], placement[:3, 2], placement[:3, 3] = r, np.cross(r, f), -f, e
        return np.linalg.inv(placement)

    patch(pkg, "projection.look_at", look_at)


@alternative(ALTERNATIVES, STEP, "OrbitCameraSystem", "yaw-pitch-quaternion",
             "the camera turned by quat(y, yaw) · quat(x, -pitch) instead of look_at_rotation")
def _(pkg):
    from gandalf_core.math import quat_from_axis_angle, quat_mul

    base = pkg.orbit.OrbitCameraSystem

    class OrbitCameraSystem(base):
        def on_update_system(self, ts):
            super().on_update_system(ts)  # input, clamps and the eye as the reference
            for orbit, transform in self.components:
                yaw, pitch = math.radians(orbit.yaw), math.radians(orbit.pitch)
                transform.quaternion = quat_mul(quat_from_axis_angle((0.0, 1.0, 0.0), yaw),
                                                quat_from_axis_angle((1.0, 0.0, 0.0), -pitch))

    patch(pkg, "orbit.OrbitCameraSystem", OrbitCameraSystem)
