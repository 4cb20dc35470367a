"""The components of step 04: a simple orbit camera and a camera placed by a look-at."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from gandalf_core import Component


class OrbitCameraComponent(Component):
    """An eye on a sphere around ``target``: ``distance`` away, at ``yaw`` and ``pitch`` degrees.

    yaw = pitch = 0 puts the eye on the +Z side of the target. A left-button drag of one pixel turns
    ``sensitivity`` degrees; one scroll step up multiplies the distance by ``zoom_factor``. Pitch stays in
    [min_pitch, max_pitch], distance in [min_distance, max_distance].
    """

    def __init__(
        self,
        target: Sequence[float] = (0.0, 0.0, 0.0),
        distance: float = 8.0,
        yaw: float = 0.0,
        pitch: float = 20.0,
        *,
        sensitivity: float = 0.5,
        zoom_factor: float = 0.9,
        min_pitch: float = -85.0,
        max_pitch: float = 85.0,
        min_distance: float = 1.0,
        max_distance: float = 50.0,
    ) -> None:
        self.target = np.asarray(target, dtype=np.float64)
        self.distance = float(distance)
        self.yaw = float(yaw)
        self.pitch = float(pitch)
        self.sensitivity = float(sensitivity)
        self.zoom_factor = float(zoom_factor)
        self.min_pitch = float(min_pitch)
        self.max_pitch = float(max_pitch)
        self.min_distance = float(min_distance)
        self.max_distance = float(max_distance)


class LookAtComponent(Component):
    """Place the entity's camera at ``eye``, looking at ``target`` with its top towards ``up``."""

    def __init__(
        self,
        eye: Sequence[float],
        target: Sequence[float] = (0.0, 0.0, 0.0),
        up: Sequence[float] = (0.0, 1.0, 0.0),
    ) -> None:
        self.eye = np.asarray(eye, dtype=np.float64)
        self.target = np.asarray(target, dtype=np.float64)
        self.up = np.asarray(up, dtype=np.float64)
