"""The paper's house with the core's ready materials, no shader: python -m step05_scenegraph.house.minimal --help"""
import math

import numpy as np

from gandalf_core import Scene, System, TransformComponent
from gandalf_core.app.cli import run_scene
from gandalf_core.components import CameraComponent, LightComponent, MaterialComponent, MeshComponent
from gandalf_core.math import quat_from_axis_angle, quat_mul
from gandalf_core.resources import MaterialData, TextureData, cube, pyramid


class TurnSystem(System):  # turns its entities about the y axis, 45° a second
    def on_update_entity(self, ts, entity, components):
        turn = quat_from_axis_angle((0, 1, 0), math.radians(45 * ts))
        components[0].quaternion = quat_mul(turn, components[0].quaternion)


def house_scene() -> Scene:
    scene = Scene("house")
    y, x = np.mgrid[0:64, 0:64]  # bricks: 4 courses of 2, every other one shifted, light mortar
    mortar = (y % 16 < 2) | ((x + y // 16 % 2 * 16) % 32 < 2)
    scene.assets.texture("bricks", TextureData.from_array(np.where(mortar[..., None], 0.8, (0.6, 0.25, 0.15))))
    scene.assets.mesh("walls", cube(1.0))
    scene.assets.mesh("roof", pyramid(1.3, 0.7))
    scene.assets.material("bricks", MaterialData("gandalf.blinn_phong", ["bricks"]))
    scene.assets.material("orange", MaterialData("gandalf.blinn_phong", color=(1.0, 0.5, 0.0)))
    scene.create_entity(TransformComponent((0, 0.5, 0)), MeshComponent("walls"), MaterialComponent("bricks"))
    scene.create_entity(TransformComponent((0, 1, 0)), MeshComponent("roof"), MaterialComponent("orange"))
    scene.create_entity(TransformComponent(rotation=(-40, 30, 0)), LightComponent("directional"))
    scene.create_entity(TransformComponent(), LightComponent("ambient", (0.35, 0.35, 0.4)))
    scene.create_entity(TransformComponent((0, 1.8, 4.2), (-13, 0, 0)), CameraComponent(fov=45))  # looks down a bit
    scene.add_system(TurnSystem([TransformComponent, MeshComponent]))
    return scene


if __name__ == "__main__":
    raise SystemExit(run_scene(house_scene, description=__doc__, title="house"))
