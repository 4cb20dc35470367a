"""The components of step 05: plain data for spinning, falling, springs, re-parenting and the house.

As in the paper, a component holds data only; the systems in ``systems.py`` (and the house exercise) give
them behaviour. Vectors are stored as float64 numpy arrays.
"""

from __future__ import annotations

import uuid
from collections.abc import Sequence

import numpy as np

from gandalf_core import Component

INTEGRATORS = ("explicit_euler", "semi_implicit_euler", "rk4", "implicit_euler")


def _vector(owner: str, field: str, value: Sequence[float]) -> np.ndarray:
    arr = np.asarray(value, dtype=np.float64)
    if arr.shape != (3,) or not np.all(np.isfinite(arr)):
        raise ValueError(f"{owner}.{field} must be 3 finite floats, got {value!r}")
    return arr.copy()


class SpinComponent(Component):
    """Turn about the entity's own ``axis`` at ``speed`` degrees per second."""

    def __init__(self, axis: Sequence[float] = (0.0, 1.0, 0.0), speed: float = 45.0) -> None:
        self.axis = _vector("SpinComponent", "axis", axis)
        if not np.any(self.axis):
            raise ValueError("SpinComponent.axis must not be the zero vector")
        self.speed = float(speed)


class GravityComponent(Component):
    """A falling body: ``gravity`` (m/s², pointing down when positive), its velocity, and a floor to bounce on.

    ``position``/``previous`` are the simulated states the GravitySystem interpolates between; they are
    taken from the entity's Transform when the system first sees the entity.
    """

    def __init__(
        self,
        gravity: float = 9.81,
        velocity: Sequence[float] = (0.0, 0.0, 0.0),
        floor: float | None = None,
        restitution: float = 0.8,
    ) -> None:
        if not 0.0 <= restitution <= 1.0:
            raise ValueError(f"GravityComponent.restitution must lie in [0, 1], got {restitution!r}")
        self.gravity = float(gravity)
        self.velocity = _vector("GravityComponent", "velocity", velocity)
        self.floor = None if floor is None else float(floor)
        self.restitution = float(restitution)
        self.position = np.zeros(3)
        self.previous = np.zeros(3)


class SpringComponent(Component):
    """A mass ``mass`` on a zero-length spring of stiffness ``stiffness`` towards ``rest``, with damping.

    ``integrator`` picks the method (one of :data:`INTEGRATORS`). A state that runs away (farther than
    ``reset_distance`` from rest) is put back to its start and counted in ``resets``, so an unstable
    integrator shows its blow-up again and again instead of producing infinities.
    """

    def __init__(
        self,
        rest: Sequence[float],
        stiffness: float = 40.0,
        mass: float = 1.0,
        damping: float = 0.2,
        integrator: str = "semi_implicit_euler",
        velocity: Sequence[float] = (0.0, 0.0, 0.0),
        reset_distance: float = 4.0,
    ) -> None:
        if integrator not in INTEGRATORS:
            raise ValueError(f"SpringComponent.integrator must be one of {INTEGRATORS}, got {integrator!r}")
        if not (stiffness >= 0 and mass > 0 and damping >= 0):
            raise ValueError(
                f"SpringComponent needs stiffness >= 0, mass > 0, damping >= 0; got {stiffness}, {mass}, {damping}"
            )
        self.rest = _vector("SpringComponent", "rest", rest)
        self.stiffness = float(stiffness)
        self.mass = float(mass)
        self.damping = float(damping)
        self.integrator = integrator
        self.velocity = _vector("SpringComponent", "velocity", velocity)
        self.reset_distance = float(reset_distance)
        self.resets = 0
        self.position = np.zeros(3)
        self.previous = np.zeros(3)
        self.start = np.zeros(3)


class ReparentOnKeyComponent(Component):
    """Pressing ``key`` swaps the entity's parent with ``other_parent``, keeping its world pose."""

    def __init__(self, other_parent: uuid.UUID | None, key: str = "M") -> None:
        self.other_parent = other_parent
        self.key = key.upper()


class HouseRotationComponent(Component):
    """The house turns about its y-axis at ``speed`` degrees per second; ``pause_key`` toggles ``paused``."""

    def __init__(self, speed: float = 45.0, angle: float = 0.0, paused: bool = False, pause_key: str = "P") -> None:
        self.speed = float(speed)
        self.angle = float(angle)  # degrees turned so far
        self.paused = bool(paused)
        self.pause_key = pause_key.upper()
