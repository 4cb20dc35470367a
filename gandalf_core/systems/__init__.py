"""Core systems that every scene can use."""

from .transform_system import TransformSystem, set_parent_keep_world, world_matrix

__all__ = ["TransformSystem", "set_parent_keep_world", "world_matrix"]
