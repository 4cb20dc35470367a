"""Step 04 reference solutions (same API as ``exercises``)."""


from .orbit import OrbitCameraSystem
from .projection import look_at, perspective

__all__ = ["OrbitCameraSystem", "look_at", "perspective"]

