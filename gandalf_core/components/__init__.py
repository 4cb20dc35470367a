"""Core components: Info, Transform, Link (hierarchy), ClearColor, Mesh, Material, Camera."""

from ..ecs import InfoComponent, LinkComponent
from .camera import CameraComponent
from .clear_color import ClearColorComponent
from .renderable import MaterialComponent, MeshComponent
from .transform import TransformComponent

__all__ = [
    "CameraComponent",
    "ClearColorComponent",
    "InfoComponent",
    "LinkComponent",
    "MaterialComponent",
    "MeshComponent",
    "TransformComponent",
]
