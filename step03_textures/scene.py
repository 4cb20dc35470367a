"""Step 03's scene, the same for OpenGL and WebGPU: textures on a quad, a cube and two floors.

* a brick wall: a quad with the student's ``brick_texture``;
* a die: a slowly spinning cube whose UVs (the student's ``cube_cross_uvs``) map a cross-shaped atlas;
* wrap modes: two quads with UVs from -1 to 2, the same checkerboard with ``wrap="repeat"`` (top) and
  ``wrap="clamp"`` (bottom);
* mipmaps: a floor running to the horizon, without mipmaps on the left (shimmering moiré) and with them on the
  right (the distance fades smoothly to the average grey).
"""

from __future__ import annotations

from dataclasses import replace
from types import ModuleType

import numpy as np

from gandalf_core import ClearColorComponent, InfoComponent, Scene, TransformComponent
from gandalf_core.app.cli import Part
from gandalf_core.components import CameraComponent, MaterialComponent, MeshComponent
from gandalf_core.math import look_at_rotation
from gandalf_core.resources import MaterialData, MeshData, checkerboard, cube, plane, quad
from gandalf_core.systems import SpinComponent, SpinSystem

from .atlas import dice_atlas

#: Frames the course tour renders before it takes the picture (at 60 frames per simulated second).
TOUR_FRAMES = 40
#: Name of the step's shader in both renderers' shader libraries.
SHADER = "textured"
#: The shader table the variants build: GLSL ``shaders/<name>.vert/.frag`` or WGSL ``shaders/<name>.wgsl``.
SHADERS = (SHADER,)
#: Where the camera stands and what it looks at.
EYE = (0.0, 1.7, 6.0)
TARGET = (0.0, 0.8, 0.0)


def with_uvs(mesh: MeshData, uvs: np.ndarray, name: str) -> MeshData:
    """``mesh`` with new texture coordinates (tangents follow the UVs, so they are rebuilt too)."""
    return replace(mesh, uvs=uvs, tangents=None, name=name).with_tangents()


def build_scene(impl: ModuleType) -> Scene:
    """``impl`` is the step's ``solutions`` or ``exercises`` package (brick_texture, cube_cross_uvs)."""
    scene = Scene("step03_textures")
    assets = scene.assets

    # Textures: one TextureData per look; its sampler settings (wrap, filter, mipmaps) travel with it.
    assets.texture("bricks", impl.brick_texture(128, 128, brick_size=(32, 16), mortar=2, seed=3))
    assets.texture("dice", dice_atlas(64))
    checker_colours = {"color_a": (0.98, 0.80, 0.25), "color_b": (0.16, 0.33, 0.62)}
    assets.texture("checker_repeat", checkerboard(64, 4, **checker_colours, wrap="repeat", name="checker_repeat"))
    assets.texture("checker_clamp", checkerboard(64, 4, **checker_colours, wrap="clamp", name="checker_clamp"))
    floor_colours = {"color_a": (0.92, 0.92, 0.90), "color_b": (0.18, 0.18, 0.20), "filter": "linear"}
    assets.texture("floor_mipmapped", checkerboard(64, 2, **floor_colours, mipmaps=True, name="floor_mipmapped"))
    assets.texture("floor_aliased", checkerboard(64, 2, **floor_colours, mipmaps=False, name="floor_aliased"))

    # Meshes: UVs beyond [0, 1] make the wrap mode visible; the floor repeats its texture many times.
    square = quad(1.0)
    box = cube(1.0)
    floor = plane(1.0)
    assets.mesh("quad", square)
    assets.mesh("die", with_uvs(box, impl.cube_cross_uvs(box.positions, box.normals), "die"))
    assets.mesh("quad_wide_uv", with_uvs(square, square.uvs * 3.0 - 1.0, "quad_wide_uv"))
    assets.mesh("floor", with_uvs(floor, floor.uvs * np.array([32.0, 160.0]), "floor"))

    for material, texture in (
        ("M_Bricks", "bricks"), ("M_Dice", "dice"), ("M_Repeat", "checker_repeat"), ("M_Clamp", "checker_clamp"),
        ("M_FloorMipmapped", "floor_mipmapped"), ("M_FloorAliased", "floor_aliased"),
    ):
        assets.material(material, MaterialData(SHADER, [texture], color=(1.0, 1.0, 1.0), name=material))

    scene.create_entity(InfoComponent("sky"), ClearColorComponent((0.62, 0.76, 0.90)))
    scene.create_entity(
        InfoComponent("camera"),
        TransformComponent(EYE, quaternion=look_at_rotation(EYE, TARGET)),
        CameraComponent(50.0, 0.1, 200.0),
    )
    scene.create_entity(
        InfoComponent("brick wall"), TransformComponent((-2.3, 1.1, 0.0), (0.0, 20.0, 0.0), 1.7),
        MeshComponent("quad"), MaterialComponent("M_Bricks"),
    )
    scene.create_entity(
        InfoComponent("die"), TransformComponent((0.0, 1.0, 0.4), (25.0, 35.0, 0.0), 1.3),
        MeshComponent("die"), MaterialComponent("M_Dice"), SpinComponent((0.0, 1.0, 0.0), 30.0),
    )
    scene.create_entity(
        InfoComponent("wrap: repeat"), TransformComponent((2.2, 1.65, 0.0), (0.0, -20.0, 0.0), 1.0),
        MeshComponent("quad_wide_uv"), MaterialComponent("M_Repeat"),
    )
    scene.create_entity(
        InfoComponent("wrap: clamp"), TransformComponent((2.2, 0.5, 0.0), (0.0, -20.0, 0.0), 1.0),
        MeshComponent("quad_wide_uv"), MaterialComponent("M_Clamp"),
    )
    # Two floor halves, 16 x 80 units each, reaching from just behind the camera towards the horizon.
    for side, material in ((-1, "M_FloorAliased"), (1, "M_FloorMipmapped")):
        scene.create_entity(
            InfoComponent(f"floor ({'mipmaps' if side > 0 else 'no mipmaps'})"),
            TransformComponent((8.0 * side, -0.3, -33.0), scale=(16.0, 1.0, 80.0)),
            MeshComponent("floor"), MaterialComponent(material),
        )
    scene.add_system(SpinSystem())
    return scene


#: What the variants (``opengl.py``, ``webgpu.py``) hand the launcher: this step, its scene and its shaders.
PART = Part(__package__, build_scene, SHADERS)
