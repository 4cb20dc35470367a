"""Exercise: two integrators for ``x' = v, v' = accel(x, v)``.

The lesson's other integrators (explicit and implicit Euler) are in ``step05_scenegraph/integrators.py``.

Both take the position ``x``, the velocity ``v`` (floats or numpy arrays), the acceleration function
``accel(x, v)`` and the time step ``dt``, and return the new ``(x, v)``. They are graded numerically:
energy over 10,000 steps, and the order of convergence measured by halving ``dt``.
"""

from __future__ import annotations


# --8<-- [start:stubs]
def semi_implicit_euler_step(x, v, accel, dt):
    """Symplectic Euler: first ``v_new = v + accel(x, v) * dt``, then ``x_new = x + v_new * dt``.

    Using the NEW velocity for the position is the whole difference to explicit Euler, and it
    keeps the energy of an oscillator bounded instead of growing. Error order 1.
    """
    raise NotImplementedError("exercise: semi_implicit_euler_step")


def rk4_step(x, v, accel, dt):
    """Classical Runge-Kutta: four slope evaluations, weighted 1, 2, 2, 1 (error order 4).

    With the state ``y = (x, v)`` and ``f(y) = (v, accel(x, v))``: ``k1 = f(y)``,
    ``k2 = f(y + dt/2 k1)``, ``k3 = f(y + dt/2 k2)``, ``k4 = f(y + dt k3)``,
    ``y_new = y + dt/6 (k1 + 2 k2 + 2 k3 + k4)``.
    """
    raise NotImplementedError("exercise: rk4_step")
# --8<-- [end:stubs]
