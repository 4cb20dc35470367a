"""The custom systems' scene, the same for OpenGL and WebGPU: balls that fall and bounce, losing height.

``build_scene(impl)`` returns it (``impl`` is unused: the custom systems have no exercise).
"""

from __future__ import annotations

from types import ModuleType

from gandalf_core import InfoComponent, Scene, TransformComponent
from gandalf_core.app.cli import Part
from gandalf_core.components import MaterialComponent, MeshComponent
from gandalf_core.resources import MaterialData, uv_sphere

from .. import SHADERS
from ..hierarchy.scene import add_camera, add_floor
from .components import GravityComponent
from .systems import GravitySystem

#: Frames the course tour renders before it takes the picture (at 60 frames per simulated second).
TOUR_FRAMES = 90

#: The balls' start heights (m) and colours.
BALLS = ((1.5, (0.9, 0.9, 0.9)), (2.5, (0.95, 0.6, 0.25)), (3.5, (0.35, 0.6, 0.95)))


def build_gravity_scene(impl: ModuleType | None = None) -> Scene:
    """Three balls dropped from 1.5, 2.5 and 3.5 m onto a floor that gives back 80 % of their speed."""
    scene = Scene("gravity")
    assets = scene.assets
    assets.mesh("gravity.ball", uv_sphere(1.0, 24, 12))
    add_floor(scene, "gravity")
    # --8<-- [start:balls]
    for i, (height, color) in enumerate(BALLS):
        material = f"gravity.ball{i}"
        assets.material(material, MaterialData("shaded", color=color, name=material))
        scene.create_entity(
            InfoComponent(f"ball {i}"), TransformComponent((-1.2 + 1.2 * i, height, 0.0), scale=0.25),
            MeshComponent("gravity.ball"), MaterialComponent(material),
            GravityComponent(floor=0.25, restitution=0.8),
        )
    scene.add_system(GravitySystem())
    # --8<-- [end:balls]
    add_camera(scene, (0.0, 2.0, 6.0), (0.0, 1.5, 0.0), 50.0)
    return scene


#: What the variants (``opengl.py``, ``webgpu.py``) hand the launcher: this concept, its scene and the step's shaders.
PART = Part(__package__, build_gravity_scene, SHADERS)
#: The concept's scene by its common name (``impl`` unused: this concept has no exercise).
build_scene = build_gravity_scene
