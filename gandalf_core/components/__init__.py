"""Core components: Info, Transform, Link (hierarchy), ClearColor, Mesh, Material, Camera."""

from ..ecs import InfoComponent, LinkComponent
from .camera import CameraComponent
from .clear_color import ClearColorComponent
from .light import LightComponent
from .renderable import MaterialComponent, MeshComponent
from .skybox import SkyboxComponent
from .transform import TransformComponent

__all__ = [
    "CameraComponent",
    "ClearColorComponent",
    "InfoComponent",
    "LightComponent",
    "LinkComponent",
    "MaterialComponent",
    "MeshComponent",
    "SkyboxComponent",
    "TransformComponent",
]
