"""gandalf_core: the frozen framework of the gandalf course.

``import gandalf_core`` loads only the ECS, maths and data modules; moderngl or wgpu are imported when an
:class:`Application` creates its renderer, and trimesh, USD and ImGui only when those features are used.
"""

from .app import Application
from .components import ClearColorComponent, InfoComponent, LinkComponent, TransformComponent
from .ecs import Component, Scene, SceneManager, System
from .systems import TransformSystem

__version__ = "0.1.0"

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
