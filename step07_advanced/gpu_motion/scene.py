"""The GPU-driven motion scene, the same for OpenGL and WebGPU: ``count`` cubes on a grid, each spinning about
its own axis at its own speed, lit by one light. ``path`` picks where the spin is evaluated: ``"entity"`` or
``"batch"`` (``SpinSystem``'s paths, on the CPU) or ``"gpu"`` (this technique's :class:`~.system.GpuSpinSystem`);
the picture at time t is the same on every path.
"""

from __future__ import annotations

import math
from types import ModuleType

import numpy as np

from gandalf_core import Scene, TransformComponent
from gandalf_core.app.cli import Part
from gandalf_core.components import (
    CameraComponent,
    ClearColorComponent,
    InfoComponent,
    LightComponent,
    MaterialComponent,
    MeshComponent,
)
from gandalf_core.math import look_at_rotation
from gandalf_core.render.capabilities import Needs
from gandalf_core.resources import MaterialData, primitives
from gandalf_core.systems.spin import SpinComponent, SpinSystem

from .system import GpuSpinSystem

#: Cubes in the demo.
COUNT = 1000
#: Frames the course tour renders before it takes the picture.
TOUR_FRAMES = 30
BACKGROUND = (0.06, 0.07, 0.1)
SPACING = 1.6


def spins(count: int) -> tuple[np.ndarray, np.ndarray]:
    """Each cube's spin: a unit axis (tilted a little from +Y, different per cube) and a speed in °/s."""
    i = np.arange(count)
    tilt = 0.35 * np.sin(1.7 * i)
    axes = np.stack([tilt * np.cos(2.3 * i), np.ones(count), tilt * np.sin(2.3 * i)], 1)
    axes /= np.linalg.norm(axes, axis=1, keepdims=True)
    return axes, 40.0 + 25.0 * (i % 5)


def grid(count: int) -> np.ndarray:
    """``count`` positions on a cubic grid centred on the origin (x, y) and going away from the camera (z)."""
    side = math.ceil(round(count ** (1.0 / 3.0), 9))
    i = np.arange(count)
    return np.stack([(i % side) - (side - 1) / 2, (i // side % side) - (side - 1) / 2, -(i // (side * side))],
                    1) * SPACING


def build_scene(impl: ModuleType | None = None, *, path: str = "gpu", count: int = COUNT, local: bool = False
                ) -> Scene:
    """``count`` spinning cubes whose spin runs on ``path``; the camera sees them all. ``local``: each cube spins
    about its own (tilted) axis instead of the world's."""
    del impl  # no exercise: the scene is the same for the exercises and the solutions
    scene = Scene("step07_gpu_motion")
    scene.assets.mesh("cube", primitives.cube())
    scene.assets.material("cube", MaterialData("gandalf.blinn_phong", color=(0.85, 0.55, 0.3)))
    scene.create_entity(InfoComponent("background"), ClearColorComponent(BACKGROUND))
    sun = (3.0, 5.0, 4.0)
    scene.create_entity(InfoComponent("sun"), TransformComponent(sun, quaternion=look_at_rotation(sun, (0, 0, 0))),
                        LightComponent("directional", (1.0, 0.97, 0.92), intensity=1.0))
    scene.create_entity(InfoComponent("ambient"), TransformComponent(), LightComponent("ambient", (0.2, 0.2, 0.25)))
    side = math.ceil(round(count ** (1.0 / 3.0), 9))
    eye = np.array([0.35 * side * SPACING, 0.45 * side * SPACING, 1.2 * side * SPACING + 2.0])
    scene.create_entity(InfoComponent("camera"),
                        TransformComponent(eye, quaternion=look_at_rotation(eye, (0.0, 0.0, -0.5 * side * SPACING))),
                        CameraComponent(50.0, 0.1, 10.0 * side * SPACING + 50.0))
    axes, speeds = spins(count)
    start = np.radians(37.0 * np.arange(count))
    # A start pose turned about a tilted axis, so that a local spin axis differs from the world's.
    tilt = np.array([0.3, 1.0, 0.2]) / np.linalg.norm([0.3, 1.0, 0.2])
    quaternions = np.concatenate([np.cos(start / 2)[:, None], np.sin(start / 2)[:, None] * tilt], 1)
    scene.create_entities(count, TransformComponent.batch(translations=grid(count), quaternions=quaternions,
                                                          scales=0.8),
                          MeshComponent("cube"), MaterialComponent("cube"),
                          [SpinComponent(axis, speed, local=local) for axis, speed in zip(axes, speeds)])
    scene.add_system(GpuSpinSystem() if path == "gpu" else SpinSystem(path=path))
    return scene


#: The technique the variants hand the launcher. The GPU path needs compute shaders: OpenGL 4.3.
PART = Part(__package__, build_scene=build_scene, needs=Needs(opengl=430, opengl_for="compute shaders"))
