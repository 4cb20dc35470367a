"""Step 07's scene, the same for OpenGL and WebGPU: PBR, normal and parallax mapping, and a GPU particle fountain.

A chart of spheres shows the metallic-roughness model (rows: metallic 0, 0.5, 1; columns: roughness 0 to 1)
under a sun, two point lights and the sky. The floor and a turning cube are brick walls made of three
procedural maps: parallax occlusion mapping shifts the UVs by the height map, the normal map bends the
shading normal. On the right a fountain of small copper cubes follows particles that a compute shader
simulates on the GPU; the variant files pass that kernel in (the numpy twin stands in without one).
The sun casts shadows of all of it onto the floor (a shadow map, drawn by the core renderers).
"""

from __future__ import annotations

from types import ModuleType

import numpy as np

from gandalf_core import Scene, TransformComponent
from gandalf_core.app.cli import Needs, Part
from gandalf_core.components import (
    CameraComponent,
    InfoComponent,
    LightComponent,
    MaterialComponent,
    MeshComponent,
    SkyboxComponent,
)
from gandalf_core.math import look_at_rotation
from gandalf_core.resources import MaterialData, cube, plane, sky_cube, uv_sphere
from gandalf_core.systems import SpinComponent, SpinSystem

from .particles import (
    NumpyParticleKernel,
    ParticleComponent,
    ParticleKernel,
    ParticleSystem,
    SimParams,
    initial_particles,
)
from .textures import brick_textures

#: Frames the course tour renders before it takes the picture (at 60 frames per simulated second).
TOUR_FRAMES = 60
PARTICLE_COUNT = 384
FOUNTAIN = SimParams(emitter=(2.9, 0.1, 0.4), floor_y=0.035)
METALLIC = (0.0, 0.5, 1.0)
ROUGHNESS = (0.0, 0.25, 0.5, 0.75, 1.0)
BRICKS = ["bricks_albedo", "bricks_normal", "bricks_height", "sky"]


def add_materials(scene: Scene) -> None:
    """The sky, the brick maps and the step's materials (the PBR chart's one per sphere)."""
    assets = scene.assets
    assets.texture("sky", sky_cube(128))
    for name, texture in brick_textures(256).items():
        assets.texture(name, texture)
    pbr = {"env_strength": 1.0}
    for i, metallic in enumerate(METALLIC):
        for j, roughness in enumerate(ROUGHNESS):
            params = {**pbr, "metallic": metallic, "roughness": roughness}
            assets.material(f"chart_{i}_{j}", MaterialData("pbr", ["sky"], color=(0.95, 0.64, 0.38), params=params))
    assets.material("copper", MaterialData("pbr", ["sky"], color=(0.96, 0.62, 0.48),
                                           params={**pbr, "metallic": 1.0, "roughness": 0.3}))
    bricks = {**pbr, "metallic": 0.0, "roughness": 0.8}
    assets.material("floor", MaterialData("bumpy", BRICKS, params={**bricks, "height_scale": 0.05, "uv_scale": 8.0}))
    assets.material("brick_cube", MaterialData("bumpy", BRICKS, params={**bricks, "height_scale": 0.06,
                                                                        "uv_scale": 1.0}))


def add_lights(scene: Scene) -> None:
    """A shadow-casting sun from the front left, a warm and a cool point light, and a little ambient.

    The sun's shadow box is centred on its position, 8 units from the middle of the scene: 12 units wide
    across the light covers everything that casts or receives a shadow, 28 long reaches past the floor.
    """
    sun = (-3.0, 6.0, 4.5)
    scene.create_entity(InfoComponent("sun"), TransformComponent(sun, quaternion=look_at_rotation(sun, (0, 0, 0))),
                        LightComponent("directional", (1.0, 0.96, 0.9), intensity=2.6, cast_shadows=True,
                                       shadow_extent=6.0, shadow_depth=28.0))
    scene.create_entity(InfoComponent("warm light"), TransformComponent((1.6, 2.6, 1.6)),
                        LightComponent("point", (1.0, 0.75, 0.5), intensity=6.0, range=7.0))
    scene.create_entity(InfoComponent("cool light"), TransformComponent((-2.8, 2.0, 2.2)),
                        LightComponent("point", (0.55, 0.7, 1.0), intensity=5.0, range=7.0))
    scene.create_entity(InfoComponent("ambient"), TransformComponent(),
                        LightComponent("ambient", (0.03, 0.03, 0.035)))


def build_scene(impl: ModuleType, particles: ParticleKernel | None = None) -> Scene:
    """The demo scene. ``impl`` (exercises or solutions) provides the shader includes the variant files build
    the shaders with; ``particles`` is the GPU kernel of the fountain (default: the numpy twin)."""
    scene = Scene("step07_advanced")
    add_materials(scene)
    scene.assets.mesh("floor", plane(14.0, 1))
    scene.assets.mesh("ball", uv_sphere(0.32, 48, 24))
    scene.assets.mesh("block", cube(1.2))
    scene.assets.mesh("grain", cube(0.07))
    scene.create_entity(InfoComponent("sky"), SkyboxComponent("sky"))
    scene.create_entity(InfoComponent("floor"), TransformComponent(), MeshComponent("floor"),
                        MaterialComponent("floor"))
    for i in range(len(METALLIC)):
        for j in range(len(ROUGHNESS)):
            position = (-0.6 + 0.78 * (j - 2), 0.45 + 0.78 * i, -1.2)
            scene.create_entity(InfoComponent(f"sphere m{METALLIC[i]} r{ROUGHNESS[j]}"), TransformComponent(position),
                                MeshComponent("ball"), MaterialComponent(f"chart_{i}_{j}"))
    scene.create_entity(InfoComponent("brick cube"), TransformComponent((-3.0, 0.75, 0.9), rotation=(0, 30, 0)),
                        SpinComponent((0.0, 1.0, 0.0), 18.0), MeshComponent("block"), MaterialComponent("brick_cube"))
    kernel = particles if particles is not None else NumpyParticleKernel(fountain_state())
    for k in range(PARTICLE_COUNT):
        scene.create_entity(TransformComponent(FOUNTAIN.emitter), ParticleComponent(k), MeshComponent("grain"),
                            MaterialComponent("copper"))
    add_lights(scene)
    eye = (0.0, 2.7, 8.2)
    scene.create_entity(InfoComponent("camera"), TransformComponent(eye, quaternion=look_at_rotation(eye, (0, 1.1, 0))),
                        CameraComponent(42.0, 0.1, 100.0))
    scene.add_system(SpinSystem())
    scene.add_system(ParticleSystem(kernel, FOUNTAIN))
    return scene


def fountain_state() -> np.ndarray:
    """The fountain's particles after their warm-up: the state every kernel starts from."""
    return initial_particles(PARTICLE_COUNT, FOUNTAIN)


#: The technique the variants (``opengl.py``, ``webgpu.py``) hand the launcher with their backends.
PART = Part(__package__, needs=Needs(opengl=430, opengl_for="compute shaders for its particles"))
