"""Step 06 reference solutions (same API as ``exercises``, including ``shading.glsl``/``shading.wgsl``)."""

from gandalf_core.usd import register_system

from .lights import LightCollectionSystem
from .optics import reflect, refract

__all__ = ["LightCollectionSystem", "reflect", "refract"]

register_system(LightCollectionSystem)  # allowed in saved scenes (gandalf_core.usd)
