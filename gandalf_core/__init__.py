"""gandalf_core: the frozen framework of the gandalf course.

``import gandalf_core`` loads only the ECS, maths and component modules (and numpy); the application layer
(:class:`Application`), the systems, the resource loaders and the renderers load on first use, and moderngl or
wgpu only when an :class:`Application` creates its renderer; trimesh only when a mesh file is read.
``from gandalf_core import Application`` and ``gandalf_core.app`` work as before (module ``__getattr__``).
The engine imports no ImGui, USD, course step or tool: the editor and USD scenes are the final step's
(``step07_advanced``), reached through the hooks of :mod:`gandalf_core.app.extensions`.
"""

from __future__ import annotations

from .components import ClearColorComponent, InfoComponent, LinkComponent, TransformComponent
from .ecs import Component, Scene, SceneManager, System
from .lazy import lazy_attributes

__version__ = "0.1.0"

# name -> module that defines it, imported on first access
_LAZY = {"Application": "app", "TransformSystem": "systems"}
_SUBPACKAGES = ("app", "components", "ecs", "math", "render", "resources", "systems")


__getattr__, __dir__ = lazy_attributes(__name__, _LAZY, _SUBPACKAGES)


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
