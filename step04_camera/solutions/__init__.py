"""Step 04 reference solutions (same API as ``exercises``)."""

from gandalf_core.usd import register_function, register_system

from .orbit import OrbitCameraSystem
from .projection import look_at, perspective

__all__ = ["OrbitCameraSystem", "look_at", "perspective"]

register_system(OrbitCameraSystem)  # allowed in saved scenes (gandalf_core.usd)
register_function(look_at)  # a saved LookAtSystem may name it
