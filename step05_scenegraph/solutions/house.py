"""Reference solution of the house capstone: five milestones, as in the paper's user study."""

from __future__ import annotations

import math

import numpy as np

from gandalf_core import System, TransformComponent
from gandalf_core.components import CameraComponent
from gandalf_core.math import look_at_rotation, quat_from_axis_angle
from gandalf_core.resources import MaterialData, MeshData, TextureData, cube, pyramid

from ..house.components import HouseRotationComponent

WALL_HEIGHT = 1.0
ROOF_BASE = 1.3
ROOF_HEIGHT = 0.7
ORANGE = (1.0, 0.5, 0.0)


def _moved(mesh: MeshData, scale: float, offset: tuple[float, float, float], name: str) -> MeshData:
    # Uniform scale and a translation leave normals, uvs and tangents as they are.
    positions = mesh.positions.astype(np.float64) * scale + np.asarray(offset)
    return MeshData(
        positions, normals=mesh.normals, uvs=mesh.uvs, tangents=mesh.tangents, indices=mesh.indices, name=name
    )


def house_meshes() -> tuple[MeshData, MeshData]:
    """Milestone 1: the walls (a unit cube standing on y = 0) and the roof (on top, overhanging)."""
    walls = _moved(cube(1.0), WALL_HEIGHT, (0.0, WALL_HEIGHT / 2, 0.0), "house.walls")
    roof = pyramid(ROOF_BASE, ROOF_HEIGHT)
    return walls, _moved(roof, 1.0, (0.0, WALL_HEIGHT, 0.0), "house.roof")


def brick_texture_data(size: int = 64) -> TextureData:
    """Milestone 2: bricks in a running bond, four courses of two bricks, light mortar joints."""
    brick = np.array([0.62, 0.24, 0.17])
    mortar = np.array([0.82, 0.80, 0.75])
    y, x = np.mgrid[0:size, 0:size]
    course = size // 4
    row = y // course
    shifted = (x + (row % 2) * (size // 4)) % size  # every other course is shifted by half a brick
    joint = (y % course < 2) | (shifted % (size // 2) < 2)
    # A little per-brick variation so the wall does not look printed.
    brick_id = row * 2 + shifted // (size // 2)
    shade = 0.9 + 0.1 * ((brick_id * 7919) % 5) / 4.0
    rgb = np.where(joint[..., None], mortar, brick * shade[..., None])
    return TextureData.from_array(rgb, name="house.brick")


def house_material_data() -> dict[str, MaterialData]:
    """Milestone 3: the walls textured with bricks and lit; the roof lit, flat orange."""
    return {
        "house.walls": MaterialData("shaded_textured", ["house.brick"], color=(1.0, 1.0, 1.0), name="house.walls"),
        "house.roof": MaterialData("shaded", color=ORANGE, name="house.roof"),
    }


def house_camera(aspect: float | None = None) -> tuple[CameraComponent, TransformComponent]:
    """Milestone 4: a 45° perspective camera in front of and above the house, looking at its middle."""
    eye = np.array([0.0, 1.8, 4.2])
    target = np.array([0.0, 0.8, 0.0])
    camera = CameraComponent(45.0, 0.1, 50.0, aspect=aspect)
    return camera, TransformComponent(eye, quaternion=look_at_rotation(eye, target))


class HouseRotationSystem(System):
    """Milestone 5: turn the house about y at its component's speed; the pause key toggles the motion."""

    def __init__(self) -> None:
        super().__init__([HouseRotationComponent, TransformComponent])

    def on_update_entity(self, ts, entity, components) -> None:
        rotation, transform = components
        app = self.scene.app
        if app is not None and app.input.pressed(rotation.pause_key):
            rotation.paused = not rotation.paused
        if not rotation.paused:
            rotation.angle = (rotation.angle + rotation.speed * ts) % 360.0  # Python's % wraps negatives into [0, 360)
        transform.quaternion = quat_from_axis_angle((0.0, 1.0, 0.0), math.radians(rotation.angle))
