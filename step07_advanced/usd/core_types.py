"""The core's own components and systems that a saved scene may hold: a declaration the registry reads.

Built-in components (transforms, cameras, lights, meshes, ...) are mapped onto USD schemas by the writer; these
are the other core classes a scene may hold: the camera controllers and the spin, and the transform and light
systems (the app adds them when a scene has none; a scene saved from a running app keeps them, in their order).
The render system and an editor's panel systems belong to the tool, not to a scene (``System.saved = False``):
they are never saved. Same shape as a step's ``saved.py``.
"""

from __future__ import annotations

from gandalf_core.systems import (
    FlyControllerComponent,
    FlyControllerSystem,
    LightSystem,
    OrbitControllerComponent,
    OrbitControllerSystem,
    SpinComponent,
    SpinSystem,
    TransformSystem,
)

COMPONENTS = {
    OrbitControllerComponent: ("target", "distance", "yaw", "pitch", "sensitivity", "zoom_speed", "min_distance",
                               "max_distance", "min_pitch", "max_pitch"),
    FlyControllerComponent: ("speed", "sensitivity", "yaw", "pitch", "min_pitch", "max_pitch"),
    SpinComponent: ("axis", "speed", "local"),
}
SYSTEMS = {TransformSystem: (), LightSystem: (), OrbitControllerSystem: (), FlyControllerSystem: (),
           SpinSystem: ("path",)}
