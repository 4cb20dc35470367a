"""Camera controllers every step can reuse: an orbit camera (drag to rotate, scroll to zoom) and a fly camera.

Both write the entity's TransformComponent (translation and quaternion, in the parent's space when the
camera has a parent); the render system turns that into the view matrix. Input comes from
``scene.app.input``; on a scene without an application there is no input and the controllers only keep
the transform in step with their component (no crash, no movement).

Angles are degrees (the edge convention); yaw turns about +Y, pitch tilts up (+) or down (-). Pitch is
clamped strictly inside (-90, 90) so the view direction never becomes parallel to the up axis, where a
look-at rotation is undefined.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from ..components import TransformComponent
from ..ecs import Component, System
from ..math import look_at_rotation, quat_from_euler, quat_rotate

LEFT_BUTTON = 0
RIGHT_BUTTON = 1
# Pitch limits may approach but never reach +-90 degrees (see the module docstring).
_PITCH_LIMIT = 89.9


def _finite(owner: str, name: str, value: float) -> float:
    v = float(value)
    if not math.isfinite(v):
        raise ValueError(f"{owner}.{name} must be a finite number, got {value!r}")
    return v


def _positive(owner: str, name: str, value: float) -> float:
    v = _finite(owner, name, value)
    if v <= 0.0:
        raise ValueError(f"{owner}.{name} must be > 0, got {value!r}")
    return v


def _pitch_limits(owner: str, min_pitch: float, max_pitch: float) -> tuple[float, float]:
    lo, hi = _finite(owner, "min_pitch", min_pitch), _finite(owner, "max_pitch", max_pitch)
    for name, v in (("min_pitch", lo), ("max_pitch", hi)):
        if abs(v) > _PITCH_LIMIT:
            raise ValueError(f"{owner}.{name} must lie in [-{_PITCH_LIMIT}, {_PITCH_LIMIT}] degrees, got {v!r}")
    if lo > hi:
        raise ValueError(f"{owner}.min_pitch ({lo!r}) must not exceed max_pitch ({hi!r})")
    return lo, hi


def _input_of(system: System) -> Any:
    """The application's Input, or None for a scene that no application runs (or while the editor's
    panels have the mouse: dragging a slider must not also turn the camera)."""
    app = system.scene.app if system.scene is not None else None
    if app is not None and getattr(app, "gui_wants_mouse", _never)():
        return None
    return getattr(app, "input", None)


def _never() -> bool:
    return False


class OrbitControllerComponent(Component):
    """An orbit around ``target`` at ``distance``; ``yaw``/``pitch`` in degrees place the eye.

    yaw = pitch = 0 puts the eye on the +Z side of the target (the default view direction -Z).
    ``sensitivity`` is degrees per pixel of mouse drag; each scroll step scales the distance by
    ``exp(-zoom_speed)`` (scrolling up zooms in), clamped to [min_distance, max_distance].
    """

    def __init__(self, target: Sequence[float] = (0.0, 0.0, 0.0), distance: float = 5.0, yaw: float = 0.0,
                 pitch: float = 20.0, *, sensitivity: float = 0.3, zoom_speed: float = 0.1, min_distance: float = 0.1,
                 max_distance: float = 1000.0, min_pitch: float = -89.0, max_pitch: float = 89.0) -> None:
        owner = "OrbitControllerComponent"
        self.target = np.asarray(target, dtype=np.float64)
        if self.target.shape != (3,) or not np.all(np.isfinite(self.target)):
            raise ValueError(f"{owner}.target must be a finite 3-vector, got {target!r}")
        self.min_distance = _positive(owner, "min_distance", min_distance)
        self.max_distance = _positive(owner, "max_distance", max_distance)
        if self.min_distance > self.max_distance:
            raise ValueError(f"{owner}.min_distance ({min_distance!r}) must not exceed max_distance ({max_distance!r})")
        self.min_pitch, self.max_pitch = _pitch_limits(owner, min_pitch, max_pitch)
        self.distance = float(np.clip(_positive(owner, "distance", distance), self.min_distance, self.max_distance))
        self.yaw = _finite(owner, "yaw", yaw)
        self.pitch = float(np.clip(_finite(owner, "pitch", pitch), self.min_pitch, self.max_pitch))
        self.sensitivity = _finite(owner, "sensitivity", sensitivity)
        self.zoom_speed = _finite(owner, "zoom_speed", zoom_speed)

    def eye(self) -> np.ndarray:
        """The eye position for the current yaw, pitch and distance."""
        yaw, pitch = math.radians(self.yaw), math.radians(self.pitch)
        offset = np.array([math.cos(pitch) * math.sin(yaw), math.sin(pitch), math.cos(pitch) * math.cos(yaw)])
        return self.target + self.distance * offset


def _drag(system: System, button: int) -> tuple[Any, float, float]:
    """The app's input (None without an app) and the mouse's motion while ``button`` is held, else (0, 0)."""
    inp = _input_of(system)
    held = inp is not None and button in inp.buttons_down
    dx, dy = inp.mouse_delta() if held else (0.0, 0.0)
    return inp, dx, dy


class OrbitControllerSystem(System):
    """Left-button drag orbits (right = the camera swings left, "grabbing" the world), scroll zooms."""

    def __init__(self) -> None:
        super().__init__([OrbitControllerComponent, TransformComponent])

    def on_update_system(self, ts: float) -> None:
        inp, dx, dy = _drag(self, LEFT_BUTTON)
        scroll = inp.scroll_delta() if inp is not None else 0.0
        for orbit, transform in self.components:
            # Screen y grows downwards: dragging down lifts the eye, as if pulling the world down.
            orbit.yaw = math.remainder(orbit.yaw - dx * orbit.sensitivity, 360.0)
            orbit.pitch = float(np.clip(orbit.pitch + dy * orbit.sensitivity, orbit.min_pitch, orbit.max_pitch))
            if scroll:
                zoomed = orbit.distance * math.exp(-orbit.zoom_speed * scroll)
                orbit.distance = float(np.clip(zoomed, orbit.min_distance, orbit.max_distance))
            eye = orbit.eye()
            transform.translation = eye
            transform.quaternion = look_at_rotation(eye, orbit.target)


class FlyControllerComponent(Component):
    """A free-flying camera: ``speed`` world units per second, ``sensitivity`` degrees per pixel.

    ``yaw``/``pitch`` (degrees) are the heading; left as None they are taken from the entity's
    rotation on the first update, so a camera placed with ``look_at_rotation`` keeps its view.
    """

    def __init__(
        self,
        speed: float = 3.0,
        sensitivity: float = 0.2,
        *,
        yaw: float | None = None,
        pitch: float | None = None,
        min_pitch: float = -89.0,
        max_pitch: float = 89.0,
    ) -> None:
        owner = "FlyControllerComponent"
        self.speed = _finite(owner, "speed", speed)
        self.sensitivity = _finite(owner, "sensitivity", sensitivity)
        self.min_pitch, self.max_pitch = _pitch_limits(owner, min_pitch, max_pitch)
        self.yaw = None if yaw is None else _finite(owner, "yaw", yaw)
        self.pitch = None if pitch is None else float(np.clip(_finite(owner, "pitch", pitch), min_pitch, max_pitch))


# Key -> direction in the camera's local frame (it looks down -Z, +Y is its top).
FLY_KEYS = {
    "W": (0.0, 0.0, -1.0),
    "S": (0.0, 0.0, 1.0),
    "A": (-1.0, 0.0, 0.0),
    "D": (1.0, 0.0, 0.0),
    "E": (0.0, 1.0, 0.0),
    "Q": (0.0, -1.0, 0.0),
}


class FlyControllerSystem(System):
    """WASD moves, E/Q rise/sink (in the camera's own frame, ``speed * ts`` per frame); right-drag turns."""

    def __init__(self) -> None:
        super().__init__([FlyControllerComponent, TransformComponent])

    def on_update_system(self, ts: float) -> None:
        inp, dx, dy = _drag(self, RIGHT_BUTTON)
        move = np.zeros(3)
        if inp is not None:
            for key, direction in FLY_KEYS.items():
                if inp.is_down(key):
                    move += direction
        length = float(np.linalg.norm(move))
        for fly, transform in self.components:
            if fly.yaw is None or fly.pitch is None:
                yaw, pitch = heading_of(transform.quaternion)
                fly.yaw = yaw if fly.yaw is None else fly.yaw
                fly.pitch = pitch if fly.pitch is None else fly.pitch
            # Mouse right turns right (yaw is counter-clockwise seen from above), mouse down looks down.
            fly.yaw = math.remainder(fly.yaw - dx * fly.sensitivity, 360.0)
            fly.pitch = float(np.clip(fly.pitch - dy * fly.sensitivity, fly.min_pitch, fly.max_pitch))
            q = quat_from_euler((fly.pitch, fly.yaw, 0.0))
            transform.quaternion = q
            if length > 0.0:
                # Normalised so that a diagonal (W + D) is not faster than a straight move.
                transform.translation = transform.translation + quat_rotate(q, move / length) * fly.speed * ts


def heading_of(quaternion: Sequence[float]) -> tuple[float, float]:
    """(yaw, pitch) in degrees of a camera rotation: where its -Z axis points; roll is dropped."""
    forward = quat_rotate(np.asarray(quaternion, dtype=np.float64), (0.0, 0.0, -1.0))
    pitch = math.degrees(math.asin(float(np.clip(forward[1], -1.0, 1.0))))
    yaw = math.degrees(math.atan2(-forward[0], -forward[2]))
    return yaw, pitch
