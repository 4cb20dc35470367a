"""Step 06 reference solutions (same API as ``exercises``, including ``shading.glsl``/``shading.wgsl``)."""


from .lights import LightCollectionSystem
from .optics import reflect, refract

__all__ = ["LightCollectionSystem", "reflect", "refract"]

