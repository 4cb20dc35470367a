"""Loading a scene into a running app: reuse the GPU resources the renderer already built for equal data.

A renderer builds each mesh, texture and material once per name and refuses a second scene that uses
the name for other data. A scene saved and loaded again repeats its names with new (equal) data
objects, so the loaded scene is pointed at the running scene's objects wherever the data is the same.
"""

from __future__ import annotations

import dataclasses
from typing import Any

import numpy as np

from gandalf_core.resources.assets import Assets

_KINDS = ("meshes", "textures", "materials")


def _equal(a: Any, b: Any) -> bool:
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        a, b = np.asarray(a), np.asarray(b)
        # USD stores float32: allow its rounding, nothing more.
        return a.shape == b.shape and bool(np.allclose(a, b, rtol=1e-6, atol=1e-6))
    if isinstance(a, (tuple, list)) and isinstance(b, (tuple, list)):
        return len(a) == len(b) and all(_equal(x, y) for x, y in zip(a, b))
    if dataclasses.is_dataclass(a) and type(a) is type(b):
        # The ``name`` field is a label for messages, not data.
        return all(_equal(getattr(a, f.name), getattr(b, f.name)) for f in dataclasses.fields(a) if f.name != "name")
    return bool(a == b)


def adopt_built_assets(loaded: Assets, current: Assets, renderer: Any) -> list[str]:
    """Share ``current``'s data objects with ``loaded`` where the renderer built that name from equal data.

    Returns the clashing resources ("material 'M'"): names the program built itself (``renderer.materials.build``)
    from other data. A name built from a scene's assets with other data (a colour edited since, say) is no clash:
    the loaded scene keeps its own data and the renderer builds it anew when that scene is drawn.
    """
    clashes = []
    for kind in _KINDS:
        library = getattr(renderer, kind)
        table, running = getattr(loaded, kind), getattr(current, kind)
        for name, data in table.items():
            if name not in library:
                continue
            existing = running.get(name)
            if existing is not None and _equal(existing, data):
                table[name] = existing
            elif name not in getattr(library, "_from_assets", ()):
                clashes.append(f"{kind[:-1] if kind != 'meshes' else 'mesh'} '{name}'")
    return clashes
