"""Attack: import the reference solution by a name assembled at run time (importlib)."""
import importlib

_m = importlib.import_module(__name__.rsplit('.', 2)[0] + '.' + 'sol' + 'utions.hue')
hsv_to_rgb, HueCycleSystem = _m.hsv_to_rgb, _m.HueCycleSystem
