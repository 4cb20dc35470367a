"""Step 04's scene, the same for OpenGL and WebGPU: objects on a ground plane, seen through two cameras.

* "orbit camera": perspective, primary; the exercise ``OrbitCameraSystem`` places it from an
  OrbitCameraComponent (drag with the left mouse button, scroll to zoom).
* "ortho camera": orthographic, not primary; ``LookAtSystem`` places it with the exercise ``look_at``.
* Press C to switch between them (``CameraSwitchSystem``).
"""

from __future__ import annotations

from pathlib import Path
from types import ModuleType

from gandalf_core import Application, ClearColorComponent, InfoComponent, Scene, TransformComponent
from gandalf_core.app.cli import Part, build_shaders
from gandalf_core.components import CameraComponent, MaterialComponent, MeshComponent
from gandalf_core.resources import MaterialData, checkerboard, primitives

from .components import LookAtComponent, OrbitCameraComponent
from .systems import CameraSwitchSystem, LookAtSystem

#: Frames the course tour renders before it takes the picture (at 60 frames per simulated second).
TOUR_FRAMES = 2
#: The shaders the variant files register: name -> file stem under ``shaders/``.
SHADERS = ("unlit", "normals")


def build_scene(impl: ModuleType) -> Scene:
    """``impl`` is the step's ``solutions`` or ``exercises`` package (look_at and OrbitCameraSystem)."""
    scene = Scene("step04_camera")
    assets = scene.assets
    assets.mesh("ground", primitives.plane(12.0, 1))
    assets.mesh("cube", primitives.cube())
    assets.mesh("roof", primitives.pyramid(1.2, 0.7))
    assets.mesh("sphere", primitives.uv_sphere(0.6, 32, 16))
    assets.mesh("torus", primitives.torus())
    assets.texture("tiles", checkerboard(64, 12, (0.85, 0.85, 0.85), (0.35, 0.38, 0.42)))
    assets.texture("crate", checkerboard(32, 4, (0.95, 0.75, 0.45), (0.7, 0.4, 0.2)))
    assets.material("ground", MaterialData("unlit", ["tiles"]))
    assets.material("crate", MaterialData("unlit", ["crate"]))
    assets.material("roof", MaterialData("unlit", ["crate"], color=(1.0, 0.55, 0.1)))
    assets.material("shape", MaterialData("normals"))

    scene.create_entity(InfoComponent("background"), ClearColorComponent((0.55, 0.7, 0.85)))
    scene.create_entity(
        InfoComponent("ground"), TransformComponent(), MeshComponent("ground"), MaterialComponent("ground")
    )
    scene.create_entity(
        InfoComponent("house"), TransformComponent((0.0, 0.5, 0.0), (0.0, 20.0, 0.0)),
        MeshComponent("cube"), MaterialComponent("crate"),
    )
    scene.create_entity(
        InfoComponent("roof"), TransformComponent((0.0, 1.0, 0.0), (0.0, 20.0, 0.0)),
        MeshComponent("roof"), MaterialComponent("roof"),
    )
    for i, x in enumerate((-3.0, 3.0)):
        scene.create_entity(
            InfoComponent(f"crate {i}"), TransformComponent((x, 0.35, -2.0 + 3.0 * i), (0.0, 35.0 * (i + 1), 0.0), 0.7),
            MeshComponent("cube"), MaterialComponent("crate"),
        )
    scene.create_entity(
        InfoComponent("ball"), TransformComponent((-2.0, 0.6, 2.0)), MeshComponent("sphere"), MaterialComponent("shape")
    )
    scene.create_entity(
        InfoComponent("ring"), TransformComponent((2.5, 1.0, -2.5), (60.0, 0.0, 0.0), 0.8),
        MeshComponent("torus"), MaterialComponent("shape"),
    )

    scene.create_entity(
        InfoComponent("orbit camera"), TransformComponent(), CameraComponent(50.0, 0.1, 100.0),
        OrbitCameraComponent(target=(0.0, 0.5, 0.0), distance=9.0, yaw=30.0, pitch=25.0),
    )
    scene.create_entity(
        InfoComponent("ortho camera"), TransformComponent(),
        CameraComponent(near=0.1, far=100.0, projection="orthographic", height=9.0, primary=False),
        LookAtComponent(eye=(8.0, 8.0, 8.0), target=(0.0, 0.5, 0.0)),
    )
    scene.add_system(impl.OrbitCameraSystem())
    scene.add_system(LookAtSystem(impl.look_at))
    scene.add_system(CameraSwitchSystem())
    return scene


def register_shaders(app: Application) -> None:
    """Build the step's shader table in ``app``'s API (the variants, the preview and the tests use it)."""
    build_shaders(app, SHADERS, Path(__file__).resolve().parent / "shaders")


#: What the variants (``opengl.py``, ``webgpu.py``) hand the launcher: this step, its scene and its shaders.
PART = Part(__package__, build_scene, SHADERS)
