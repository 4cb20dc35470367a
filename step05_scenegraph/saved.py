"""What step 05 saves in USD scenes: declared once, read by the final step's USD layer (``step07_advanced.usd``).

``COMPONENTS`` maps a component class to the fields a file holds; ``SYSTEMS`` a system class to the constructor
settings it is rebuilt with (a scene may name only these). Nothing here imports USD: the lessons stay free
of the persistence layer, and a file names classes, never code.
"""

from __future__ import annotations

from gandalf_core.app.cli import load_impl

from . import exercises
from .custom_systems.components import GravityComponent
from .custom_systems.systems import GravitySystem
from .hierarchy.components import ReparentOnKeyComponent
from .hierarchy.systems import ReparentSystem
from .house.components import HouseRotationComponent
from .integrators.components import SpringComponent
from .integrators.systems import SpringSystem

# The reference (the exercises again where a student's release has no solutions/).
_reference = load_impl(__package__)

COMPONENTS = {
    ReparentOnKeyComponent: ("other_parent", "key"),  # other_parent: an entity
    GravityComponent: ("gravity", "velocity", "floor", "restitution", "position", "previous"),
    SpringComponent: ("rest", "stiffness", "mass", "damping", "integrator", "velocity", "reset_distance", "resets",
                      "position", "previous", "start"),
    HouseRotationComponent: ("speed", "angle", "paused", "pause_key"),
}
SYSTEMS = {
    ReparentSystem: (),
    GravitySystem: (),
    SpringSystem: (),
    exercises.HouseRotationSystem: (),
    _reference.HouseRotationSystem: (),
}
