"""Step 01 reference solutions (same API as ``exercises``)."""


from .hue import HueCycleSystem, hsv_to_rgb

__all__ = ["HueCycleSystem", "hsv_to_rgb"]

