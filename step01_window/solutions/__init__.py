"""Step 01 reference solutions (same API as ``exercises``)."""

from gandalf_core.usd import register_system

from .hue import HueCycleSystem, hsv_to_rgb

__all__ = ["HueCycleSystem", "hsv_to_rgb"]

register_system(HueCycleSystem)  # allowed in saved scenes (gandalf_core.usd)
