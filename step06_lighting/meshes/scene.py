"""The meshes' scene, the same for OpenGL and WebGPU: the bunny read from a glTF file, part by part, a textured
crate read from an OBJ file and its PNG, and two spheres.

``load_meshes`` returns one ``MeshData`` per part with its node transform already applied, so the five parts hang
from one parent entity at identity and the bunny comes out whole; the file has no normals, the loader computes
them. Beside it a coarse (8 × 4) and a fine (64 × 32) ``uv_sphere``: the same smooth normals, a different outline.
:func:`add_bunny` is the helper the step's other scenes use to place the whole (merged) bunny.
"""

from __future__ import annotations

import uuid
from pathlib import Path
from types import ModuleType

from gandalf_core import ClearColorComponent, Scene, TransformComponent
from gandalf_core.app.cli import Part
from gandalf_core.components import (
    CameraComponent,
    InfoComponent,
    LightComponent,
    LinkComponent,
    MaterialComponent,
    MeshComponent,
)
from gandalf_core.math import look_at_rotation
from gandalf_core.resources import MaterialData, TextureData, plane, uv_sphere
from gandalf_core.resources.mesh_loader import load_mesh, load_meshes

from ..shaders import shader_table
from . import SHADERS
from .make_crate import CRATE_OBJ, CRATE_PNG

#: Frames the course tour renders before it takes the picture (at 60 frames per simulated second).
TOUR_FRAMES = 30
#: The step's model, shared by the concepts (and by step 07's explode and path tracer).
BUNNY_PATH = Path(__file__).resolve().parents[1] / "models" / "bunny.glb"
#: sRGB colour of each of the bunny's parts (the names of the glTF mesh nodes).
PART_COLORS = {"body": (0.86, 0.52, 0.36), "head": (0.93, 0.76, 0.42), "ear_left": (0.42, 0.62, 0.88),
               "ear_right": (0.42, 0.62, 0.88), "tail": (0.95, 0.95, 0.92)}
#: (segments, rings) of the two spheres: an outline of 8 sides, and one of 64.
SPHERES = ((8, 4), (64, 32))


def add_bunny_mesh(scene: Scene) -> None:
    """Register the whole bunny (its five parts merged) as the mesh ``bunny``."""
    scene.assets.mesh("bunny", load_mesh(BUNNY_PATH))


def add_bunny(scene: Scene, name: str, material: str, x: float) -> uuid.UUID:
    """A bunny (the mesh ``bunny``) of ``material`` standing on the floor at ``x``, turned 60° towards the right."""
    return scene.create_entity(InfoComponent(name), TransformComponent((x, 0.0, 0.0), rotation=(0.0, 60.0, 0.0)),
                               MeshComponent("bunny"), MaterialComponent(material))


def _phong(color: tuple[float, float, float]) -> MaterialData:
    return MaterialData("phong", color=color, params={"specular": 0.3, "shininess": 32.0})


# --8<-- [start:crate]
def add_crate(scene: Scene, position: tuple[float, float, float], turn: float) -> uuid.UUID:
    """The textured model: the crate's mesh from its OBJ file, its wood from the PNG beside
    it, lit by the textured Blinn-Phong shader (``phong_textured``: the material colour
    times the texture is the albedo)."""
    scene.assets.mesh("crate", load_mesh(CRATE_OBJ))
    scene.assets.texture("crate", TextureData(CRATE_PNG))
    wood = MaterialData("phong_textured", ["crate"], color=(1.0, 1.0, 1.0),
                        params={"specular": 0.15, "shininess": 16.0})
    scene.assets.material("crate", wood)
    place = TransformComponent(position, rotation=(0.0, turn, 0.0))
    return scene.create_entity(InfoComponent("crate"), place, MeshComponent("crate"),
                               MaterialComponent("crate"))
# --8<-- [end:crate]


def build_scene(impl: ModuleType | None = None) -> Scene:
    """The bunny's parts, two spheres and a floor under a key and an ambient light (``impl`` is unused: the
    variants pass the step's, and the lit shaders include its ``shading``)."""
    scene = Scene("step06_lighting.meshes")
    assets = scene.assets
    # --8<-- [start:parts]
    bunny = scene.create_entity(InfoComponent("bunny"),
                                TransformComponent((-1.3, 0.0, 0.0), rotation=(0.0, 60.0, 0.0)))
    for part, mesh in load_meshes(BUNNY_PATH).items():  # one MeshData per glTF mesh node, placed
        assets.mesh(f"bunny.{part}", mesh)
        assets.material(f"bunny.{part}", _phong(PART_COLORS[part]))
        scene.create_entity(InfoComponent(part), TransformComponent(), LinkComponent(bunny),
                            MeshComponent(f"bunny.{part}"), MaterialComponent(f"bunny.{part}"))
    # --8<-- [end:parts]
    assets.material("sphere", _phong((0.35, 0.6, 0.45)))
    for k, (segments, rings) in enumerate(SPHERES):
        assets.mesh(f"sphere {segments}x{rings}", uv_sphere(0.6, segments, rings))
        scene.create_entity(InfoComponent(f"sphere {segments}x{rings}"),
                            TransformComponent((0.9 + 1.5 * k, 0.6, 0.4)),
                            MeshComponent(f"sphere {segments}x{rings}"), MaterialComponent("sphere"))
    add_crate(scene, (0.05, 0.0, -1.25), 30.0)
    scene.create_entity(InfoComponent("background"), ClearColorComponent((0.1, 0.11, 0.14)))
    assets.mesh("floor", plane(14.0, 8))
    assets.material("floor", _phong((0.55, 0.56, 0.6)))
    scene.create_entity(InfoComponent("floor"), TransformComponent(), MeshComponent("floor"),
                        MaterialComponent("floor"))
    key = (-4.0, 6.0, 5.0)
    scene.create_entity(InfoComponent("key light"),
                        TransformComponent(key, quaternion=look_at_rotation(key, (0, 0, 0))),
                        LightComponent("directional", (1.0, 0.96, 0.9), intensity=1.0))
    scene.create_entity(InfoComponent("ambient"), TransformComponent(), LightComponent("ambient", (0.2, 0.22, 0.27)))
    eye = (0.0, 1.9, 5.6)
    camera = TransformComponent(eye, quaternion=look_at_rotation(eye, (0.1, 0.7, 0.0)))
    scene.create_entity(InfoComponent("camera"), camera, CameraComponent(45.0, 0.1, 100.0))
    return scene


#: What the variants (``opengl.py``, ``webgpu.py``) hand the launcher: this concept, its scene and the
#: step's shaders it uses (with the implementation's ``shading``).
PART = Part(__package__, build_scene, shader_table(SHADERS), include_impl=True)
