"""The custom component of step 05: a falling body's data (``systems.py`` gives it behaviour).

As in the paper, a component holds data only; a system gives it behaviour. Vectors are stored as float64 numpy
arrays, checked when the component is made (:func:`vector3`, which the integrators' SpringComponent uses too).
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from gandalf_core import Component


def vector3(owner: str, field: str, value: Sequence[float]) -> np.ndarray:
    """``value`` as a float64 copy, or a ValueError naming ``owner.field`` unless it is 3 finite floats."""
    arr = np.asarray(value, dtype=np.float64)
    if arr.shape != (3,) or not np.all(np.isfinite(arr)):
        raise ValueError(f"{owner}.{field} must be 3 finite floats, got {value!r}")
    return arr.copy()


# --8<-- [start:component]
class GravityComponent(Component):
    """A falling body: ``gravity`` (m/s², pointing down when positive), its velocity, and a floor
    to bounce on.

    ``position``/``previous`` are the simulated states the GravitySystem interpolates between;
    they are taken from the entity's Transform when the system first sees the entity.
    """

    def __init__(
        self,
        gravity: float = 9.81,
        velocity: Sequence[float] = (0.0, 0.0, 0.0),
        floor: float | None = None,
        restitution: float = 0.8,
    ) -> None:
        if not 0.0 <= restitution <= 1.0:
            raise ValueError(f"GravityComponent.restitution must lie in [0, 1], "
                             f"got {restitution!r}")
        self.gravity = float(gravity)
        self.velocity = vector3("GravityComponent", "velocity", velocity)
        self.floor = None if floor is None else float(floor)
        self.restitution = float(restitution)
        self.position = np.zeros(3)
        self.previous = np.zeros(3)
# --8<-- [end:component]

# Saved in USD scenes by name (the loader only builds classes registered like this).
