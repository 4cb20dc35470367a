"""The integrators' component: a mass on a damped spring, and which integrator advances it."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from gandalf_core import Component

from ..custom_systems.components import vector3

#: The integrators a SpringComponent can name, in the order the page teaches them.
INTEGRATORS = ("explicit_euler", "semi_implicit_euler", "rk4", "implicit_euler", "exact")


class SpringComponent(Component):
    """A mass ``mass`` on a zero-length spring of stiffness ``stiffness`` towards ``rest``, with damping.

    ``integrator`` picks the method (one of :data:`INTEGRATORS`). A state that runs away (farther than
    ``runaway_distance`` from rest, or not finite) stops where it was last bounded and records the simulated
    time in ``ran_away_at`` (-1: never): the blow-up stays in sight and is reported, never reset away.
    """

    def __init__(
        self,
        rest: Sequence[float],
        stiffness: float = 40.0,
        mass: float = 1.0,
        damping: float = 0.2,
        integrator: str = "semi_implicit_euler",
        velocity: Sequence[float] = (0.0, 0.0, 0.0),
        runaway_distance: float = 4.0,
    ) -> None:
        if integrator not in INTEGRATORS:
            raise ValueError(f"SpringComponent.integrator must be one of {INTEGRATORS}, got {integrator!r}")
        if not (stiffness >= 0 and mass > 0 and damping >= 0):
            raise ValueError(
                f"SpringComponent needs stiffness >= 0, mass > 0, damping >= 0; got {stiffness}, {mass}, {damping}"
            )
        self.rest = vector3("SpringComponent", "rest", rest)
        self.stiffness = float(stiffness)
        self.mass = float(mass)
        self.damping = float(damping)
        self.integrator = integrator
        self.velocity = vector3("SpringComponent", "velocity", velocity)
        self.runaway_distance = float(runaway_distance)
        self.ran_away_at = -1.0
        self.position = np.zeros(3)
        self.previous = np.zeros(3)
        self.start = np.zeros(3)

# Saved in USD scenes by name (the loader only builds classes registered like this).
