"""The lights' scene, the same for OpenGL and WebGPU: the clay bunny inside a ring of sixteen coloured lights.

The lights circle the bunny (``OrbitComponent``, moved by ``OrbitSystem``), each drawn as a small glowing ball; a
directional key light and an ambient light complete the set. ``build_scene(impl)`` takes the step's
``solutions`` or ``exercises`` package: its ``LightCollectionSystem`` packs the lights block. The helpers here
also build the step's whole scene (``step06_lighting.scene``).
"""

from __future__ import annotations

import colorsys
from types import ModuleType

from gandalf_core import Scene, TransformComponent
from gandalf_core.app.cli import Part
from gandalf_core.components import CameraComponent, InfoComponent, LightComponent, MaterialComponent, MeshComponent
from gandalf_core.math import look_at_rotation
from gandalf_core.resources import MaterialData, checkerboard, plane, uv_sphere

from ..meshes.scene import add_bunny, add_bunny_mesh
from ..shaders import shader_table
from . import SHADERS
from .components import OrbitComponent
from .systems import OrbitSystem

#: Frames the course tour renders before it takes the picture (at 60 frames per simulated second).
TOUR_FRAMES = 30
RING_LIGHTS = 16


def add_clay(scene: Scene) -> None:
    """The Blinn-Phong material of the clay bunny."""
    scene.assets.material("clay", MaterialData("phong", color=(0.86, 0.52, 0.36),
                                               params={"specular": 0.35, "shininess": 48.0}))


def add_floor(scene: Scene) -> None:
    """A 14 m checkered floor (Blinn-Phong with a texture) at y = 0."""
    scene.assets.texture("floor", checkerboard(256, 16, (0.85, 0.85, 0.82), (0.35, 0.36, 0.4)))
    scene.assets.material("floor", MaterialData("phong_textured", ["floor"],
                                                params={"specular": 0.1, "shininess": 16.0}))
    scene.assets.mesh("floor", plane(14.0, 8))
    scene.create_entity(InfoComponent("floor"), TransformComponent(), MeshComponent("floor"),
                        MaterialComponent("floor"))


# --8<-- [start:ring]
def add_light_ring(scene: Scene, radius: float = 3.6) -> None:
    """RING_LIGHTS point lights of every hue circling the y axis at two heights, with markers."""
    scene.assets.mesh("marker", uv_sphere(0.07, 12, 6))
    for k in range(RING_LIGHTS):
        rgb = colorsys.hsv_to_rgb(k / RING_LIGHTS, 0.75, 1.0)
        scene.assets.material(f"marker{k}", MaterialData("emissive", color=rgb))
        scene.create_entity(
            InfoComponent(f"light {k}"),
            TransformComponent(),
            OrbitComponent(center=(0.0, 0.45 + 0.5 * (k % 2), 0.0), radius=radius,
                           angle=360.0 * k / RING_LIGHTS, speed=24.0),
            LightComponent("point", rgb, intensity=1.6, range=4.0),  # range: fades to zero at 4 m
            MeshComponent("marker"),
            MaterialComponent(f"marker{k}"),
        )


def add_key_and_ambient(scene: Scene) -> None:
    """A warm directional key light from the upper left front, and a cool ambient light."""
    key = (-4.0, 6.0, 5.0)
    towards_origin = look_at_rotation(key, (0, 0, 0))  # a directional light shines along its -Z
    scene.create_entity(InfoComponent("key light"),
                        TransformComponent(key, quaternion=towards_origin),
                        LightComponent("directional", (1.0, 0.96, 0.9), intensity=0.9))
    scene.create_entity(InfoComponent("ambient"), TransformComponent(),
                        LightComponent("ambient", (0.2, 0.22, 0.27)))
# --8<-- [end:ring]


def build_scene(impl: ModuleType) -> Scene:
    """``impl`` is the step's ``solutions`` or ``exercises`` package (it provides LightCollectionSystem)."""
    scene = Scene("step06_lighting.lights")
    add_floor(scene)
    add_clay(scene)
    add_bunny_mesh(scene)
    add_bunny(scene, "clay bunny", "clay", 0.0)
    add_light_ring(scene, radius=2.2)
    add_key_and_ambient(scene)
    eye = (0.0, 2.6, 6.6)
    camera = TransformComponent(eye, quaternion=look_at_rotation(eye, (0.0, 0.8, 0.0)))
    scene.create_entity(InfoComponent("camera"), camera, CameraComponent(40.0, 0.1, 100.0))
    # --8<-- [start:systems]
    scene.add_system(OrbitSystem())  # moves the lights round the circle
    scene.add_system(impl.LightCollectionSystem())  # exercise: packs them into the lights block
    # --8<-- [end:systems]
    return scene


#: What the variants (``opengl.py``, ``webgpu.py``) hand the launcher: this concept, its scene and the
#: step's shaders it uses (with the implementation's ``shading``).
# --8<-- [start:part]
PART = Part(__package__, build_scene, shader_table(SHADERS), include_impl=True)
# --8<-- [end:part]
