"""The custom systems of step 05: spin, gravity (done right), damped springs, re-parenting, scene switching.

The paper's gravity example moved the position by ``force * ts`` each frame, which is a constant speed, not
a fall. Here the velocity is integrated (``v += g dt``, then ``x += v dt``: semi-implicit Euler) on a fixed
time step, so the fall is the same at 30 or 300 frames per second.
"""

from __future__ import annotations

import math
import warnings

import numpy as np

from gandalf_core import System, TransformComponent
from gandalf_core.math import quat_from_axis_angle, quat_mul
from gandalf_core.systems.transform_system import set_parent_keep_world

from .components import GravityComponent, ReparentOnKeyComponent, SpinComponent, SpringComponent
from .fixed_step import FixedStep
from .integrators import (
    STABLE_OMEGA_DT,
    explicit_euler_step,
    implicit_euler_spring_step,
    omega_dt,
    spring_acceleration,
)
from .solutions.integrators import rk4_step, semi_implicit_euler_step

__all__ = [
    "GravitySystem",
    "ReparentSystem",
    "SceneSwitchSystem",
    "SpinSystem",
    "SpringSystem",
]


class SpinSystem(System):
    """Rotates every entity with a SpinComponent about its own axis (a per-entity system, as in the paper)."""

    def __init__(self) -> None:
        super().__init__([SpinComponent, TransformComponent])

    def on_update_entity(self, ts, entity, components) -> None:
        spin, transform = components
        turn = quat_from_axis_angle(spin.axis, math.radians(spin.speed * ts))
        # q * turn applies the turn first, in the entity's own frame: it spins about its own axis.
        transform.quaternion = quat_mul(transform.quaternion, turn)


class _FixedStepSystem(System):
    """A system that simulates at a fixed ``dt`` and shows the state interpolated to the frame time."""

    def __init__(self, component_types, dt: float) -> None:
        super().__init__(component_types)
        self.clock = FixedStep(dt)

    def on_update_system(self, ts: float) -> None:
        for _ in range(self.clock.advance(ts)):
            for body, _transform in self.components:
                body.previous = body.position.copy()
                self.step(body, self.clock.dt)
        alpha = self.clock.alpha
        for body, transform in self.components:
            transform.translation = body.previous + alpha * (body.position - body.previous)

    def on_create_entity(self, entity, components) -> None:
        body, transform = components
        body.position = np.array(transform.translation)
        body.previous = body.position.copy()

    def step(self, body, dt: float) -> None:
        raise NotImplementedError


class GravitySystem(_FixedStepSystem):
    """Falling bodies: velocity integration (semi-implicit Euler) and an optional bouncy floor."""

    def __init__(self, dt: float = 1.0 / 120.0) -> None:
        super().__init__([GravityComponent, TransformComponent], dt)

    def step(self, body: GravityComponent, dt: float) -> None:
        body.velocity[1] -= body.gravity * dt
        body.position = body.position + body.velocity * dt
        if body.floor is not None and body.position[1] < body.floor:
            # Reflect the penetration and the velocity; restitution < 1 loses energy at every bounce.
            body.position[1] = body.floor + (body.floor - body.position[1]) * body.restitution
            body.velocity[1] = -body.velocity[1] * body.restitution


class SpringSystem(_FixedStepSystem):
    """Damped springs, each advanced with the integrator its SpringComponent names."""

    def __init__(self, dt: float = 1.0 / 120.0) -> None:
        super().__init__([SpringComponent, TransformComponent], dt)

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
            step = {
                "explicit_euler": explicit_euler_step,
                "semi_implicit_euler": semi_implicit_euler_step,
                "rk4": rk4_step,
            }[body.integrator]
            x, v = step(x, v, spring_acceleration(k, m, c, body.rest), dt)
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


class ReparentSystem(System):
    """On a key press, moves an entity under its other parent without moving it in the world."""

    def __init__(self) -> None:
        super().__init__([ReparentOnKeyComponent])

    def on_update_entity(self, ts, entity, components) -> None:
        (swap,) = components
        app = self.scene.app
        if app is not None and app.input.pressed(swap.key):
            current = self.scene.parent_of(entity)
            set_parent_keep_world(self.scene, entity, swap.other_parent)
            swap.other_parent = current


class SceneSwitchSystem(System):
    """Reads the keyboard and asks the app to switch scenes (taking effect at the next frame).

    ``keys`` maps key names to scene names; ``cycle_key`` goes to the next scene in the app's order.
    """

    def __init__(self, keys: dict[str, str], cycle_key: str = "TAB") -> None:
        super().__init__([])
        self.keys = {k.upper(): v for k, v in keys.items()}
        self.cycle_key = cycle_key.upper()

    def on_update_system(self, ts: float) -> None:
        app = self.scene.app
        if app is None:
            return
        for key, scene_name in self.keys.items():
            if app.input.pressed(key):
                app.switch_scene(scene_name)
        if app.input.pressed(self.cycle_key):
            names = [s.name for s in app.scenes.scenes]
            app.switch_scene(names[(names.index(self.scene.name) + 1) % len(names)])
