"""Step 06 exercises: fill in ``lights.py``, ``optics.py`` and ``shading.glsl``/``shading.wgsl``, then run
``pytest --student tests/step06_lighting``. The shader files are included by the step's shaders from this folder.
"""


from .lights import LightCollectionSystem
from .optics import reflect, refract

__all__ = ["LightCollectionSystem", "reflect", "refract"]

