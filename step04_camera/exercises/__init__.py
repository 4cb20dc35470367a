"""Step 04 exercises: fill in ``projection.py`` and ``orbit.py``, then run ``pytest --student tests/step04_camera``."""


from .orbit import OrbitCameraSystem
from .projection import look_at, perspective

__all__ = ["OrbitCameraSystem", "look_at", "perspective"]

