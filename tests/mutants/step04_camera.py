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


@mutant(MUTANTS, STEP, "perspective", "degrees", "tan of the angle in degrees (no conversion to radians)")
def _(pkg):
    _perspective(pkg, focal=lambda fov: 1.0 / math.tan(fov / 2.0))


@mutant(MUTANTS, STEP, "perspective", "full-angle", "tan(fovy) instead of tan(fovy / 2)")
def _(pkg):
    _perspective(pkg, focal=lambda fov: 1.0 / math.tan(math.radians(fov)))


@mutant(MUTANTS, STEP, "perspective", "aspect-times", "multiplies x by the aspect instead of dividing")
def _(pkg):
    _perspective(pkg, aspect_times=True)


@mutant(MUTANTS, STEP, "perspective", "opengl-only", "ignores depth_range: always [-1, 1]")
def _(pkg):
    _perspective(pkg, depth=(-1.0, 1.0))


@mutant(MUTANTS, STEP, "perspective", "left-handed-w", "w_clip = +z (a left-handed camera looking down +Z)")
def _(pkg):
    _perspective(pkg, w_sign=1.0)


@mutant(MUTANTS, STEP, "perspective", "no-checks", "no argument checks (far <= near, fovy 180, ... go through)")
def _(pkg):
    _perspective(pkg, checks=False)


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


@mutant(MUTANTS, STEP, "look_at", "left-handed", "right = up x forward (the other handedness)")
def _(pkg):
    _look_at(pkg, left_handed=True)


@mutant(MUTANTS, STEP, "look_at", "eye-not-rotated", "translation -eye, not rotated into camera space")
def _(pkg):
    _look_at(pkg, untransformed_eye=True)


@mutant(MUTANTS, STEP, "look_at", "camera-to-world", "returns the camera's model matrix, not its inverse")
def _(pkg):
    _look_at(pkg, inverse=True)


@mutant(MUTANTS, STEP, "look_at", "right-not-normalised", "forgets to normalise right (up not at 90 degrees)")
def _(pkg):
    _look_at(pkg, normalise_right=False)


@mutant(MUTANTS, STEP, "look_at", "columns-for-rows", "r, u, -f as columns instead of rows (transposed rotation)")
def _(pkg):
    _look_at(pkg, transpose=True)


@mutant(MUTANTS, STEP, "look_at", "no-checks", "no check for target == eye or a parallel up")
def _(pkg):
    _look_at(pkg, checks=False)


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


@mutant(MUTANTS, STEP, "OrbitCameraSystem", "radians", "uses yaw and pitch (degrees) as radians")
def _(pkg):
    _orbit(pkg, radians=True)


@mutant(MUTANTS, STEP, "OrbitCameraSystem", "yaw-sign", "yaw += dx (the orbit turns the wrong way)")
def _(pkg):
    _orbit(pkg, yaw_sign=True)


@mutant(MUTANTS, STEP, "OrbitCameraSystem", "no-pitch-clamp", "pitch not clamped (the camera flips over the pole)")
def _(pkg):
    _orbit(pkg, no_pitch_clamp=True)


@mutant(MUTANTS, STEP, "OrbitCameraSystem", "no-zoom-clamp", "distance not clamped to [min, max]")
def _(pkg):
    _orbit(pkg, no_zoom_clamp=True)


@mutant(MUTANTS, STEP, "OrbitCameraSystem", "zoom-sign", "scrolling zooms the wrong way")
def _(pkg):
    _orbit(pkg, zoom_sign=True)


@mutant(MUTANTS, STEP, "OrbitCameraSystem", "orbit-origin", "orbits the world origin, not the target")
def _(pkg):
    _orbit(pkg, origin=True)


@mutant(MUTANTS, STEP, "OrbitCameraSystem", "any-button", "turns while any mouse button is down")
def _(pkg):
    _orbit(pkg, any_button=True)


@mutant(MUTANTS, STEP, "OrbitCameraSystem", "yaw-from-x", "yaw measured from +X (sin and cos swapped)")
def _(pkg):
    _orbit(pkg, yaw_from_x=True)


@mutant(MUTANTS, STEP, "OrbitCameraSystem", "no-look-at", "moves the camera but never turns it to the target")
def _(pkg):
    _orbit(pkg, no_rotation=True)
