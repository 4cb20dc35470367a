"""The environment's scene, the same for OpenGL and WebGPU: a silver and an ice bunny under a sky read from six files.

No light is needed: both materials take their colour from the sky's cube map, the one the skybox draws behind
everything. :func:`add_sky` and :func:`add_environment_materials` are the helpers the step's whole scene reuses.
"""

from __future__ import annotations

from types import ModuleType

from gandalf_core import Scene, TransformComponent
from gandalf_core.app.cli import Part
from gandalf_core.components import CameraComponent, InfoComponent, SkyboxComponent
from gandalf_core.math import look_at_rotation
from gandalf_core.resources import CubeTextureData, MaterialData

from ..meshes.scene import add_bunny, add_bunny_mesh
from ..shaders import shader_table
from . import SHADERS
from .make_sky import SKY_FILES

#: Frames the course tour renders before it takes the picture (at 60 frames per simulated second).
TOUR_FRAMES = 30


# --8<-- [start:sky]
def add_sky(scene: Scene) -> None:
    """The sky cube map (texture ``sky``), read from its six face files in +X, -X, +Y, -Y, +Z, -Z
    order (``models/sky/``, written by ``make_sky.py``), and the skybox that draws it behind
    everything."""
    sky = CubeTextureData.from_files(SKY_FILES, name="sky")
    scene.assets.texture("sky", sky)
    scene.create_entity(InfoComponent("sky"), SkyboxComponent("sky"))


def add_environment_materials(scene: Scene) -> None:
    """``silver`` mirrors the sky; ``ice`` refracts it (index of refraction 1.31), reflects some."""
    scene.assets.material("silver", MaterialData("mirror", ["sky"], color=(0.96, 0.95, 0.92)))
    scene.assets.material("ice", MaterialData("glass", ["sky"], color=(0.82, 0.93, 1.0),
                                              params={"ior": 1.31}))
# --8<-- [end:sky]


def build_scene(impl: ModuleType | None = None) -> Scene:
    """The two bunnies and the sky (``impl`` is unused: the variants pass the step's, and the shaders include its
    ``shading``, where ``reflect_direction`` and ``refract_direction`` live)."""
    scene = Scene("step06_lighting.environment")
    add_sky(scene)
    add_environment_materials(scene)
    add_bunny_mesh(scene)
    add_bunny(scene, "silver bunny", "silver", -1.15)
    add_bunny(scene, "ice bunny", "ice", 1.15)
    eye = (0.0, 1.5, 5.2)
    camera = TransformComponent(eye, quaternion=look_at_rotation(eye, (0.0, 0.85, 0.0)))
    scene.create_entity(InfoComponent("camera"), camera, CameraComponent(40.0, 0.1, 100.0))
    return scene


#: What the variants (``opengl.py``, ``webgpu.py``) hand the launcher: this concept, its scene and the
#: step's shaders it uses (with the implementation's ``shading``).
PART = Part(__package__, build_scene, shader_table(SHADERS), include_impl=True)
