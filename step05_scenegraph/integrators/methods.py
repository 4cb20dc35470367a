"""Time integrators for a mass on a damped spring: a numerics lesson in float64.

The state is a position ``x`` and a velocity ``v`` (floats or numpy arrays of any shape); ``accel(x, v)``
returns the acceleration. One step advances the state by ``dt`` seconds:

* explicit (forward) Euler: first order, adds energy every step, unstable for any undamped oscillator;
* semi-implicit (symplectic) Euler: first order, keeps the energy bounded while ``omega * dt < 2``;
* classical Runge-Kutta (RK4): fourth order, bounded while ``omega * dt < 2 * sqrt(2)`` (about 2.83);
* implicit (backward) Euler for the linear damped spring: first order, stable for every k, m, c and dt,
  solved in closed form (no iteration) because the force is linear.

``damped_spring_exact`` is the exact solution the study measures every integrator against. The
semi-implicit Euler and RK4 steps are the exercise (``exercises/integrators.py``); the step's systems and
study use :func:`reference_step`: the reference answers in ``solutions/integrators.py``, or in a student's release
(no ``solutions/``) the student's own.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

State = tuple[np.ndarray, np.ndarray]
Acceleration = Callable[[np.ndarray, np.ndarray], np.ndarray]

#: The largest ``omega * dt`` (omega = sqrt(k / m)) at which each integrator keeps an undamped spring bounded:
#: explicit Euler never does, implicit Euler always does.
STABLE_OMEGA_DT = {
    "explicit_euler": 0.0,
    "semi_implicit_euler": 2.0,
    "rk4": 2.0 * math.sqrt(2.0),
    "implicit_euler": math.inf,
}


def reference_step(name: str) -> Callable[..., State]:
    """The step's ``semi_implicit_euler_step`` or ``rk4_step``: the reference solution's, or where a student's
    release has no ``solutions/``, the student's own from ``exercises/integrators.py``."""
    from gandalf_core.app.cli import load_impl

    return getattr(load_impl(__package__.split(".")[0]), name)


def omega_dt(k: float, m: float, dt: float) -> float:
    """``sqrt(k / m) * dt``: the angle a spring turns through in one step, which decides its stability."""
    return math.sqrt(k / m) * dt


def _check_spring(k: float | np.ndarray, m: float | np.ndarray, c: float | np.ndarray) -> None:
    if type(k) is float and type(m) is float and type(c) is float:  # the common case, checked cheaply
        if math.isfinite(k + m + c) and k >= 0.0 and m > 0.0 and c >= 0.0:
            return
    # Arrays are allowed (one spring per element: the stiffness sweep runs many springs at once).
    for name, value, low_ok in (("stiffness k", k, True), ("mass m", m, False), ("damping c", c, True)):
        arr = np.asarray(value, dtype=np.float64)
        if not (np.all(np.isfinite(arr)) and np.all(arr >= 0.0 if low_ok else arr > 0.0)):
            raise ValueError(f"{name} must be finite and {'>= 0' if low_ok else '> 0'}, got {value!r}")


def spring_acceleration(k: float, m: float, c: float = 0.0, rest: float | np.ndarray = 0.0) -> Acceleration:
    """``a(x, v) = (-k (x - rest) - c v) / m``: Hooke's law plus viscous damping."""
    _check_spring(k, m, c)
    rest = np.asarray(rest, dtype=np.float64)

    def accel(x: np.ndarray, v: np.ndarray) -> np.ndarray:
        return (-k * (x - rest) - c * v) / m

    return accel


def spring_energy(x: np.ndarray, v: np.ndarray, k: float, m: float, rest: float | np.ndarray = 0.0) -> np.ndarray:
    """Kinetic plus potential energy ``m v^2 / 2 + k (x - rest)^2 / 2`` (summed over the last axis of vectors)."""
    x, v = np.asarray(x, np.float64), np.asarray(v, np.float64)
    e = 0.5 * m * v * v + 0.5 * k * (x - rest) ** 2
    return e.sum(axis=-1) if e.ndim else e



# --8<-- [start:explicit_euler]
def explicit_euler_step(x: np.ndarray, v: np.ndarray, accel: Acceleration, dt: float) -> State:
    """Forward Euler: both updates use the old state (``x += v dt``, ``v += a(x, v) dt``)."""
    a = accel(x, v)
    return x + v * dt, v + a * dt
# --8<-- [end:explicit_euler]


# --8<-- [start:implicit_euler]
def implicit_euler_spring_step(
    x: np.ndarray, v: np.ndarray, k: float, m: float, c: float, dt: float,
    rest: float | np.ndarray = 0.0,
) -> State:
    """Backward Euler for the linear damped spring, solved exactly.

    The update uses the forces at the END of the step:
    ``v1 = v0 + dt (-k (x1 - rest) - c v1) / m`` and ``x1 = x0 + dt v1``. Substituting ``x1``
    gives one linear equation for ``v1``:
    ``v1 (1 + dt c / m + dt^2 k / m) = v0 - dt k / m (x0 - rest)``.
    The divisor is >= 1, so the step never amplifies: the method is stable for every stiffness,
    mass, damping and time step (it damps too much).
    """
    _check_spring(k, m, c)
    if not (math.isfinite(dt) and dt >= 0.0):
        raise ValueError(f"time step dt must be a finite number >= 0, got {dt!r}")
    v_new = (v - dt * (k / m) * (x - rest)) / (1.0 + dt * c / m + dt * dt * k / m)
    return x + dt * v_new, v_new
# --8<-- [end:implicit_euler]


def damped_spring_exact(
    x0: float, v0: float, k: float, m: float, c: float, t: float | np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Exact ``(x(t), v(t))`` of ``m x'' + c x' + k x = 0`` (rest at 0), under-, critically or over-damped.

    With ``g = c / 2m`` and ``w2 = k/m - g^2``: ``x = e^{-g t} (x0 C(t) + (v0 + g x0) S(t))`` where
    ``C = cos(w t)``, ``S = sin(w t) / w`` for ``w2 > 0`` and their hyperbolic twins for ``w2 < 0``.
    ``S`` is written as ``t * sinc`` / ``expm1`` so that it stays accurate as ``w -> 0`` (critical damping),
    and the overdamped exponentials are combined before they could overflow.
    """
    _check_spring(k, m, c)
    t = np.asarray(t, dtype=np.float64)
    g = c / (2.0 * m)
    w2 = k / m - g * g
    b = v0 + g * x0
    if w2 >= 0.0:
        w = math.sqrt(w2)
        decay = np.exp(-g * t)
        ec = decay * np.cos(w * t)
        es = decay * t * np.sinc(w * t / math.pi)  # e^{-g t} sin(w t) / w, exact at w = 0
    else:
        w = math.sqrt(-w2)
        slow, fast = np.exp((w - g) * t), np.exp(-(w + g) * t)  # w < g: both decay, no overflow
        ec = 0.5 * (slow + fast)
        # e^{-g t} sinh(w t) / w: expm1 avoids the cancellation of slow - fast while w t is small.
        small = 2.0 * w * t < 1.0
        es = np.where(small, fast * np.expm1(np.minimum(2.0 * w * t, 1.0)) / (2.0 * w), (slow - fast) / (2.0 * w))
    x = x0 * ec + b * es
    v = -g * x + (b * ec - x0 * w2 * es)
    return x, v
