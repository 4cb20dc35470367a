"""Exercise: the house capstone, in five milestones (the paper's user-study task).

A house is a brick-textured cube with an orange pyramid roof, turning about its y-axis, seen through a
perspective camera. Each milestone is graded on its own by rendering it (``pytest --student
tests/step05_scenegraph -k house``); the reference parts fill in the rest.

1. attributes  ``house_meshes()``
2. textures    ``brick_texture_data()``
3. shaders     ``house_material_data()``
4. camera      ``house_camera(aspect)``
5. uniforms / interactivity  ``HouseRotationSystem``
"""

from __future__ import annotations

from gandalf_core import System, TransformComponent
from gandalf_core.components import CameraComponent
from gandalf_core.resources import MaterialData, MeshData, TextureData

from ..house.components import HouseRotationComponent

#: The roof colour (sRGB, as a colour picker shows it).
ORANGE = (1.0, 0.5, 0.0)


def house_meshes() -> tuple[MeshData, MeshData]:
    """Milestone 1 (attributes): return ``(walls, roof)`` MeshData named "house.walls" and "house.roof".

    * walls: ``gandalf_core.resources.cube(1.0)`` moved up so that it stands on y = 0 (x and z from
      -0.5 to 0.5, y from 0 to 1);
    * roof: ``pyramid(base=1.3, height=0.7)`` (its base is at y = 0) moved up so that its base rests on the
      top of the walls (y from 1.0 to 1.7); the 1.3 base makes the eaves overhang.

    Hint: ``MeshData(new_positions, normals=m.normals, uvs=m.uvs, tangents=m.tangents, indices=m.indices,
    name=...)``; a translation does not change normals or uvs.
    """
    raise NotImplementedError("exercise: house_meshes")


def brick_texture_data(size: int = 64) -> TextureData:
    """Milestone 2 (textures): a ``size`` x ``size`` brick texture named "house.brick".

    Red-brown bricks (sRGB (0.62, 0.24, 0.17), each channel within 0.1 of it: a per-brick variation is
    welcome) separated by light grey mortar joints ((0.82, 0.80, 0.75), within 0.05), 2 pixels wide: four
    courses of bricks of equal length, every other course shifted by half a brick. Where a joint sits (top or
    bottom of a course, left or right of a brick) and how many bricks a course holds are yours to choose; the
    texture repeats, so a joint may also cross its edge. Build an ``(size, size, 3)`` float array in [0, 1] and
    return ``TextureData.from_array(rgb, name=...)``.
    """
    raise NotImplementedError("exercise: brick_texture_data")


def house_material_data() -> dict[str, MaterialData]:
    """Milestone 3 (shaders): the two materials by name.

    * "house.walls": shader "shaded_textured" (lit, textured; see ``shaders/shaded_textured.*``) with the
      texture "house.brick" and a white colour;
    * "house.roof": shader "shaded" (lit, one colour) with the colour ``ORANGE``.
    """
    raise NotImplementedError("exercise: house_material_data")


def house_camera(aspect: float | None = None) -> tuple[CameraComponent, TransformComponent]:
    """Milestone 4 (camera): a perspective CameraComponent and the Transform that places it.

    Frame the whole house (about 1.3 wide, 1.7 tall, standing at the origin) from any side you like: the
    house (roof above the walls) inside the frame with a margin of a few pixels, covering 10-60 % of it and
    roughly centred. E.g. a 45° vertical field of view from ``eye = (0, 1.8, 4.2)`` looking at
    ``(0, 0.8, 0)``; use ``gandalf_core.math.look_at_rotation(eye, target)`` for the quaternion. Pass
    ``aspect`` on to the camera (None follows the render target).
    """
    raise NotImplementedError("exercise: house_camera")


# --8<-- [start:rotation]
class HouseRotationSystem(System):
    """Milestone 5 (uniforms / interactivity): turn the house about its y-axis.

    Every frame, for each entity with a HouseRotationComponent and a TransformComponent:

    * if ``self.scene.app`` exists and ``app.input.pressed(rotation.pause_key)``, toggle
      ``rotation.paused``;
    * unless paused, advance ``rotation.angle`` by ``rotation.speed * ts`` degrees (keep it in
      [0, 360));
    * set ``transform.quaternion`` to the rotation by ``rotation.angle`` degrees about (0, 1, 0)
      (``gandalf_core.math.quat_from_axis_angle`` takes radians).
    """

    def __init__(self) -> None:
        super().__init__([HouseRotationComponent, TransformComponent])

    def on_update_entity(self, ts, entity, components) -> None:
        rotation, transform = components
        raise NotImplementedError("exercise: HouseRotationSystem.on_update_entity")
# --8<-- [end:rotation]
