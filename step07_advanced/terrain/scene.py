"""The terrain's scene, the same for OpenGL and WebGPU: a fractal heightfield seen from just above a valley.

The variant files pass a small backend object (:class:`TerrainBackend`): OpenGL's gives a patch mesh and a
material whose program tessellates it; WebGPU's gives a plain vertex count and a material that pulls vertices
from a storage buffer, plus a per-frame hook that runs its compute pass for the camera's position
(:class:`TessellationSystem`). Everything else (heightmap, camera, lights, haze) is written once, here.
"""

from __future__ import annotations

import functools
from types import ModuleType
from typing import Any, Protocol

import numpy as np

from gandalf_core import Scene, TransformComponent
from gandalf_core.app.cli import Needs, Part
from gandalf_core.components import (
    CameraComponent,
    ClearColorComponent,
    InfoComponent,
    LightComponent,
    MaterialComponent,
    MeshComponent,
)
from gandalf_core.ecs import System
from gandalf_core.math import look_at_rotation
from gandalf_core.resources import MaterialData, MeshData

from .heightfield import encode_heights, fractal_heights
from .patches import TerrainParams

#: Frames the course tour renders before it takes the picture (the scene is still: one is enough; two to be sure
#: WebGPU's compute pass has run for the final camera).
TOUR_FRAMES = 2
HEIGHTMAP_SIZE = 256
#: The haze and the sky behind the terrain (sRGB).
HAZE = (0.62, 0.72, 0.84)
EYE = (0.0, 4.2, 11.0)
TARGET = (0.0, 1.2, -4.0)
FOV = 50.0
PARAMS = TerrainParams()


@functools.cache
def terrain_heights(size: int = HEIGHTMAP_SIZE) -> np.ndarray:
    """The scene's heightmap (deterministic, cached): (size, size) float64 in [0, 1]."""
    heights = fractal_heights(size)
    heights.flags.writeable = False
    return heights


class TerrainBackend(Protocol):
    """What :func:`build_scene` needs from a variant: the terrain's mesh and material, and a per-frame hook."""

    params: TerrainParams

    def mesh(self) -> MeshData: ...

    def material(self, base: MaterialData) -> MaterialData: ...

    def update(self, eye: np.ndarray) -> None: ...


def terrain_material(params: TerrainParams) -> MaterialData:
    """The material both variants start from: the terrain shader, the heightmap, the terrain's shape and LOD."""
    values = {"size": params.size, "height_scale": params.height_scale, "lod": (*params.lod, 0.0)}
    return MaterialData("terrain", ["heightmap"], color=HAZE, params=values, cull="none", name="terrain")


class TessellationSystem(System):
    """Once per frame, before the frame is drawn: hands the first camera's position to the backend."""

    def __init__(self, backend: TerrainBackend) -> None:
        super().__init__((CameraComponent, TransformComponent))
        self.backend = backend

    def on_update_system(self, ts: float) -> None:
        if self.components:
            transform = self.components[0][1]
            self.backend.update(np.asarray(transform.translation, dtype=np.float64))


def build_scene(impl: ModuleType, terrain: TerrainBackend, eye: Any = EYE, target: Any = TARGET,
                heights: np.ndarray | None = None) -> Scene:
    """The terrain scene. ``impl`` is the exercises or the solutions package (the variant built its shaders
    from it); ``terrain`` is the variant's backend; ``heights`` replaces the fractal heightmap."""
    scene = Scene("terrain")
    scene.assets.texture("heightmap", encode_heights(terrain_heights() if heights is None else heights))
    scene.assets.mesh("terrain", terrain.mesh())
    scene.assets.material("terrain", terrain.material(terrain_material(terrain.params)))
    scene.create_entity(InfoComponent("terrain"), TransformComponent(), MeshComponent("terrain"),
                        MaterialComponent("terrain"))
    sun = (-6.0, 3.2, 1.5)
    scene.create_entity(InfoComponent("sun"), TransformComponent(sun, quaternion=look_at_rotation(sun, (0, 0, 0))),
                        LightComponent("directional", (1.0, 0.95, 0.85), intensity=2.4))
    scene.create_entity(InfoComponent("sky light"), TransformComponent(), LightComponent("ambient", HAZE,
                                                                                          intensity=0.22))
    eye = np.asarray(eye, dtype=np.float64)
    scene.create_entity(InfoComponent("camera"), TransformComponent(eye, quaternion=look_at_rotation(eye, target)),
                        CameraComponent(FOV, 0.1, 100.0), ClearColorComponent(HAZE))
    scene.add_system(TessellationSystem(terrain))
    return scene


# In saved scenes (step07_advanced.usd): refused, naming why.


#: The technique the variants (``opengl.py``, ``webgpu.py``) hand the launcher with their backends.
PART = Part(__package__, needs=Needs(opengl=400, opengl_for="tessellation shaders"))
