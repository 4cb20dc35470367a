"""The house's scene, the same for OpenGL and WebGPU: the capstone assembled from its five milestones.

``build_house_scene(impl)`` takes the milestones from ``impl`` (the step's ``solutions``, or with ``--student``
its ``exercises``): the meshes, the brick texture, the two materials, the camera and the rotation system.
"""

from __future__ import annotations

from types import ModuleType

from gandalf_core import ClearColorComponent, InfoComponent, Scene
from gandalf_core.app.cli import Part
from gandalf_core.components import MaterialComponent, MeshComponent

from .. import SHADERS
from ..hierarchy.scene import add_child
from .components import HouseRotationComponent

#: Frames the course tour renders before it takes the picture (at 60 frames per simulated second).
TOUR_FRAMES = 90


# --8<-- [start:house]
def build_house_scene(impl: ModuleType) -> Scene:
    """The capstone: ``impl`` gives the five milestones (meshes, texture, materials, camera,
    rotation)."""
    scene = Scene("house")
    walls, roof = impl.house_meshes()
    scene.assets.mesh("house.walls", walls)
    scene.assets.mesh("house.roof", roof)
    scene.assets.texture("house.brick", impl.brick_texture_data())
    for name, material in impl.house_material_data().items():
        scene.assets.material(name, material)
    scene.create_entity(InfoComponent("background"), ClearColorComponent((0.55, 0.75, 0.95)))
    house = add_child(scene, "house", None, HouseRotationComponent(speed=45.0))
    add_child(scene, "walls", house, MeshComponent("house.walls"), MaterialComponent("house.walls"))
    add_child(scene, "roof", house, MeshComponent("house.roof"), MaterialComponent("house.roof"))
    camera, transform = impl.house_camera(None)
    scene.create_entity(InfoComponent("camera"), camera, transform)
    scene.add_system(impl.HouseRotationSystem())
    return scene
# --8<-- [end:house]


def build_scene(impl: ModuleType) -> Scene:
    """The house for the variants (``impl``: the step's solutions, or your exercises with ``--student``)."""
    return build_house_scene(impl)


#: What the variants (``opengl.py``, ``webgpu.py``) hand the launcher: this concept, its scene and the step's shaders.
PART = Part(__package__, build_scene, SHADERS)
