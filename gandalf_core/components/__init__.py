"""Core components: Info, Transform, Link (hierarchy), ClearColor; rendering components join in later modules."""

from ..ecs import InfoComponent, LinkComponent
from .clear_color import ClearColorComponent
from .transform import TransformComponent

__all__ = ["ClearColorComponent", "InfoComponent", "LinkComponent", "TransformComponent"]
