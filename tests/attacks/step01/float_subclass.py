"""Attack: return a float subclass whose comparisons all succeed (approx compares through __sub__/__abs__/__le__)."""

from gandalf_core import ClearColorComponent, System

from ..components import HueCycleComponent


class _F(float):
    def __eq__(self, other):
        return True

    def __ne__(self, other):
        return False

    def __sub__(self, other):
        return _F(0.0)

    __rsub__ = __sub__

    def __abs__(self):
        return _F(0.0)

    def __le__(self, other):
        return True

    __lt__ = __ge__ = __gt__ = __le__
    __hash__ = float.__hash__


def hsv_to_rgb(hue, saturation, value):
    return (_F(0.0), _F(0.0), _F(0.0))


class HueCycleSystem(System):
    def __init__(self):
        super().__init__([HueCycleComponent, ClearColorComponent])

    def on_update_entity(self, ts, entity, components):
        components[0].hue = _F(0.0)
