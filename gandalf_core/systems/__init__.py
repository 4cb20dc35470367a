"""Core systems that every scene can use: transforms, lights, camera controllers, a spin."""

from .camera_controllers import (
    FlyControllerComponent,
    FlyControllerSystem,
    OrbitControllerComponent,
    OrbitControllerSystem,
)
from .light_system import LightSystem, pack_lights, pack_shadow
from .spin import SpinComponent, SpinSystem
from .transform_system import TransformSystem, set_parent_keep_world, world_matrix

__all__ = [
    "FlyControllerComponent",
    "FlyControllerSystem",
    "LightSystem",
    "OrbitControllerComponent",
    "OrbitControllerSystem",
    "SpinComponent",
    "SpinSystem",
    "TransformSystem",
    "pack_lights",
    "pack_shadow",
    "set_parent_keep_world",
    "world_matrix",
]
