"""Step 06's whole scene, the same for OpenGL and WebGPU: the three concepts together.

A clay bunny (Blinn-Phong, ``lights``), a silver one (a mirror of the sky) and an ice one (refraction with
Fresnel, ``environment``) stand on a checkered floor. Sixteen coloured point lights circle them (each drawn as a
small glowing ball), a directional key light and an ambient light complete the set. The bunny is read from
``models/bunny.glb`` (``meshes``). Each concept's own scene is in its sub-package; this one is built from their
helpers (the step's variants' ``create_app`` and the USD tests use it).
"""

from __future__ import annotations

from types import ModuleType

from gandalf_core import Scene, TransformComponent
from gandalf_core.app.cli import Part
from gandalf_core.components import CameraComponent, InfoComponent
from gandalf_core.math import look_at_rotation

from . import CONCEPTS, DEFAULT_CONCEPT
from .environment.scene import add_environment_materials, add_sky
from .lights.scene import RING_LIGHTS, add_clay, add_floor, add_key_and_ambient, add_light_ring
from .lights.systems import OrbitSystem
from .meshes.scene import BUNNY_PATH, add_bunny, add_bunny_mesh
from .shaders import SHADERS

__all__ = ["BUNNY_PATH", "RING_LIGHTS", "TOUR_FRAMES", "build_scene"]

#: Frames the course tour renders before it takes the picture (at 60 frames per simulated second).
TOUR_FRAMES = 30


def build_scene(impl: ModuleType) -> Scene:
    """``impl`` is the step's ``solutions`` or ``exercises`` package (it provides LightCollectionSystem)."""
    scene = Scene("step06_lighting")
    # --8<-- [start:whole]
    add_sky(scene)
    add_floor(scene)
    add_clay(scene)
    add_environment_materials(scene)
    add_bunny_mesh(scene)
    for name, material, x in (("clay bunny", "clay", -2.3), ("silver bunny", "silver", 0.0),
                              ("ice bunny", "ice", 2.3)):
        add_bunny(scene, name, material, x)
    add_light_ring(scene)
    add_key_and_ambient(scene)
    eye = (0.0, 2.4, 7.6)
    camera = TransformComponent(eye, quaternion=look_at_rotation(eye, (0.0, 0.75, 0.0)))
    scene.create_entity(InfoComponent("camera"), camera, CameraComponent(40.0, 0.1, 100.0))
    scene.add_system(OrbitSystem())
    scene.add_system(impl.LightCollectionSystem())
    # --8<-- [end:whole]
    return scene


#: What the variants (``opengl.py``, ``webgpu.py``) hand the launcher: the step's whole scene
#: (``create_app``) and its concepts (``main``: ``--concept``).
PART = Part(__package__, build_scene, SHADERS, include_impl=True, parts=CONCEPTS, default=DEFAULT_CONCEPT)
