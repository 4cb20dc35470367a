"""Core systems that every scene can use."""

from .light_system import LightSystem, pack_lights
from .transform_system import TransformSystem, set_parent_keep_world, world_matrix

__all__ = ["LightSystem", "pack_lights", "TransformSystem", "set_parent_keep_world", "world_matrix"]
