"""Step 05's scenes, the same for OpenGL and WebGPU: a solar system, the house, and springs.

``build_scenes(impl)`` returns all three (the app switches between them with keys 1/2/3 or TAB);
``build_scene(impl)`` returns the first, for the course tour. Resource names carry the scene's name as a
prefix: a renderer caches GPU objects by name, and the scenes share one renderer.
"""

from __future__ import annotations

from types import ModuleType

import numpy as np

from gandalf_core import ClearColorComponent, InfoComponent, LinkComponent, Scene, TransformComponent
from gandalf_core.components import CameraComponent, MaterialComponent, MeshComponent
from gandalf_core.math import look_at_rotation
from gandalf_core.resources import MaterialData, TextureData, cube, plane, uv_sphere, value_noise

from .components import (
    GravityComponent,
    HouseRotationComponent,
    ReparentOnKeyComponent,
    SpinComponent,
    SpringComponent,
)
from .systems import GravitySystem, ReparentSystem, SceneSwitchSystem, SpinSystem, SpringSystem

#: Frames the course tour renders before it takes the picture (at 60 frames per simulated second).
TOUR_FRAMES = 90

#: Which key shows which scene.
SCENE_KEYS = {"1": "solar", "2": "house", "3": "springs"}

#: The shaders this step's variants register (GLSL ``<name>.vert/.frag`` or ``<name>.wgsl`` in ``shaders/``).
SHADERS = ("unlit_textured", "shaded", "shaded_textured")


def _camera(scene: Scene, eye: tuple[float, float, float], target: tuple[float, float, float], fov: float) -> None:
    eye_arr = np.asarray(eye, dtype=np.float64)
    scene.create_entity(
        InfoComponent("camera"),
        TransformComponent(eye_arr, quaternion=look_at_rotation(eye_arr, target)),
        CameraComponent(fov, 0.1, 100.0),
    )


def _child(scene: Scene, name: str, parent, *components, **transform) -> object:
    """An entity with a name, a Transform and a Link to ``parent`` (None for a root)."""
    return scene.create_entity(InfoComponent(name), TransformComponent(**transform), LinkComponent(parent), *components)


def build_solar_scene() -> Scene:
    """Sun, earth with its moon, and mars: each body hangs from an orbit pivot that spins about the sun.

    An orbit pivot is an entity without a mesh; turning it carries its children around. Scales stay on the
    bodies (leaves), so a moon's orbit radius is not shrunk by the earth's size. Press M to move the moon
    under the sun's root and back, keeping its world pose.
    """
    scene = Scene("solar")
    assets = scene.assets
    assets.mesh("solar.sphere", uv_sphere(1.0, 32, 16))
    noise = value_noise(64, seed=5, cells=4, octaves=3).pixels[..., :3] / 255.0
    sun_rgb = np.array([1.0, 0.78, 0.25]) * (0.75 + 0.25 * noise)
    assets.texture("solar.sun", TextureData.from_array(sun_rgb, name="solar.sun"))
    assets.material("solar.sun", MaterialData("unlit_textured", ["solar.sun"], name="solar.sun"))
    assets.material("solar.earth", MaterialData("shaded", color=(0.2, 0.45, 0.9), name="solar.earth"))
    assets.material("solar.moon", MaterialData("shaded", color=(0.75, 0.75, 0.72), name="solar.moon"))
    assets.material("solar.mars", MaterialData("shaded", color=(0.85, 0.35, 0.2), name="solar.mars"))
    scene.create_entity(InfoComponent("background"), ClearColorComponent((0.02, 0.02, 0.06)))

    sphere = MeshComponent("solar.sphere")
    root = _child(scene, "solar system", None)
    _child(scene, "sun", root, sphere, MaterialComponent("solar.sun"), SpinComponent((0, 1, 0), 10.0), scale=1.2)
    earth_orbit = _child(scene, "earth orbit", root, SpinComponent((0, 1, 0), 36.0))
    earth_carrier = _child(scene, "earth carrier", earth_orbit, translation=(3.4, 0.0, 0.0))
    _child(
        scene, "earth", earth_carrier, MeshComponent("solar.sphere"), MaterialComponent("solar.earth"),
        SpinComponent((0, 1, 0), 90.0), rotation=(0.0, 0.0, 23.0), scale=0.45,
    )
    moon_orbit = _child(scene, "moon orbit", earth_carrier, SpinComponent((0, 1, 0), 120.0))
    _child(
        scene, "moon", moon_orbit, MeshComponent("solar.sphere"), MaterialComponent("solar.moon"),
        ReparentOnKeyComponent(root, key="M"), translation=(0.85, 0.0, 0.0), scale=0.14,
    )
    mars_orbit = _child(scene, "mars orbit", root, SpinComponent((0, 1, 0), 20.0), rotation=(0.0, 140.0, 0.0))
    _child(
        scene, "mars", mars_orbit, MeshComponent("solar.sphere"), MaterialComponent("solar.mars"),
        SpinComponent((0, 1, 0), 70.0), translation=(5.2, 0.0, 0.0), scale=0.32,
    )
    _camera(scene, (0.0, 4.5, 9.5), (0.0, -0.3, 0.0), 50.0)
    scene.add_system(SpinSystem())
    scene.add_system(ReparentSystem())
    return scene


def build_house_scene(impl: ModuleType) -> Scene:
    """The capstone: ``impl`` provides the five milestones (meshes, texture, materials, camera, rotation)."""
    scene = Scene("house")
    walls, roof = impl.house_meshes()
    scene.assets.mesh("house.walls", walls)
    scene.assets.mesh("house.roof", roof)
    scene.assets.texture("house.brick", impl.brick_texture_data())
    for name, material in impl.house_material_data().items():
        scene.assets.material(name, material)
    scene.create_entity(InfoComponent("background"), ClearColorComponent((0.55, 0.75, 0.95)))
    house = _child(scene, "house", None, HouseRotationComponent(speed=45.0))
    _child(scene, "walls", house, MeshComponent("house.walls"), MaterialComponent("house.walls"))
    _child(scene, "roof", house, MeshComponent("house.roof"), MaterialComponent("house.roof"))
    camera, transform = impl.house_camera(None)
    scene.create_entity(InfoComponent("camera"), camera, transform)
    scene.add_system(impl.HouseRotationSystem())
    return scene


#: The four integrators side by side in the springs scene, each with its colour.
SPRING_COLUMNS = (
    ("explicit_euler", (0.9, 0.25, 0.2)),
    ("semi_implicit_euler", (0.3, 0.8, 0.3)),
    ("rk4", (0.25, 0.45, 0.95)),
    ("implicit_euler", (0.95, 0.8, 0.2)),
)


def build_springs_scene() -> Scene:
    """Four damped springs (one per integrator, same k, m, c and start) and three bouncing balls.

    Explicit Euler gains energy every step until its mass runs away and is reset; implicit Euler loses
    energy too fast; semi-implicit Euler and RK4 follow the true motion.
    """
    scene = Scene("springs")
    assets = scene.assets
    assets.mesh("springs.cube", cube(1.0))
    assets.mesh("springs.ball", uv_sphere(1.0, 24, 12))
    assets.mesh("springs.floor", plane(1.0))
    assets.material("springs.anchor", MaterialData("shaded", color=(0.6, 0.6, 0.65), name="springs.anchor"))
    assets.material("springs.floor", MaterialData("shaded", color=(0.35, 0.4, 0.35), name="springs.floor"))
    assets.material("springs.ball", MaterialData("shaded", color=(0.9, 0.9, 0.9), name="springs.ball"))
    scene.create_entity(InfoComponent("background"), ClearColorComponent((0.12, 0.12, 0.15)))
    scene.create_entity(
        InfoComponent("floor"), TransformComponent((0.0, -0.05, 0.0), scale=(14.0, 1.0, 6.0)),
        MeshComponent("springs.floor"), MaterialComponent("springs.floor"),
    )
    for i, (integrator, color) in enumerate(SPRING_COLUMNS):
        x = -3.6 + 1.6 * i
        material = f"springs.{integrator}"
        assets.material(material, MaterialData("shaded", color=color, name=material))
        scene.create_entity(
            InfoComponent(f"anchor {integrator}"), TransformComponent((x, 3.6, 0.0), scale=(0.6, 0.1, 0.6)),
            MeshComponent("springs.cube"), MaterialComponent("springs.anchor"),
        )
        scene.create_entity(
            InfoComponent(f"mass {integrator}"), TransformComponent((x, 3.0, 0.0), scale=0.5),
            MeshComponent("springs.cube"), MaterialComponent(material),
            SpringComponent(rest=(x, 2.0, 0.0), stiffness=40.0, mass=1.0, damping=0.2, integrator=integrator),
        )
    for i, height in enumerate((1.5, 2.5, 3.5)):
        scene.create_entity(
            InfoComponent(f"ball {i}"), TransformComponent((3.2 + 0.7 * i, height, 0.8), scale=0.25),
            MeshComponent("springs.ball"), MaterialComponent("springs.ball"),
            GravityComponent(floor=0.25, restitution=0.8),
        )
    _camera(scene, (0.0, 2.6, 9.0), (0.0, 1.7, 0.0), 50.0)
    scene.add_system(SpringSystem())
    scene.add_system(GravitySystem())
    return scene


def build_scenes(impl: ModuleType) -> list[Scene]:
    """All three scenes, each with a system that switches scenes on the keys of :data:`SCENE_KEYS`."""
    scenes = [build_solar_scene(), build_house_scene(impl), build_springs_scene()]
    for scene in scenes:
        scene.add_system(SceneSwitchSystem(SCENE_KEYS), index=0)
    return scenes


def build_scene(impl: ModuleType) -> Scene:
    """The first scene (the solar system), for the course tour."""
    return build_scenes(impl)[0]
