"""gandalf_core: the frozen framework of the gandalf course.

``import gandalf_core`` loads only the ECS, maths and component modules (and numpy); the application layer
(:class:`Application`), the systems, the resource loaders and the renderers load on first use, and moderngl or
wgpu only when an :class:`Application` creates its renderer; trimesh only when a mesh file is read.
``from gandalf_core import Application`` and ``gandalf_core.app`` work as before (module ``__getattr__``).
The engine imports no ImGui, USD, course step or tool: the editor and USD scenes are the final step's
(``step07_advanced``), reached through the hooks of :mod:`gandalf_core.app.extensions`.
"""

from __future__ import annotations

import importlib
from typing import Any

from .components import ClearColorComponent, InfoComponent, LinkComponent, TransformComponent
from .ecs import Component, Scene, SceneManager, System

__version__ = "0.1.0"

# name -> module that defines it, imported on first access
_LAZY = {"Application": ".app", "TransformSystem": ".systems"}
_SUBPACKAGES = ("app", "components", "ecs", "math", "render", "resources", "systems")


def __getattr__(name: str) -> Any:
    if name in _LAZY:
        value = getattr(importlib.import_module(_LAZY[name], __name__), name)
    elif name in _SUBPACKAGES:
        value = importlib.import_module(f".{name}", __name__)
    else:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_LAZY) | set(_SUBPACKAGES))


__all__ = [
    "Application",
    "ClearColorComponent",
    "Component",
    "InfoComponent",
    "LinkComponent",
    "Scene",
    "SceneManager",
    "System",
    "TransformComponent",
    "TransformSystem",
]
