"""The integrators' system: damped springs, each advanced with the integrator its SpringComponent names.

It is a :class:`~step05_scenegraph.custom_systems.systems.FixedStepSystem`: integrators are stable and repeatable
only at a fixed ``dt``. A spring beyond its integrator's stability limit is announced when it is created; one
that runs away anyway is put back to its start (counted, and reported once), so the blow-up shows again and again.
"""

from __future__ import annotations

import warnings

import numpy as np

from gandalf_core import TransformComponent

from ..custom_systems.systems import FixedStepSystem
from .components import SpringComponent
from .methods import (
    STABLE_OMEGA_DT,
    explicit_euler_step,
    implicit_euler_spring_step,
    omega_dt,
    reference_step,
    spring_acceleration,
)

__all__ = ["SpringSystem"]


class SpringSystem(FixedStepSystem):
    """Damped springs, each advanced with the integrator its SpringComponent names."""

    def __init__(self, dt: float = 1.0 / 120.0) -> None:
        super().__init__([SpringComponent, TransformComponent], dt)
        self.steps = {
            "explicit_euler": explicit_euler_step,
            "semi_implicit_euler": reference_step("semi_implicit_euler_step"),
            "rk4": reference_step("rk4_step"),
        }

    def on_create_entity(self, entity, components) -> None:
        super().on_create_entity(entity, components)
        spring = components[0]
        spring.start = spring.position.copy()
        angle, limit = omega_dt(spring.stiffness, spring.mass, self.clock.dt), STABLE_OMEGA_DT[spring.integrator]
        if angle >= limit and spring.integrator != "explicit_euler":  # explicit Euler's growth is the lesson
            warnings.warn(f"spring {self.scene.describe(entity)}: omega*dt = {angle:.3g} at dt = {self.clock.dt:.4g} s "
                          f"is beyond {spring.integrator}'s stability limit {limit:.3g}: it will blow up "
                          "(use implicit_euler, a smaller dt, or a softer spring)", stacklevel=2)

    def step(self, body: SpringComponent, dt: float) -> None:
        x, v = body.position, body.velocity
        k, m, c = body.stiffness, body.mass, body.damping
        if body.integrator == "implicit_euler":
            x, v = implicit_euler_spring_step(x, v, k, m, c, dt, body.rest)
        else:
            x, v = self.steps[body.integrator](x, v, spring_acceleration(k, m, c, body.rest), dt)
        if not np.all(np.isfinite(x)) or np.linalg.norm(x - body.rest) > body.reset_distance:
            if body.resets == 0:  # the reset shows the blow-up again; it must not hide that there was one
                limit = STABLE_OMEGA_DT[body.integrator]
                why = "never stable for an undamped spring" if limit == 0.0 else f"stable below {limit:.3g}"
                warnings.warn(f"a spring with {body.integrator} (omega*dt = {omega_dt(k, m, dt):.3g}; {why}) ran "
                              "away and is put back to its start; SpringComponent.resets counts the resets",
                              stacklevel=2)
            x, v = body.start.copy(), np.zeros(3)
            body.previous = x.copy()
            body.resets += 1
        body.position, body.velocity = x, v

# Saved in USD scenes by name (the loader only builds classes registered like this).
