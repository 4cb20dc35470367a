"""Attack: import the reference solution by its name."""
from ..solutions.hue import HueCycleSystem, hsv_to_rgb  # noqa: F401
