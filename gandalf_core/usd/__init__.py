"""USD scenes: save a Scene to a .usda/.usdc file and load it back.

``save_scene(scene, "level.usda")`` and ``scene = load_scene("level.usda")``; the mapping of components to
USD prims and attributes is described in ``docs/usd.md`` and :mod:`gandalf_core.usd.mapping`. Steps' own
components are saved once registered with :func:`register_component`.

Importing this package does not import USD (``pxr``); saving or loading does.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from .errors import USDSceneError, USDSceneWarning
from .registry import register_component, unregister_component

if TYPE_CHECKING:
    from ..ecs import Scene


def save_scene(scene: Scene, path: str | Path, *, assets: bool = True) -> Path:
    """Write ``scene`` to ``path`` (.usda or .usdc) atomically; see :func:`gandalf_core.usd.writer.save_scene`."""
    from .writer import save_scene as save

    return save(scene, path, assets=assets)


def load_scene(path: str | Path, *, name: str | None = None, strict: bool = True) -> Scene:
    """Read a USD file into a new Scene; see :func:`gandalf_core.usd.reader.load_scene`."""
    from .reader import load_scene as load

    return load(path, name=name, strict=strict)


__all__ = [
    "USDSceneError",
    "USDSceneWarning",
    "load_scene",
    "register_component",
    "save_scene",
    "unregister_component",
]
