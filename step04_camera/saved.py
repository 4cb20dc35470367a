"""What step 04 saves in USD scenes: declared once, read by the final step's USD layer (``step07_advanced.usd``).

``COMPONENTS`` maps a component class to the fields a file holds; ``SYSTEMS`` a system class to the constructor
settings it is rebuilt with (a scene may name only these); ``FUNCTIONS`` the functions a saved setting may name.
Nothing here imports USD: the lessons stay free of the persistence layer, and a file names classes, never code.
"""

from __future__ import annotations

from gandalf_core.app.cli import load_impl

from . import exercises
from .components import LookAtComponent, OrbitCameraComponent
from .systems import CameraSwitchSystem, LookAtSystem

# The reference (the exercises again where a student's release has no solutions/).
_reference = load_impl(__package__)

COMPONENTS = {
    OrbitCameraComponent: ("target", "distance", "yaw", "pitch", "sensitivity", "zoom_factor", "min_pitch",
                           "max_pitch", "min_distance", "max_distance"),
    # comes back as LookAtComponent(eye=, target=, up=)
    LookAtComponent: ("eye", "target", "up"),
}
SYSTEMS = {
    exercises.OrbitCameraSystem: (),
    _reference.OrbitCameraSystem: (),
    LookAtSystem: ("look_at",),  # keeps its look_at function, one of FUNCTIONS
    CameraSwitchSystem: (),
}
FUNCTIONS = tuple(dict.fromkeys((exercises.look_at, _reference.look_at)))
