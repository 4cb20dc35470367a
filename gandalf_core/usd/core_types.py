"""The core's own components and systems on the USD allow-list (imported by the registry on first use).

Built-in components (transforms, cameras, lights, meshes, ...) are mapped onto USD schemas by the writer; these
are the other core classes a scene may hold: the camera controllers, and the transform and light systems (the
app adds them when a scene has none; a scene saved from a running app keeps them, in their order). The render
system and the editor's panel systems belong to the tool, not to a scene: they are never saved.
"""

from __future__ import annotations

from ..systems import (
    FlyControllerComponent,
    FlyControllerSystem,
    LightSystem,
    OrbitControllerComponent,
    OrbitControllerSystem,
    TransformSystem,
)
from .registry import register_component, register_system

register_component(OrbitControllerComponent, fields=["target", "distance", "yaw", "pitch", "sensitivity", "zoom_speed",
                                                     "min_distance", "max_distance", "min_pitch", "max_pitch"])
register_component(FlyControllerComponent, fields=["speed", "sensitivity", "yaw", "pitch", "min_pitch", "max_pitch"])
for _system in (TransformSystem, LightSystem, OrbitControllerSystem, FlyControllerSystem):
    register_system(_system)
