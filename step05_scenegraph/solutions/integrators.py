"""Reference solution of the integrator exercise (the step's systems and study use these too)."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

State = tuple[np.ndarray, np.ndarray]
Acceleration = Callable[[np.ndarray, np.ndarray], np.ndarray]


def semi_implicit_euler_step(x: np.ndarray, v: np.ndarray, accel: Acceleration, dt: float) -> State:
    """Symplectic Euler: the velocity first (``v += a(x, v) dt``), then the position with the NEW velocity."""
    v_new = v + accel(x, v) * dt
    return x + v_new * dt, v_new


def rk4_step(x: np.ndarray, v: np.ndarray, accel: Acceleration, dt: float) -> State:
    """Classical fourth-order Runge-Kutta on the first-order system ``x' = v, v' = a(x, v)``."""
    k1x, k1v = v, accel(x, v)
    k2x, k2v = v + 0.5 * dt * k1v, accel(x + 0.5 * dt * k1x, v + 0.5 * dt * k1v)
    k3x, k3v = v + 0.5 * dt * k2v, accel(x + 0.5 * dt * k2x, v + 0.5 * dt * k2v)
    k4x, k4v = v + dt * k3v, accel(x + dt * k3x, v + dt * k3v)
    return (
        x + dt / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x),
        v + dt / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v),
    )
