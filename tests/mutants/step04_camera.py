"""Mutants of step 04: ``perspective``, ``look_at`` and ``OrbitCameraSystem``."""

from __future__ import annotations

import math

import numpy as np

from gandalf_tools.grading.mutants import Mutant, mutant, patch

STEP = "step04_camera"
MUTANTS: list[Mutant] = []


# --- perspective -----------------------------------------------------------------------------------


def _perspective(pkg, *, focal=None, aspect_times=False, depth=None, w_sign=-1.0, checks=True):
    original = pkg.projection.perspective
    from gandalf_core.math import depth_range as resolve

    def perspective(fovy_deg, aspect, near, far, depth_range="opengl"):
        if checks:
            original(fovy_deg, aspect, near, far, depth_range)
        lo, hi = depth if depth is not None else resolve(depth_range)
        f = focal(fovy_deg) if focal else 1.0 / math.tan(math.radians(fovy_deg) / 2.0)
        a = -(hi * far - lo * near) / (far - near)
        b = -(hi - lo) * far * near / (far - near)
        return np.array(
            [
                [f * aspect if aspect_times else f / aspect, 0.0, 0.0, 0.0],
                [0.0, f, 0.0, 0.0],
                [0.0, 0.0, a, b],
                [0.0, 0.0, w_sign, 0.0],
            ]
        )

    patch(pkg, "projection.perspective", perspective)


for _name, _text, _slips in [
    ("degrees", "tan of the angle in degrees (no conversion to radians)",
     {"focal": lambda fov: 1.0 / math.tan(fov / 2.0)}),
    ("full-angle", "tan(fovy) instead of tan(fovy / 2)", {"focal": lambda fov: 1.0 / math.tan(math.radians(fov))}),
    ("aspect-times", "multiplies x by the aspect instead of dividing", {"aspect_times": True}),
    ("opengl-only", "ignores depth_range: always [-1, 1]", {"depth": (-1.0, 1.0)}),
    ("left-handed-w", "w_clip = +z (a left-handed camera looking down +Z)", {"w_sign": 1.0}),
    ("no-checks", "no argument checks (far <= near, fovy 180, ... go through)", {"checks": False}),
]:
    mutant(MUTANTS, STEP, "perspective", _name, _text)(lambda pkg, _s=_slips: _perspective(pkg, **_s))


@mutant(MUTANTS, STEP, "perspective", "inf-passes", "checks ranges with comparisons only: inf passes far > near "
        "and aspect > 0 (NaN entries, no ValueError)")
def _(pkg):
    original = pkg.projection.perspective

    def perspective(fovy_deg, aspect, near, far, depth_range="opengl"):
        finite = [v if math.isfinite(v) else 1e300 for v in (fovy_deg, aspect, near, far)]
        original(*finite, depth_range)  # the range checks as the reference makes them
        return _unchecked(fovy_deg, aspect, near, far, depth_range)

    patch(pkg, "projection.perspective", perspective)


def _unchecked(fovy_deg, aspect, near, far, depth_range):
    from gandalf_core.math import depth_range as resolve

    lo, hi = resolve(depth_range)
    f = 1.0 / math.tan(math.radians(fovy_deg) / 2.0)
    with np.errstate(all="ignore"):
        a = np.float64(-(hi * far - lo * near)) / np.float64(far - near)
        b = np.float64(-(hi - lo) * far * near) / np.float64(far - near)
    return np.array([[f / aspect, 0, 0, 0], [0, f, 0, 0], [0, 0, a, b], [0, 0, -1.0, 0]], dtype=np.float64)



# --- look_at ---------------------------------------------------------------------------------------


def _look_at(
    pkg,
    *,
    left_handed=False,
    untransformed_eye=False,
    inverse=False,
    normalise_right=True,
    transpose=False,
    checks=True,
):
    original = pkg.projection.look_at

    def look_at(eye, target, up=(0.0, 1.0, 0.0)):
        if checks:
            original(eye, target, up)
        e = np.asarray(eye, float)
        f = np.asarray(target, float) - e
        f /= np.linalg.norm(f)
        u = np.asarray(up, float)
        r = np.cross(u, f) if left_handed else np.cross(f, u)
        if normalise_right:
            r /= np.linalg.norm(r)
        true_up = np.cross(r, f)
        rot = np.array([r, true_up, -f])
        if transpose:
            rot = rot.T
        view = np.eye(4)
        view[:3, :3] = rot
        view[:3, 3] = -e if untransformed_eye else -rot @ e
        return np.linalg.inv(view) if inverse else view

    patch(pkg, "projection.look_at", look_at)


for _name, _text, _slips in [
    ("left-handed", "right = up x forward (the other handedness)", {"left_handed": True}),
    ("eye-not-rotated", "translation -eye, not rotated into camera space", {"untransformed_eye": True}),
    ("camera-to-world", "returns the camera's model matrix, not its inverse", {"inverse": True}),
    ("right-not-normalised", "forgets to normalise right (up not at 90 degrees)", {"normalise_right": False}),
    ("columns-for-rows", "r, u, -f as columns instead of rows (transposed rotation)", {"transpose": True}),
    ("no-checks", "no check for target == eye or a parallel up", {"checks": False}),
]:
    mutant(MUTANTS, STEP, "look_at", _name, _text)(lambda pkg, _s=_slips: _look_at(pkg, **_s))


# --- OrbitCameraSystem -----------------------------------------------------------------------------


def _orbit(pkg, **slips):
    base = pkg.orbit.OrbitCameraSystem
    from gandalf_core.math import look_at_rotation

    class OrbitCameraSystem(base):
        def on_update_system(self, ts):
            app = self.scene.app
            dx = dy = scroll = 0.0
            if app is not None:
                if slips.get("any_button") or 0 in app.input.buttons_down:
                    if slips.get("any_button") and not app.input.buttons_down:
                        dx = dy = 0.0
                    else:
                        dx, dy = app.input.mouse_delta()
                scroll = app.input.scroll_delta()
            for orbit, transform in self.components:
                orbit.yaw += (1 if slips.get("yaw_sign") else -1) * dx * orbit.sensitivity
                pitch = orbit.pitch + dy * orbit.sensitivity
                orbit.pitch = (
                    pitch if slips.get("no_pitch_clamp") else float(np.clip(pitch, orbit.min_pitch, orbit.max_pitch))
                )
                distance = orbit.distance * orbit.zoom_factor ** (-scroll if slips.get("zoom_sign") else scroll)
                orbit.distance = (
                    distance
                    if slips.get("no_zoom_clamp")
                    else float(np.clip(distance, orbit.min_distance, orbit.max_distance))
                )
                if slips.get("radians"):
                    yaw, pitch = orbit.yaw, orbit.pitch
                else:
                    yaw, pitch = math.radians(orbit.yaw), math.radians(orbit.pitch)
                if slips.get("yaw_from_x"):
                    d = np.array([math.cos(pitch) * math.cos(yaw), math.sin(pitch), math.cos(pitch) * math.sin(yaw)])
                else:
                    d = np.array([math.cos(pitch) * math.sin(yaw), math.sin(pitch), math.cos(pitch) * math.cos(yaw)])
                target = np.asarray(orbit.target, float)
                eye = (np.zeros(3) if slips.get("origin") else target) + orbit.distance * d
                transform.translation = eye
                if not slips.get("no_rotation"):
                    transform.quaternion = look_at_rotation(eye, target)

    patch(pkg, "orbit.OrbitCameraSystem", OrbitCameraSystem)


for _name, _text, _slips in [
    ("radians", "uses yaw and pitch (degrees) as radians", {"radians": True}),
    ("yaw-sign", "yaw += dx (the orbit turns the wrong way)", {"yaw_sign": True}),
    ("no-pitch-clamp", "pitch not clamped (the camera flips over the pole)", {"no_pitch_clamp": True}),
    ("no-zoom-clamp", "distance not clamped to [min, max]", {"no_zoom_clamp": True}),
    ("zoom-sign", "scrolling zooms the wrong way", {"zoom_sign": True}),
    ("orbit-origin", "orbits the world origin, not the target", {"origin": True}),
    ("any-button", "turns while any mouse button is down", {"any_button": True}),
    ("yaw-from-x", "yaw measured from +X (sin and cos swapped)", {"yaw_from_x": True}),
    ("no-look-at", "moves the camera but never turns it to the target", {"no_rotation": True}),
]:
    mutant(MUTANTS, STEP, "OrbitCameraSystem", _name, _text)(lambda pkg, _s=_slips: _orbit(pkg, **_s))
