"""Step 01 exercises: fill in ``hue.py``, then run ``pytest --student tests/step01_window``."""


from .hue import HueCycleSystem, hsv_to_rgb

__all__ = ["HueCycleSystem", "hsv_to_rgb"]

