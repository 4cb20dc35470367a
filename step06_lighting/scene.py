"""Step 06's scene, the same for OpenGL and WebGPU: three bunnies under a sky and seventeen lights.

A clay bunny (Blinn-Phong), a silver one (a mirror of the sky) and an ice one (refraction with Fresnel) stand
on a checkered floor. Sixteen coloured point lights circle them (each drawn as a small glowing ball), a
directional key light and an ambient light complete the set. The bunny is read from ``models/bunny.glb``.
"""

from __future__ import annotations

import colorsys
from pathlib import Path
from types import ModuleType

from gandalf_core import Scene, TransformComponent
from gandalf_core.components import (
    CameraComponent,
    InfoComponent,
    LightComponent,
    MaterialComponent,
    MeshComponent,
    SkyboxComponent,
)
from gandalf_core.math import look_at_rotation
from gandalf_core.resources import MaterialData, checkerboard, plane, sky_cube, uv_sphere
from gandalf_core.resources.mesh_loader import load_mesh

from .components import OrbitComponent
from .systems import OrbitSystem

#: Frames the course tour renders before it takes the picture (at 60 frames per simulated second).
TOUR_FRAMES = 30
BUNNY_PATH = Path(__file__).resolve().parent / "models" / "bunny.glb"
RING_LIGHTS = 16


def add_materials(scene: Scene) -> None:
    """The step's materials (and the sky texture the environment-mapped ones sample)."""
    assets = scene.assets
    assets.texture("sky", sky_cube(128))
    assets.texture("floor", checkerboard(256, 16, (0.85, 0.85, 0.82), (0.35, 0.36, 0.4)))
    assets.material("clay", MaterialData("phong", color=(0.86, 0.52, 0.36), params={"specular": 0.35,
                                                                                     "shininess": 48.0}))
    assets.material("floor", MaterialData("phong_textured", ["floor"], params={"specular": 0.1, "shininess": 16.0}))
    assets.material("silver", MaterialData("mirror", ["sky"], color=(0.96, 0.95, 0.92)))
    assets.material("ice", MaterialData("glass", ["sky"], color=(0.82, 0.93, 1.0), params={"ior": 1.31}))


def build_scene(impl: ModuleType) -> Scene:
    """``impl`` is the step's ``solutions`` or ``exercises`` package (it provides LightCollectionSystem)."""
    scene = Scene("step06_lighting")
    add_materials(scene)
    scene.assets.mesh("bunny", load_mesh(BUNNY_PATH))
    scene.assets.mesh("floor", plane(14.0, 8))
    scene.assets.mesh("marker", uv_sphere(0.07, 12, 6))
    scene.create_entity(InfoComponent("sky"), SkyboxComponent("sky"))
    floor = (MeshComponent("floor"), MaterialComponent("floor"))
    scene.create_entity(InfoComponent("floor"), TransformComponent(), *floor)
    for name, material, x in (("clay bunny", "clay", -2.3), ("silver bunny", "silver", 0.0), ("ice bunny", "ice", 2.3)):
        scene.create_entity(InfoComponent(name), TransformComponent((x, 0.0, 0.0), rotation=(0.0, 60.0, 0.0)),
                            MeshComponent("bunny"), MaterialComponent(material))
    for k in range(RING_LIGHTS):
        rgb = colorsys.hsv_to_rgb(k / RING_LIGHTS, 0.75, 1.0)
        scene.assets.material(f"marker{k}", MaterialData("emissive", color=rgb))
        scene.create_entity(
            InfoComponent(f"light {k}"),
            TransformComponent(),
            OrbitComponent(center=(0.0, 0.45 + 0.5 * (k % 2), 0.0), radius=3.6, angle=360.0 * k / RING_LIGHTS,
                           speed=24.0),
            LightComponent("point", rgb, intensity=1.6, range=4.0),
            MeshComponent("marker"),
            MaterialComponent(f"marker{k}"),
        )
    key = (-4.0, 6.0, 5.0)
    scene.create_entity(
        InfoComponent("key light"), TransformComponent(key, quaternion=look_at_rotation(key, (0, 0, 0))),
        LightComponent("directional", (1.0, 0.96, 0.9), intensity=0.9))
    scene.create_entity(InfoComponent("ambient"), TransformComponent(), LightComponent("ambient", (0.2, 0.22, 0.27)))
    eye = (0.0, 2.4, 7.6)
    camera = TransformComponent(eye, quaternion=look_at_rotation(eye, (0.0, 0.75, 0.0)))
    scene.create_entity(InfoComponent("camera"), camera, CameraComponent(40.0, 0.1, 100.0))
    scene.add_system(OrbitSystem())
    scene.add_system(impl.LightCollectionSystem())
    return scene
