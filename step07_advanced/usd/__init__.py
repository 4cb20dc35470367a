"""USD scenes: save a Scene to a .usda/.usdc file and load it back (step 07's last concept).

``save_scene(scene, "level.usda")`` and ``scene = load_scene("level.usda")``; every step's launcher saves with
``--save FILE.usda`` through the engine's ``save_scene`` hook (:mod:`gandalf_core.app.extensions`). The mapping of
components to USD prims and attributes is described in ``docs/usd.md`` and :mod:`step07_advanced.usd.mapping`.
A file may name only allowed classes (:mod:`step07_advanced.usd.registry`): a course step lists its components and
systems in its ``saved.py``; a program of your own registers its classes with :func:`register_component` and
:func:`register_system`.

Importing this package does not import USD (``pxr``); saving or loading does.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from .errors import USDSceneError, USDSceneWarning
from .registry import (
    allow_package,
    register_component,
    register_function,
    register_system,
    unregister_component,
    unregister_function,
    unregister_system,
)

if TYPE_CHECKING:
    from collections.abc import Callable

    from gandalf_core.ecs import Scene
    from gandalf_core.resources import MaterialData

    from .foreign import PreviewSurface


def save_scene(scene: Scene, path: str | Path, *, assets: bool = True) -> Path:
    """Write ``scene`` to ``path`` (.usda or .usdc) atomically; see :func:`step07_advanced.usd.writer.save_scene`."""
    from .writer import save_scene as save

    return save(scene, path, assets=assets)


def load_scene(path: str | Path, *, name: str | None = None, strict: bool = True, allow_outside: bool = False,
               preview_material: Callable[[PreviewSurface], MaterialData] | None = None) -> Scene:
    """Read a USD file (gandalf's or another tool's) into a new Scene; see :func:`.reader.load_scene`.

    ``allow_outside=True`` lets sublayers, references, payloads and textures lie outside the file's folder;
    ``preview_material`` maps another tool's UsdPreviewSurface (a :class:`step07_advanced.usd.foreign.PreviewSurface`)
    onto an engine ``MaterialData`` (default: the built-in ``gandalf.blinn_phong``).
    """
    from .reader import load_scene as load

    return load(path, name=name, strict=strict, allow_outside=allow_outside, preview_material=preview_material)


__all__ = [
    "USDSceneError",
    "USDSceneWarning",
    "allow_package",
    "load_scene",
    "register_component",
    "register_function",
    "register_system",
    "save_scene",
    "unregister_component",
    "unregister_function",
    "unregister_system",
]
