"""The hierarchy's scene, the same for OpenGL and WebGPU: a solar system built from parent links.

``build_scene(impl)`` returns it (``impl`` is unused: the hierarchy has no exercise). :func:`add_child`,
:func:`add_camera` and :func:`add_floor` are the helpers the step's other scenes reuse. Resource names carry the
scene's name as a prefix (``solar.sphere``): the scenes of ``several_scenes`` share one renderer, which caches GPU
objects by name.
"""

from __future__ import annotations

import uuid
from types import ModuleType

import numpy as np

from gandalf_core import ClearColorComponent, Component, InfoComponent, LinkComponent, Scene, TransformComponent
from gandalf_core.app.cli import Part
from gandalf_core.components import CameraComponent, MaterialComponent, MeshComponent
from gandalf_core.math import look_at_rotation
from gandalf_core.resources import MaterialData, TextureData, plane, uv_sphere, value_noise
from gandalf_core.systems import SpinComponent, SpinSystem

from .. import SHADERS
from .components import ReparentOnKeyComponent
from .systems import ReparentSystem

#: Frames the course tour renders before it takes the picture (at 60 frames per simulated second).
TOUR_FRAMES = 90


def add_camera(scene: Scene, eye: tuple[float, float, float], target: tuple[float, float, float],
               fov: float) -> uuid.UUID:
    """A perspective camera at ``eye`` looking at ``target`` (``fov``: vertical, degrees)."""
    eye_arr = np.asarray(eye, dtype=np.float64)
    return scene.create_entity(
        InfoComponent("camera"),
        TransformComponent(eye_arr, quaternion=look_at_rotation(eye_arr, target)),
        CameraComponent(fov, 0.1, 100.0),
    )


def add_floor(scene: Scene, prefix: str) -> None:
    """A dark background and a 14 m x 6 m grey-green floor just below y = 0 (mesh and material ``<prefix>.floor``)."""
    name = f"{prefix}.floor"
    scene.assets.mesh(name, plane(1.0))
    scene.assets.material(name, MaterialData("shaded", color=(0.35, 0.4, 0.35), name=name))
    scene.create_entity(InfoComponent("background"), ClearColorComponent((0.12, 0.12, 0.15)))
    scene.create_entity(InfoComponent("floor"), TransformComponent((0.0, -0.05, 0.0), scale=(14.0, 1.0, 6.0)),
                        MeshComponent(name), MaterialComponent(name))


# --8<-- [start:child]
def add_child(scene: Scene, name: str, parent: uuid.UUID | None, *components: Component,
              **transform) -> uuid.UUID:
    """An entity with a name, a Transform (``transform``: its local pose) and a Link to ``parent``
    (None: a root)."""
    return scene.create_entity(InfoComponent(name), TransformComponent(**transform),
                               LinkComponent(parent), *components)
# --8<-- [end:child]


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

    # --8<-- [start:solar]
    sphere = MeshComponent("solar.sphere")
    root = add_child(scene, "solar system", None)
    # Each body spins about its own (local=True) axis: the earth's is tilted by 23°.
    add_child(scene, "sun", root, sphere, MaterialComponent("solar.sun"),
              SpinComponent((0, 1, 0), 10.0, local=True), scale=1.2)
    earth_orbit = add_child(scene, "earth orbit", root, SpinComponent((0, 1, 0), 36.0, local=True))
    earth_carrier = add_child(scene, "earth carrier", earth_orbit, translation=(3.4, 0.0, 0.0))
    add_child(
        scene, "earth", earth_carrier, MeshComponent("solar.sphere"), MaterialComponent("solar.earth"),
        SpinComponent((0, 1, 0), 90.0, local=True), rotation=(0.0, 0.0, 23.0), scale=0.45,
    )
    moon_orbit = add_child(scene, "moon orbit", earth_carrier,
                           SpinComponent((0, 1, 0), 120.0, local=True))
    add_child(
        scene, "moon", moon_orbit, MeshComponent("solar.sphere"), MaterialComponent("solar.moon"),
        ReparentOnKeyComponent(root, key="M"), translation=(0.85, 0.0, 0.0), scale=0.14,
    )
    mars_orbit = add_child(scene, "mars orbit", root, SpinComponent((0, 1, 0), 20.0, local=True),
                           rotation=(0.0, 140.0, 0.0))
    add_child(
        scene, "mars", mars_orbit, MeshComponent("solar.sphere"), MaterialComponent("solar.mars"),
        SpinComponent((0, 1, 0), 70.0, local=True), translation=(5.2, 0.0, 0.0), scale=0.32,
    )
    # --8<-- [end:solar]
    add_camera(scene, (0.0, 4.5, 9.5), (0.0, -0.3, 0.0), 50.0)
    scene.add_system(SpinSystem())
    scene.add_system(ReparentSystem())
    return scene


def build_scene(impl: ModuleType | None = None) -> Scene:
    """The solar system (the variants pass the step's ``impl``; the hierarchy has no exercise)."""
    return build_solar_scene()


#: What the variants (``opengl.py``, ``webgpu.py``) hand the launcher: this concept, its scene and the step's shaders.
PART = Part(__package__, build_scene, SHADERS)
